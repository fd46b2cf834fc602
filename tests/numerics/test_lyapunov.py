"""The largest Lyapunov exponent measured by a second run beside the first (app/numerics/lyapunov.py)."""

from __future__ import annotations

import math

import numpy as np

from app.numerics.lyapunov import largest_exponent
from app.service.chapter.derivations import PROCESS_SCENES
from app.service.simulations.simulate_request import parameter_vector


def _pendulum():
    d = PROCESS_SCENES.derivation("simple-pendulum")
    system, _ = PROCESS_SCENES.system("simple-pendulum")
    return system, parameter_vector(d, {}), {p.name: p.default for p in d.system.parameters}


def test_at_the_top_of_a_pendulum_nearby_starts_part_at_the_rate_of_its_unstable_linear_motion():
    # about θ = π, η̈ = (g/R) η: a small gap grows as e^{√(g/R) t}, so λ = √(g/R)
    system, k, p = _pendulum()
    found = largest_exponent(system, k, np.array([math.pi, 0.0]), 5.0)
    assert abs(found.value - math.sqrt(p["g"] / p["R"])) < 1e-3 * math.sqrt(p["g"] / p["R"]), found


def test_a_regular_swing_has_no_positive_exponent():
    # a swing of one degree of freedom is regular: nearby starts part at most linearly in time, so the
    # average of ln(growth) over 60 s is small, and shrinks as the time grows
    system, k, _ = _pendulum()
    short = largest_exponent(system, k, np.array([1.0, 0.0]), 20.0).value
    long = largest_exponent(system, k, np.array([1.0, 0.0]), 60.0).value
    assert 0 <= long < short < 0.3, (short, long)
