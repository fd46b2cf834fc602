"""Documented examples of the user-system API, requests and the answers they really get.

The answers live in ``examples/user_api.json``, written by running the API on
the requests below (``python scripts/record_examples.py``, outside the app); a
test checks that the file still matches what the API answers.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

EXAMPLES_FILE = Path(__file__).with_name("examples") / "user_api.json"

DOUBLE_PENDULUM = {
    "coordinates": ["theta1", "theta2"],
    "parameters": [
        {"name": "m1", "value": 1.0, "unit": "kg", "min": 0.01},
        {"name": "m2", "value": 1.0, "unit": "kg", "min": 0.01},
        {"name": "l1", "value": 1.0, "unit": "m", "min": 0.01},
        {"name": "l2", "value": 1.0, "unit": "m", "min": 0.01},
        {"name": "g", "value": 9.81, "unit": "m/s^2", "min": 0.01},
    ],
    # x horizontal, z up (as the playground's form says), the pivot at the origin
    "particles": [
        {"mass": "m1", "position": ["l1*sin(theta1)", "0", "-l1*cos(theta1)"]},
        {"mass": "m2", "position": ["l1*sin(theta1) + l2*sin(theta2)", "0", "-l1*cos(theta1) - l2*cos(theta2)"]},
    ],
    "potential": "-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)",
}
# The same with standard gravity: a request no cache holds (the app's warm-up and the tests derive the one
# above, and a worker keeps its last derivations), for the refusals that come before or during the work
# (one at a time, busy, the time limit).
UNCACHED_DOUBLE_PENDULUM = {
    **DOUBLE_PENDULUM,
    "parameters": [{**p, "value": 9.80665} if p["name"] == "g" else p for p in DOUBLE_PENDULUM["parameters"]],
}


def _chain(links: int) -> dict[str, Any]:
    """A pendulum of ``links`` equal links, each bob a particle at the end of its link."""
    x = [" + ".join(f"l*sin(q{j})" for j in range(1, i + 1)) for i in range(1, links + 1)]
    y = [" - ".join(f"l*cos(q{j})" for j in range(1, i + 1)) for i in range(1, links + 1)]
    return {
        "coordinates": [f"q{i}" for i in range(1, links + 1)],
        "parameters": ["m", "l", "g"],
        "particles": [{"mass": "m", "position": [xi, "0", f"-{yi}"]} for xi, yi in zip(x, y, strict=True)],
        "potential": " + ".join(f"m*g*(-{yi})" for yi in y),
    }


# The time limit's example: a six-link chain, whose whole document takes over half a second even in a worker
# that has derived it before (the double pendulum's, with the display forms a worker keeps, fits in 0.2 s)
LONG_CHAIN = _chain(6)
FORCED_SPRING = {
    "coordinates": ["x"],
    "parameters": [
        {"name": "m", "value": 1.0, "unit": "kg", "min": 0.01},
        {"name": "k", "value": 4.0, "unit": "N/m", "min": 0.01},
        {"name": "b", "value": 0.1, "unit": "kg/s", "min": 0.0},
        {"name": "F", "value": 0.5, "unit": "N"},
        {"name": "w", "value": 1.5, "unit": "1/s"},
    ],
    "kinetic": "m*x_dot**2/2",
    "potential": "k*x**2/2",
    "forces": {"x": "F*cos(w*t) - b*x_dot"},
}
# R w² = 18 m/s² > g: θ = 0 is unstable and the bead rests off the axis, at cos θ = g/(R w²) (away from the
# bifurcation R w² = g, where θ = 0 is a quartic minimum with no small-oscillation frequency)
SPINNING_HOOP = {
    "coordinates": ["theta"],
    "parameters": [
        {"name": "m", "value": 0.1, "unit": "kg", "min": 0.001},
        {"name": "R", "value": 0.5, "unit": "m", "min": 0.01},
        {"name": "g", "value": 9.81, "unit": "m/s^2", "min": 0.01},
        {"name": "w", "value": 6.0, "unit": "rad/s", "min": 0.01},
    ],
    "lagrangian": "m*R**2*(theta_dot**2 + w**2*sin(theta)**2)/2 + m*g*R*cos(theta)",
}
# L = −mc²√(1 − ẋ²/c²) − ½kx², not quadratic in ẋ.  A toy speed of light, c = 1 m/s, and k a²/(2mc²) = 2 at the
# playground's start x = 1 m: the bob reaches γ = 3 (ẋ = 0.94c) and its period is 1.6 times the slow 2π√(m/k)
RELATIVISTIC_OSCILLATOR = {
    "coordinates": ["x"],
    "parameters": [
        {"name": "m", "value": 1.0, "unit": "kg", "min": 0.001},
        {"name": "c", "value": 1.0, "unit": "m/s", "min": 0.01},
        {"name": "k", "value": 4.0, "unit": "N/m", "min": 0.001},
    ],
    "lagrangian": "-m*c**2*sqrt(1 - x_dot**2/c**2) - k*x**2/2",
}

DERIVE_EXAMPLES: dict[str, dict[str, Any]] = {
    "forced-spring": {
        "summary": "A spring-mass with damping and a periodic force (T, U and Q)",
        "value": FORCED_SPRING,
    },
    "double-pendulum": {"summary": "A double pendulum given by its particles and U", "value": DOUBLE_PENDULUM},
    "spinning-hoop": {"summary": "A bead on a spinning hoop given by L alone", "value": SPINNING_HOOP},
}

SIMULATE_EXAMPLES: dict[str, dict[str, Any]] = {
    "forced-spring": {
        "summary": "The driven, damped spring from rest at x = 1 (a few samples)",
        "value": {**FORCED_SPRING, "initial": {"x": 1.0, "x_dot": 0.0}, "t_end": 5.0, "samples": 6},
    },
    "double-pendulum": {
        "summary": "The double pendulum released from rest",
        "value": {**DOUBLE_PENDULUM, "initial": {"theta1": 1.0, "theta2": 2.0}, "t_end": 10.0, "samples": 200},
    },
}
SIMULATE_REFUSED = {
    "summary": "An initial value for a name that is not a coordinate",
    "value": {**FORCED_SPRING, "initial": {"y": 1.0}, "t_end": 5.0},
}

# Requests whose refusals are documented (their answers are in the examples file).
REFUSED_REQUESTS: dict[str, dict[str, Any]] = {
    "code": {
        "summary": "Code instead of an expression",
        "value": {"coordinates": ["x"], "lagrangian": "__import__('os').system('ls')"},
    },
    "attribute": {
        "summary": "Attribute access",
        "value": {"coordinates": ["x"], "lagrangian": "x_dot**2/2 + sin.__globals__"},
    },
    "unknown-name": {
        "summary": "A name that was not declared",
        "value": {"coordinates": ["x"], "parameters": ["k"], "kinetic": "x_dot**2/2", "potential": "k*y**2/2"},
    },
    "clashing-name": {
        "summary": "A parameter named like a function",
        "value": {"coordinates": ["x"], "parameters": ["sin"], "lagrangian": "x_dot**2"},
    },
    "tower": {
        "summary": "A tower of exponents",
        "value": {"coordinates": ["x"], "lagrangian": "x_dot**2/2 - 9**9**9**9*x"},
    },
    "singular": {
        "summary": "No term quadratic in the velocities",
        "value": {"coordinates": ["x"], "lagrangian": "x_dot*x - x**2/2"},
    },
    "shape": {"summary": "A body of the wrong shape", "value": {"coordinates": [], "lagrangian": "x_dot**2"}},
}


def _load() -> dict[str, Any]:
    try:
        return json.loads(EXAMPLES_FILE.read_text())
    except (OSError, ValueError):
        return {"derive": None, "errors": {}}


JSON = {"content-type": "application/json"}
# a parameter value with more digits than Python's JSON reader converts
UNREADABLE = (
    b'{"coordinates": ["x"], "lagrangian": "x_dot**2", "parameters": [{"name": "k", "value": 1' + b"0" * 5000 + b"}]}"
)
# the timeout example (LONG_CHAIN) is recorded with this limit (the served limit is longer): the chain's whole
# document takes 3.8 s here, 0.6 s when the same worker derives it again, so no worker answers within it
TIMEOUT_SECONDS = 0.2

_ANSWERS = _load()
DERIVE_RESPONSE: dict[str, Any] | None = _ANSWERS["derive"]
SIMULATE_RESPONSE: dict[str, Any] | None = _ANSWERS.get("simulate")
SUMMARIES = {
    "400": {"unreadable": "A number JSON cannot hold as a float"},
    "413": {"too-large": "A body over the size cap"},
    "422": {
        **{k: v["summary"] for k, v in REFUSED_REQUESTS.items()},
        "timeout": "Work beyond the time limit (recorded with a 1 s limit)",
        "simulate": SIMULATE_REFUSED["summary"],
    },
    "429": {"one-at-a-time": "A second request while your first is still running"},
    "503": {"busy": "Every slot taken"},
}
ERROR_EXAMPLES: dict[int, dict[str, dict[str, Any]]] = {
    int(status): {
        name: {"summary": summary, "response": _ANSWERS["errors"].get(status, {}).get(name, {"detail": summary})}
        for name, summary in names.items()
    }
    for status, names in SUMMARIES.items()
}
