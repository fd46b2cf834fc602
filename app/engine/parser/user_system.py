"""A system a user declared, once checked: one frozen, picklable value from the route to the worker.

A user system arrives in one of two input shapes, the API's request
(``app/web/schemas/user.py``) or the playground's form (``app/web/pages/playground_form.py``);
``app.service.users.user_checks.checked`` turns either's plain data into a ``UserSystem``
after refusing what is not allowed, and keeps each expression as it read it
(``parsed``: the checked trees of ``app.engine.parser.parse.read``, pure Python).  From
there on the cache keys, the worker's jobs, the exports and the page model all
take this one value; the worker builds each read expression in SymPy once
(``app.service.users.user_jobs.build_system``) and the engine's declaration
(``system()``, app/scenes/types.py) carries what it built, so no text is read
twice (docs/parsing.md).  No SymPy here.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from app.scenes.types import Parameter, Particle, System

if TYPE_CHECKING:
    from app.engine.parser.parse import Parsed


@dataclass(frozen=True)
class DeclaredParticle:
    mass: str
    position: tuple[str, ...]  # (x, y) or (x, y, z), expressions of the coordinates and t
    label: str = ""


def _parameter(p: str | Mapping[str, Any]) -> Parameter:
    """A declared parameter: a bare name (value 1), or the request's fields."""
    if isinstance(p, str):
        return Parameter(p, 1.0)
    return Parameter(
        p["name"], float(p.get("value", 1.0)), p.get("unit", ""), p.get("min"), p.get("max"), p.get("description", "")
    )


def _in_space(position: tuple[str, ...]) -> tuple[str, str, str]:
    x, y, *z = position
    return x, y, z[0] if z else "0"


@dataclass(frozen=True)
class UserSystem:
    coordinates: tuple[str, ...]
    parameters: tuple[Parameter, ...] = ()  # the request's "value" is the parameter's default
    lagrangian: str | None = None
    kinetic: str | None = None
    potential: str | None = None
    particles: tuple[DeclaredParticle, ...] = ()
    forces: tuple[tuple[str, str], ...] = ()  # (coordinate, Q), in the order given
    nonnegative: tuple[str, ...] = ()
    # each expression as the check read it, by its location (``expressions()``); None until checked.  Not part
    # of the value (equality, hashes and cache keys are the declaration's), but pickled with it to the worker.
    parsed: Mapping[tuple, Parsed] | None = field(default=None, compare=False, repr=False)

    @classmethod
    def of(cls, data: Mapping[str, Any]) -> UserSystem:
        """From plain data in the request's shape (a parameter may be a bare name)."""
        return cls(
            coordinates=tuple(data.get("coordinates") or ()),
            parameters=tuple(_parameter(p) for p in data.get("parameters") or ()),
            lagrangian=data.get("lagrangian"),
            kinetic=data.get("kinetic"),
            potential=data.get("potential"),
            particles=tuple(
                DeclaredParticle(p["mass"], tuple(p["position"]), p.get("label") or "")
                for p in data.get("particles") or ()
            ),
            forces=tuple((data.get("forces") or {}).items()),
            nonnegative=tuple(data.get("nonnegative") or ()),
        )

    def as_json(self) -> dict[str, Any]:
        """Plain data in the request's shape (what the page sends back to the API, and the cache keys' text)."""
        return {
            "coordinates": list(self.coordinates),
            "parameters": [
                {
                    "name": p.name,
                    "value": p.default,
                    "unit": p.unit,
                    "min": p.min,
                    "max": p.max,
                    "description": p.description,
                }
                for p in self.parameters
            ],
            "lagrangian": self.lagrangian,
            "kinetic": self.kinetic,
            "potential": self.potential,
            "particles": [{"mass": p.mass, "position": list(p.position), "label": p.label} for p in self.particles],
            "forces": dict(self.forces),
            "nonnegative": list(self.nonnegative),
        }

    @property
    def parameter_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.parameters)

    @property
    def form(self) -> str:
        """Which of the three forms the system is given in (the field a derivation error points at)."""
        if self.particles:
            return "particles"
        return "lagrangian" if self.lagrangian is not None else "kinetic"

    def expressions(self) -> Iterator[tuple[tuple, str, bool]]:
        """Every expression: (its location in the request, the text, whether velocities may appear)."""
        for i, particle in enumerate(self.particles):
            yield ("particles", i, "mass"), particle.mass, False
            for j, component in enumerate(particle.position):
                yield ("particles", i, "position", j), component, False
        for key, text, velocities in (
            ("lagrangian", self.lagrangian, True),
            ("kinetic", self.kinetic, True),
            ("potential", self.potential, False),
        ):
            if text is not None:
                yield (key,), text, velocities
        for name, text in self.forces:
            yield ("forces", name), text, True

    def never_real(self, built: Mapping[tuple, Any]) -> tuple[tuple, Exception] | None:
        """The first expression that is a real number nowhere, located, with its refusal (app.engine.parser.reality).

        ``built`` holds each expression built in SymPy, by location; called by the worker before deriving
        (SymPy is imported here, not at import time).
        """
        from app.engine.parser.parse import ExpressionError
        from app.engine.parser.reality import refuse_if_nowhere_real
        from app.engine.parser.symbols import SymbolTable

        table = SymbolTable(self.coordinates, self.parameter_names)
        fixed = {s: p.default for s, p in zip(table.params, self.parameters, strict=True)}
        free = [*table.q, *table.qd, table.t]
        for loc, text, velocities in self.expressions():
            if loc[0] == "forces":
                continue  # a generalized force is not an energy (a complex one is refused by the numerics)
            try:
                refuse_if_nowhere_real(text, built[loc], free if velocities else [*table.q, table.t], fixed)
            except ExpressionError as exc:
                return loc, exc
        return None

    def system(self, built: Mapping[tuple, Any] | None = None) -> System:
        """The engine's declaration (a planar particle moves in z = 0), carrying the expressions ``built`` in
        SymPy by location, if given, so that the engine builds none of them again."""
        expressions: dict[str, Any] = {}
        if built:
            from sympy import Integer

            expressions = {text: built[loc] for loc, text, _ in self.expressions()}
            expressions.setdefault("0", Integer(0))  # the z of a planar particle
        return System(
            coordinates=self.coordinates,
            parameters=tuple(Parameter(p.name, p.default, p.unit, p.min, p.max) for p in self.parameters),
            particles=tuple(Particle(p.mass, _in_space(p.position), p.label) for p in self.particles),
            kinetic=self.kinetic,
            potential=self.potential,
            lagrangian=self.lagrangian,
            forces=dict(self.forces),
            nonnegative=self.nonnegative,
            built=expressions,
        )
