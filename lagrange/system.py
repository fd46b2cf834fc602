"""A system to derive: typed in Python (as in the playground) or one of the book's scenes."""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping
from typing import Any

from app.engine.parser.user_system import UserSystem
from app.scenes import SCENES
from app.scenes.types import Scene
from app.scenes.types import System as Declared
from app.service.users.user_checks import checked
from app.service.users.user_jobs import build_system


class System:
    """A mechanical system, checked as the playground checks it (a ``lagrange.Refused`` says what is wrong).

    Give the coordinates, the parameters (``{"m": 1.0}``, or the API's list of ``{"name", "value", "unit",
    "min", "max"}``) and one of: ``lagrangian``; ``kinetic`` and ``potential``; or ``particles``
    (``[{"mass": "m", "position": ["l*sin(theta)", "-l*cos(theta)"]}]``, with ``potential`` for the
    forces a potential describes). ``forces`` maps a coordinate to a generalized force Q that no potential
    describes; ``nonnegative`` lists the coordinates that are distances.  Expressions use the playground's
    grammar: ``theta_dot`` for θ̇, ``**`` or ``^`` for powers.
    """

    def __init__(
        self,
        coordinates: Iterable[str],
        parameters: Mapping[str, float] | Iterable[Mapping[str, Any] | str] = (),
        *,
        lagrangian: str | None = None,
        kinetic: str | None = None,
        potential: str | None = None,
        particles: Iterable[Mapping[str, Any]] = (),
        forces: Mapping[str, str] | None = None,
        nonnegative: Iterable[str] = (),
    ) -> None:
        if isinstance(parameters, Mapping):
            parameters = [{"name": name, "value": value} for name, value in parameters.items()]
        data = {
            "coordinates": list(coordinates),
            "parameters": list(parameters),
            "lagrangian": lagrangian,
            "kinetic": kinetic,
            "potential": potential,
            "particles": [dict(p) for p in particles],
            "forces": dict(forces or {}),
            "nonnegative": list(nonnegative),
        }
        self._user: UserSystem | None = checked(data)
        self._scene: Scene | None = None
        self._declared: Declared | None = None

    @classmethod
    def from_json(cls, data: str | Mapping[str, Any]) -> System:
        """From the playground's JSON (a string or the parsed object), in the shape of ``POST /api/derive``."""
        spec = json.loads(data) if isinstance(data, str) else dict(data)
        return cls(
            spec.get("coordinates") or (),
            spec.get("parameters") or (),
            lagrangian=spec.get("lagrangian"),
            kinetic=spec.get("kinetic"),
            potential=spec.get("potential"),
            particles=spec.get("particles") or (),
            forces=spec.get("forces"),
            nonnegative=spec.get("nonnegative") or (),
        )

    @property
    def declared(self) -> Declared:
        """The engine's declaration (app/scenes/types.py), each expression built in SymPy once."""
        if self._declared is None:
            assert self._user is not None
            self._declared = build_system(self._user)
        return self._declared

    @property
    def title(self) -> str:
        return self._scene.title if self._scene else "the system in " + ", ".join(self.coordinates)

    @property
    def coordinates(self) -> tuple[str, ...]:
        return tuple(self.declared.coordinates) if self._user is None else self._user.coordinates

    @property
    def scene_id(self) -> str | None:
        return self._scene.id if self._scene else None

    def __repr__(self) -> str:
        return f"lagrange.scene({self._scene.id!r})" if self._scene else f"lagrange.System({self._user!r})"


def scene(scene_id: str) -> System:
    """One of the book's scenes, by its id (``lagrange.scenes()`` lists them)."""
    found = SCENES.get(scene_id)
    if found is None:
        raise KeyError(f"no scene {scene_id!r}; the scenes are: {', '.join(SCENES)}")
    system = System.__new__(System)
    system._user, system._scene, system._declared = None, found, found.system
    return system


def scenes() -> dict[str, str]:
    """The book's scenes: id → title."""
    return {s.id: s.title for s in SCENES.values()}
