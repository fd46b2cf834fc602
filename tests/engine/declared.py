"""Systems given in the API's request shape, as the engine declares them, and the check corpus's derivations.

A light module: the tests that need one derivation import it from here, not from a test module whose
module-level case lists derive every scene."""

from __future__ import annotations

from functools import cache

from app.engine.derivation.derive import Derivation, derive
from app.engine.tutor.check import Problem, problem
from app.scenes import SCENES
from app.scenes.types import Parameter, Particle, System
from tests.engine.check_corpus import USER_SYSTEMS


def system_of(spec: dict) -> System:
    """The engine's declaration of a system given in the API's request shape (with units, where given)."""
    return System(
        coordinates=tuple(spec["coordinates"]),
        parameters=tuple(
            Parameter(p["name"], p["value"], unit=p.get("unit", ""), min=p["min"], max=p.get("max"))
            for p in spec["parameters"]
        ),
        particles=tuple(
            Particle(p["mass"], tuple(p["position"]), p.get("label", "")) for p in spec.get("particles", [])
        ),
        kinetic=spec.get("kinetic"),
        potential=spec.get("potential"),
        lagrangian=spec.get("lagrangian"),
        forces=dict(spec.get("forces", {})),
    )


def declared(name: str) -> System:
    """A scene's system, or one of the check corpus's own systems (USER_SYSTEMS), as declared."""
    return system_of(USER_SYSTEMS[name]) if name in USER_SYSTEMS else SCENES[name].system


@cache
def derivation(name: str) -> Derivation:
    """A scene's derivation, or one of the check corpus's own systems (USER_SYSTEMS)."""
    return derive(declared(name))


@cache
def problem_of(name: str, step: str, coordinate: str | None = None) -> Problem:
    """The problem of one step of ``derivation(name)``, built once per test process: judging never changes a
    problem, and building one is most of a check test's time when each test builds its own."""
    return problem(derivation(name), step, coordinate)


def family_steps(name: str) -> list[tuple[str, str | None]]:
    """The steps whose mistakes a family generates (T and U where they are declared apart, an equation for each
    coordinate), read from the declaration: a module lists its cases without deriving while it is collected
    (tests/engine/tutor/test_check.py holds this list to the tutor's own ``exercises``)."""
    system = declared(name)
    apart = [("kinetic", None), ("potential", None)] if system.lagrangian is None else []
    return apart + [("equation", q) for q in system.coordinates]
