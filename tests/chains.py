"""The n-link pendulum as a user declares it: one home for the tests and the benchmarks that send it."""

from __future__ import annotations

from typing import Any


def chain_request(n: int, g: float = 9.81) -> dict[str, Any]:
    """The n-link pendulum as a user declares it: particles at the ends of the links, U = sum m g y."""
    x, y, particles, potential = "", "", [], []
    for i in range(1, n + 1):
        x = f"{x} + l{i}*sin(q{i})" if x else f"l{i}*sin(q{i})"
        y = f"{y} - l{i}*cos(q{i})" if y else f"-l{i}*cos(q{i})"
        particles.append({"mass": f"m{i}", "position": [x, "0", y]})
        potential.append(f"m{i}*g*({y})")
    parameters = [{"name": f"m{i}", "value": 1.0, "unit": "kg", "min": 0.01} for i in range(1, n + 1)]
    parameters += [{"name": f"l{i}", "value": 1.0, "unit": "m", "min": 0.01} for i in range(1, n + 1)]
    parameters.append({"name": "g", "value": g, "unit": "m/s^2", "min": 0.01})
    return {
        "coordinates": [f"q{i}" for i in range(1, n + 1)],
        "parameters": parameters,
        "particles": particles,
        "potential": " + ".join(potential),
    }
