"""Checks of a system a user types in: names, sizes and expressions, in pure Python (no SymPy).

A request arrives as plain data (the web layer validated its shape):

    {"coordinates": [...], "parameters": [{"name", "value", "unit", "min", "max"}, ...],
     "lagrangian": ... | "kinetic": ..., "potential": ... | "particles": [...], "potential": ...,
     "forces": {coordinate: Q}, "nonnegative": [...]}

``checked`` turns it into the one value a user system is from then on
(``app.engine.parser.user_system.UserSystem``), refusing bad names and bad expressions,
each refusal carrying the location of the offending field
(``["particles", 0, "position", 1]``) and the character span of the offending
part.  It runs in the web process before any job is queued, and the value keeps
each expression as it was read (``UserSystem.parsed``): the worker builds SymPy
from those without reading the text again (docs/parsing.md).
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from app.engine.display.names import page_letter_clash
from app.engine.errors import DerivationError, excerpt
from app.engine.parser.parse import MAX_TERMS, ExpressionError, Parsed, check_name, read
from app.engine.parser.user_system import UserSystem
from app.errors import Refused, TooMuchWork

# the one home of the size limits: the N-link chain as particles derives up to N = 12 within the engine's
# budget (the heavy algebra on symengine; docs/scale.md, benchmarks/bench_scale.py)
MAX_COORDINATES = 12
MAX_PARAMETERS = 40
MAX_PARTICLES = 12
# the bound on the terms of T from particles: the 12-link chain's bound is 2,768 (its T, built, has far fewer
# once sin² + cos² = 1 collapses; it derives in about 2 s)
MAX_KINETIC_TERMS = 2 * MAX_TERMS


class InvalidSystem(DerivationError):
    """A user system refused; ``loc`` is the path of the offending field in the request (always set)."""

    loc: tuple

    def __init__(
        self,
        message: str,
        loc: tuple = (),
        part: str = "",
        start: int | None = None,
        end: int | None = None,
        readings: tuple[str, ...] = (),
    ):
        Refused.__init__(self, message, part, loc, start, end)
        self.readings = tuple(readings)  # the two readings of an ambiguous expression (app/engine/parser/typed.py)


class TooCostly(InvalidSystem, TooMuchWork):
    """A user system whose derivation or simulation would take more than its budget."""


def _where(loc: tuple) -> str:
    head, *rest = loc
    text = str(head)
    for x in rest:
        text += f"[{x}]" if isinstance(x, int) else f".{excerpt(x)}"
    return text


def located(exc: DerivationError, loc: tuple, message: str | None = None) -> InvalidSystem:
    """A refusal of the engine or the numerics, located at ``loc`` in the request (too much work stays so)."""
    kind = TooCostly if isinstance(exc, TooMuchWork) else InvalidSystem
    return kind(str(exc) if message is None else message, loc, exc.part)


def _refuse(loc: tuple, exc: ExpressionError) -> InvalidSystem:
    return InvalidSystem(
        f"{_where(loc)}: {exc}", loc, exc.part, getattr(exc, "start", None), getattr(exc, "end", None), exc.readings
    )


def checked(data: Mapping[str, Any]) -> UserSystem:
    """The user system of a request's plain data, with its expressions as read, or a located refusal."""
    system = UserSystem.of(data)
    return replace(system, parsed=check_system(system))


def check_system(system: UserSystem) -> dict[tuple, Parsed]:
    """Refuse a system whose names or expressions are not allowed (pure Python, no SymPy); else each
    expression as read (``app.engine.parser.parse.read``), by its location in the request."""
    coordinates, parameters = system.coordinates, system.parameter_names
    if not 1 <= len(coordinates) <= MAX_COORDINATES:
        raise InvalidSystem(f"give between 1 and {MAX_COORDINATES} coordinates", ("coordinates",))
    if len(parameters) > MAX_PARAMETERS:
        raise InvalidSystem(f"at most {MAX_PARAMETERS} parameters are allowed", ("parameters",))
    if len(system.particles) > MAX_PARTICLES:
        raise InvalidSystem(f"at most {MAX_PARTICLES} particles are allowed", ("particles",))
    seen: set[str] = set()
    named: list[tuple[tuple, str, str]] = [(("coordinates", i), n, "coordinate") for i, n in enumerate(coordinates)]
    named += [(("parameters", i, "name"), n, "parameter") for i, n in enumerate(parameters)]
    for loc, name, what in named:
        try:
            check_name(name, what)
        except ExpressionError as exc:
            raise _refuse(loc, exc) from None
        if (clash := page_letter_clash(name, what)) is not None:
            raise InvalidSystem(f"{_where(loc)}: {clash}", loc, name)
        if name in seen:
            raise InvalidSystem(f"{_where(loc)}: the name {name!r} is declared twice", loc, name)
        seen.add(name)
    for i, p in enumerate(system.parameters):
        low, high, value = p.min, p.max, p.default
        if low is not None and high is not None and low > high:
            loc = ("parameters", i, "min")
            raise InvalidSystem(f"{_where(loc)}: min {low:g} is larger than max {high:g}", loc)
        if (low is not None and value < low) or (high is not None and value > high):
            loc = ("parameters", i, "value")
            # which end it passes, in words: "below its least value, 1e-09" rather than a range to infinity
            if low is not None and value < low:
                edge = f"is below the least value allowed for {p.name}, {low:g}" + (
                    " (it must be positive)" if low > 0 and low < 1e-6 else ""
                )
            else:
                edge = f"is above the largest value allowed for {p.name}, {high:g}"
            raise InvalidSystem(f"{_where(loc)}: {value:g} {edge}", loc)

    forms = [bool(system.particles), system.kinetic is not None, system.lagrangian is not None]
    if sum(forms) != 1:
        raise InvalidSystem(
            "give exactly one of: particles (with a potential), kinetic and potential, or lagrangian", ()
        )
    if system.lagrangian is not None and system.potential is not None:
        raise InvalidSystem("potential: a Lagrangian already contains the potential; give L alone", ("potential",))
    if system.lagrangian is None and system.potential is None:
        raise InvalidSystem(
            "potential: a potential U is needed with particles or with T (write 0 if none)", ("potential",)
        )
    for name, _ in system.forces:
        if name not in coordinates:
            raise InvalidSystem(f"forces: {name[:40]!r} is not a coordinate", ("forces", name), name[:40])
    for i, name in enumerate(system.nonnegative):
        if name not in coordinates:
            raise InvalidSystem(f"nonnegative[{i}]: {name[:40]!r} is not a coordinate", ("nonnegative", i), name[:40])

    base = frozenset(coordinates) | frozenset(parameters) | {"t"}
    with_velocities = base | {f"{q}_dot" for q in coordinates}
    parsed = {}
    for loc, text, velocities in system.expressions():
        try:
            parsed[loc] = read(text, with_velocities if velocities else base)
        except ExpressionError as exc:
            raise _refuse(loc, exc) from None
    _check_kinetic_size(system, parsed)
    return parsed


def _check_kinetic_size(system: UserSystem, parsed: dict[tuple, Parsed]) -> None:
    """Refuse particles whose kinetic energy would expand past MAX_KINETIC_TERMS terms (before SymPy builds it).

    A position of n terms of degree d has a velocity of at most n*d terms (each
    monomial differentiates into one term per factor); its square has at most
    v(v + 1)/2 terms, times the terms of the mass; T sums those over particles and axes.
    """
    total = 0
    for i, particle in enumerate(system.particles):
        mass = parsed[("particles", i, "mass")].size.terms
        for j in range(len(particle.position)):
            size = parsed[("particles", i, "position", j)].size
            velocity = size.terms * max(1, math.ceil(size.degree))
            total += mass * velocity * (velocity + 1) // 2
        if total > MAX_KINETIC_TERMS:
            loc = ("particles", i, "position")
            raise InvalidSystem(
                f"{_where(loc)}: the kinetic energy of these particles would expand into more than {MAX_KINETIC_TERMS} "
                "terms; use fewer or simpler positions (or give T and U directly)",
                loc,
            )


def simulation_loc(system: UserSystem, part: str) -> tuple:
    """Where in a simulate request the numerics' complaint points ("parameters.k" is that parameter's value)."""
    head, _, name = part.partition(".")
    if head == "parameters":
        names = list(system.parameter_names)
        return ("parameters", names.index(name), "value") if name in names else ("parameters",)
    if head == "initial":
        return ("initial", name) if name else ("initial",)
    return (head,) if head else ()


def _plain(value: Any) -> Any:
    return value.as_json() if isinstance(value, UserSystem) else str(value)


def spec_key(*parts: Any) -> str:
    """A cache key: the hash of the parts (a user system, a request, names) as canonical JSON."""
    text = json.dumps(parts, sort_keys=True, separators=(",", ":"), default=_plain)
    return hashlib.sha256(text.encode()).hexdigest()
