"""A simulation request checked against the system's declared ranges: parameters, initial state, settings."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any, Protocol

import numpy as np

from app.engine.derivation.derive import Derivation
from app.numerics import limits
from app.numerics.errors import SimulationError


class SimulationInput(Protocol):
    """What a request carries (``app.web.schemas.simulate.SimulateRequest`` has these fields)."""

    parameters: Mapping[str, float]
    initial: Mapping[str, float]
    t_end: float | None
    method: str
    rtol: float | None
    atol: float | None
    samples: int | None
    precision: str  # "full" or "display" (absent means full)


def check_number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SimulationError(f"{where} must be a finite number", where)
    if abs(value) > limits.VALUE_MAX:
        raise SimulationError(f"{where} = {value:g} is beyond the allowed magnitude {limits.VALUE_MAX:g}", where)
    return float(value)


def _in_range(value: float, low: float | None, high: float | None) -> bool:
    return (low is None or value >= low) and (high is None or value <= high)


def parameter_vector(d: Derivation, given: Mapping[str, float]) -> np.ndarray:
    declared = {p.name: p for p in d.system.parameters}
    unknown = sorted(set(given) - set(declared))
    if unknown:
        raise SimulationError(
            f"unknown parameter {unknown[0][:40]!r}; this system has {', '.join(declared) or 'no parameters'}",
            "parameters",
        )
    values = []
    for name, p in declared.items():
        value = check_number(given.get(name, p.default), f"parameters.{name}")
        if not _in_range(value, p.min, p.max):
            raise SimulationError(
                f"parameters.{name} = {value:g} is outside its allowed range [{p.min}, {p.max}] {p.unit}".rstrip(),
                f"parameters.{name}",
            )
        values.append(value)
    return np.array(values, dtype=float)


def initial_state(d: Derivation, given: Mapping[str, float], defaults: Mapping[str, float]) -> np.ndarray:
    names = list(d.table.names)
    allowed = names + [f"{q}_dot" for q in names]
    unknown = sorted(set(given) - set(allowed))
    if unknown:
        raise SimulationError(f"unknown initial value {unknown[0][:40]!r}; allowed: {', '.join(allowed)}", "initial")
    y0 = np.array([check_number(given.get(n, defaults.get(n, 0.0)), f"initial.{n}") for n in allowed])
    for q in d.system.nonnegative:
        if y0[names.index(q)] < 0:
            raise SimulationError(f"initial.{q} must be >= 0 ({q} is a distance)", f"initial.{q}")
    return y0


def setting(value: Any, default: float, allowed: limits.Range, where: str) -> float:
    """A request's setting (its default when not given), refused outside ``allowed``."""
    value = default if value is None else check_number(value, where)
    if not allowed.low <= value <= allowed.high:
        raise SimulationError(
            f"{where} = {value:g} is outside the allowed range [{allowed.low:g}, {allowed.high:g}]", where
        )
    return value
