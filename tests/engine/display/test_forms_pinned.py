"""Textbook forms (app.engine.display.forms) of every scene's and two user systems' results, pinned and checked.

The pinned strings are the served ``sympy`` texts, produced by running the engine and read by eye:
cos(θ₁ − θ₂) instead of sin θ₁ sin θ₂ + cos θ₁ cos θ₂, the double pendulum's accelerations over
l(m₁ + m₂ sin²(θ₁ − θ₂)), in single angles and shorter so than over l(2m₁ + m₂ − m₂ cos 2(θ₁ − θ₂)), squares such as M(ẏ₁ + ẏ₂)²/8 and κ(x₂ − x₁)²/2, h and E from the
same pieces as T and U.  Each served form is checked against the engine's own expression at random
points (the equations up to a factor free of the motion: each is shown scaled).
"""

import random

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.document.contract import derivation_json
from app.scenes import SCENES
from app.service.chapter.derivations import derivation, derivation_document
from tests.engine.unseen_systems import UNSEEN

PINNED = {  # fmt: skip
    "damped-pendulum": {
        "kinetic": "R**2*m*theta_dot**2/2",
        "potential": "R*g*m*(1 - cos(theta))",
        "hamiltonian": "R**2*m*theta_dot**2/2 + R*g*m*(1 - cos(theta))",
        "equations": [
            "theta_ddot + g*sin(theta)/R + b*theta_dot/(R**2*m)",
        ],
        "accelerations": {
            "theta": "-(R*g*m*sin(theta) + b*theta_dot)/(R**2*m)",
        },
    },
    "simple-pendulum": {
        "kinetic": "R**2*m*theta_dot**2/2",
        "potential": "R*g*m*(1 - cos(theta))",
        "hamiltonian": "R**2*m*theta_dot**2/2 + R*g*m*(1 - cos(theta))",
        "equations": [
            "theta_ddot + g*sin(theta)/R",
        ],
        "accelerations": {
            "theta": "-g*sin(theta)/R",
        },
    },
    "helix-bead": {
        "kinetic": "m*z_dot**2*(R**2*alpha**2 + 1)/2",
        "potential": "g*m*z",
        "hamiltonian": "g*m*z + m*z_dot**2*(R**2*alpha**2 + 1)/2",
        "equations": [
            "g/(R**2*alpha**2 + 1) + z_ddot",
        ],
        "accelerations": {
            "z": "-g/(R**2*alpha**2 + 1)",
        },
    },
    "incline-block": {
        "kinetic": "X_dot**2*m/2",
        "potential": "X*g*m*sin(alpha)",
        "hamiltonian": "X*g*m*sin(alpha) + X_dot**2*m/2",
        "equations": [
            "X_ddot + g*sin(alpha)",
        ],
        "accelerations": {
            "X": "-g*sin(alpha)",
        },
    },
    "tabletop-spring": {
        "kinetic": "m*(r**2*theta_dot**2 + r_dot**2)/2",
        "potential": "k*r**2/2",
        "hamiltonian": "k*r**2/2 + m*(r**2*theta_dot**2 + r_dot**2)/2",
        "equations": [
            "k*r/m - r*theta_dot**2 + r_ddot",
            "theta_ddot + 2*r_dot*theta_dot/r",
        ],
        "accelerations": {
            "r": "-k*r/m + r*theta_dot**2",
            "theta": "-2*r_dot*theta_dot/r",
        },
    },
    "spherical-pendulum": {
        "kinetic": "R**2*m*(phi_dot**2*sin(theta)**2 + theta_dot**2)/2",
        "potential": "R*g*m*cos(theta)",
        "hamiltonian": "R**2*m*(phi_dot**2*sin(theta)**2 + theta_dot**2)/2 + R*g*m*cos(theta)",
        "equations": [
            "-phi_dot**2*sin(theta)*cos(theta) + theta_ddot - g*sin(theta)/R",
            "phi_ddot + 2*phi_dot*theta_dot*cos(theta)/sin(theta)",
        ],
        "accelerations": {
            "theta": "phi_dot**2*sin(theta)*cos(theta) + g*sin(theta)/R",
            "phi": "-2*phi_dot*theta_dot*cos(theta)/sin(theta)",
        },
    },
    "rail-two-body": {
        "kinetic": "m1*x1_dot**2/2 + m2*x2_dot**2/2",
        "potential": "k*(-l0 - x1 + x2)**2/2",
        "hamiltonian": "k*(-l0 - x1 + x2)**2/2 + m1*x1_dot**2/2 + m2*x2_dot**2/2",
        "equations": [
            "x1_ddot + (k/m1)*(l0 + x1 - x2)",
            "x2_ddot + (k/m2)*(-l0 - x1 + x2)",
        ],
        "accelerations": {
            "x1": "k*(-l0 - x1 + x2)/m1",
            "x2": "k*(l0 + x1 - x2)/m2",
        },
    },
    "pulley": {
        "kinetic": "M*(y1_dot + y2_dot)**2/8 + m1*y1_dot**2/2 + m2*y2_dot**2/2",
        # the page's zero of U is the end masses' level, so the middle mass's −M g c stays (review student-k 7)
        "potential": "-M*c*g - M*g*(y1 + y2)/2 + g*m1*y1 + g*m2*y2",
        "hamiltonian": "-M*c*g - M*g*(y1 + y2)/2 + M*(y1_dot + y2_dot)**2/8 + g*m1*y1 + g*m2*y2 + m1*y1_dot**2/2 + m2*y2_dot**2/2",
        "equations": [
            "-M*g/2 + M*y2_ddot/4 + g*m1 + y1_ddot*(M/4 + m1)",
            "-M*g/2 + M*y1_ddot/4 + g*m2 + y2_ddot*(M/4 + m2)",
        ],
        "accelerations": {
            "y1": "g*(-M*m1 + 3*M*m2 - 4*m1*m2)/(M*(m1 + m2) + 4*m1*m2)",
            "y2": "g*(3*M*m1 - M*m2 - 4*m1*m2)/(M*(m1 + m2) + 4*m1*m2)",
        },
    },
    "movable-incline": {
        "kinetic": "D_dot**2*m/2 + D_dot*X_dot*m*cos(alpha) + X_dot**2*(M + m)/2",
        "potential": "-D*g*m*sin(alpha)",
        "hamiltonian": "-D*g*m*sin(alpha) + D_dot**2*m/2 + D_dot*X_dot*m*cos(alpha) + X_dot**2*(M + m)/2",
        "equations": [
            "D_ddot*m*cos(alpha) + X_ddot*(M + m)",
            "D_ddot + X_ddot*cos(alpha) - g*sin(alpha)",
        ],
        "accelerations": {
            "X": "-g*m*sin(alpha)*cos(alpha)/(M + m*sin(alpha)**2)",
            "D": "g*(M + m)*sin(alpha)/(M + m*sin(alpha)**2)",
        },
    },
    "rotating-parabola": {
        "kinetic": "2*alpha**2*m*rho**2*rho_dot**2 + m*omega**2*rho**2/2 + m*rho_dot**2/2",
        "potential": "alpha*g*m*rho**2",
        "hamiltonian": "2*alpha**2*m*rho**2*rho_dot**2 + m*rho**2*(alpha*g - omega**2/2) + m*rho_dot**2/2",
        "equations": [
            "4*alpha**2*rho*rho_dot**2 + rho*(2*alpha*g - omega**2) + rho_ddot*(4*alpha**2*rho**2 + 1)",
        ],
        "accelerations": {
            "rho": "rho*(-4*alpha**2*rho_dot**2 - 2*alpha*g + omega**2)/(4*alpha**2*rho**2 + 1)",
        },
    },
    "coupled-oscillators": {
        "kinetic": "m*(x1_dot**2 + x2_dot**2)/2",
        "potential": "k*x1**2/2 + k*x2**2/2 + kappa*(-x1 + x2)**2/2",
        "hamiltonian": "k*x1**2/2 + k*x2**2/2 + kappa*(-x1 + x2)**2/2 + m*(x1_dot**2 + x2_dot**2)/2",
        "equations": [
            "-kappa*x2/m + x1_ddot + x1*(k + kappa)/m",
            "-kappa*x1/m + x2_ddot + x2*(k + kappa)/m",
        ],
        "accelerations": {
            # grouped by coordinate (issue 40): κx₂ − (k + κ)x₁ over m
            "x1": "(kappa*x2 + x1*(-k - kappa))/m",
            "x2": "(kappa*x1 + x2*(-k - kappa))/m",
        },
    },
    "rolling-cylinder-wedge": {
        # the cylinder's ½ m v_cm² + ½ (½ m r²)(ṡ/r)²: its inertia along the slope is 3m/2
        "kinetic": "X_dot**2*(M + m)/2 + X_dot*m*s_dot*cos(alpha) + 3*m*s_dot**2/4",
        "potential": "-g*m*s*sin(alpha)",
        "hamiltonian": "X_dot**2*(M + m)/2 + X_dot*m*s_dot*cos(alpha) - g*m*s*sin(alpha) + 3*m*s_dot**2/4",
        "equations": [
            "X_ddot*(M + m) + m*s_ddot*cos(alpha)",
            "X_ddot*cos(alpha) - g*sin(alpha) + 3*s_ddot/2",
        ],
        # over whole numbers, as a textbook prints them: 2(M + m) g sin α/(3M + m + 2m sin² α)
        "accelerations": {
            "X": "-2*g*m*sin(alpha)*cos(alpha)/(3*M + 2*m*sin(alpha)**2 + m)",
            "s": "2*g*(M + m)*sin(alpha)/(3*M + 2*m*sin(alpha)**2 + m)",
        },
    },
    "physical-pendulum": {
        "kinetic": "M*l**2*theta_dot**2/6",
        "potential": "-M*g*l*cos(theta)/2",
        "hamiltonian": "-M*g*l*cos(theta)/2 + M*l**2*theta_dot**2/6",
        "equations": ["3*g*sin(theta)/(2*l) + theta_ddot"],
        "accelerations": {"theta": "-3*g*sin(theta)/(2*l)"},
    },
    "massive-pulley": {
        # ½(m₁ + m₂ + M/2) ż² (Morin § 8.2): the pulley's turning adds M/2 to the masses the string carries
        "kinetic": "z_dot**2*(M/2 + m1 + m2)/2",
        "potential": "g*z*(-m1 + m2)",
        "hamiltonian": "g*z*(-m1 + m2) + z_dot**2*(M/2 + m1 + m2)/2",
        "equations": ["-g*(m1 - m2) + z_ddot*(M/2 + m1 + m2)"],
        "accelerations": {"z": "g*(m1 - m2)/(M/2 + m1 + m2)"},
    },
    "double-pendulum": {
        "kinetic": "l1**2*theta1_dot**2*(m1 + m2)/2 + l1*l2*m2*theta1_dot*theta2_dot*cos(theta1 - theta2) + l2**2*m2*theta2_dot**2/2",
        "potential": "g*l1*(-m1 - m2)*cos(theta1) - g*l2*m2*cos(theta2)",
        "hamiltonian": "g*l1*(-m1 - m2)*cos(theta1) - g*l2*m2*cos(theta2) + l1**2*theta1_dot**2*(m1 + m2)/2 + l1*l2*m2*theta1_dot*theta2_dot*cos(theta1 - theta2) + l2**2*m2*theta2_dot**2/2",
        "equations": [
            "g*(m1 + m2)*sin(theta1) + l1*theta1_ddot*(m1 + m2) + l2*m2*theta2_ddot*cos(theta1 - theta2) + l2*m2*theta2_dot**2*sin(theta1 - theta2)",
            "g*sin(theta2) + l1*theta1_ddot*cos(theta1 - theta2) - l1*theta1_dot**2*sin(theta1 - theta2) + l2*theta2_ddot",
        ],
        "accelerations": {
            "theta1": "(g*m2*sin(theta2)*cos(theta1 - theta2) - g*(m1 + m2)*sin(theta1) - l1*m2*theta1_dot**2*sin(theta1 - theta2)*cos(theta1 - theta2) - l2*m2*theta2_dot**2*sin(theta1 - theta2))/(l1*(m1 + m2*sin(theta1 - theta2)**2))",
            "theta2": "(g*(m1 + m2)*sin(theta1)*cos(theta1 - theta2) - g*(m1 + m2)*sin(theta2) + l1*theta1_dot**2*(m1 + m2)*sin(theta1 - theta2) + l2*m2*theta2_dot**2*sin(theta1 - theta2)*cos(theta1 - theta2))/(l2*(m1 + m2*sin(theta1 - theta2)**2))",
        },
    },
    "user:double-pendulum": {
        "kinetic": "a_dot**2*l1**2*(m1 + m2)/2 + a_dot*b_dot*l1*l2*m2*cos(a - b) + b_dot**2*l2**2*m2/2",
        "potential": "-g*l1*(m1 + m2)*cos(a) - g*l2*m2*cos(b)",
        "hamiltonian": "a_dot**2*l1**2*(m1 + m2)/2 + a_dot*b_dot*l1*l2*m2*cos(a - b) + b_dot**2*l2**2*m2/2 - g*l1*(m1 + m2)*cos(a) - g*l2*m2*cos(b)",
        "equations": [
            "a_ddot*l1*(m1 + m2) + b_ddot*l2*m2*cos(a - b) + b_dot**2*l2*m2*sin(a - b) + g*(m1 + m2)*sin(a)",
            "a_ddot*l1*cos(a - b) - a_dot**2*l1*sin(a - b) + b_ddot*l2 + g*sin(b)",
        ],
        "accelerations": {
            "a": "(-a_dot**2*l1*m2*sin(a - b)*cos(a - b) - b_dot**2*l2*m2*sin(a - b) + g*m2*sin(b)*cos(a - b) - g*(m1 + m2)*sin(a))/(l1*(m1 + m2*sin(a - b)**2))",
            "b": "(a_dot**2*l1*(m1 + m2)*sin(a - b) + b_dot**2*l2*m2*sin(a - b)*cos(a - b) + g*(m1 + m2)*sin(a)*cos(a - b) - g*(m1 + m2)*sin(b))/(l2*(m1 + m2*sin(a - b)**2))",
        },
    },
    "user:spring-pendulum": {
        "kinetic": "m*(r**2*theta_dot**2 + r_dot**2)/2",
        "potential": "-g*m*r*cos(theta) + k*(-l0 + r)**2/2",
        "hamiltonian": "-g*m*r*cos(theta) + k*(-l0 + r)**2/2 + m*(r**2*theta_dot**2 + r_dot**2)/2",
        "equations": [
            "-g*cos(theta) - k*l0/m + k*r/m - r*theta_dot**2 + r_ddot",
            "g*sin(theta)/r + theta_ddot + 2*r_dot*theta_dot/r",
        ],
        "accelerations": {
            "r": "(g*m*cos(theta) + k*l0 - k*r + m*r*theta_dot**2)/m",
            "theta": "-(g*sin(theta) + 2*r_dot*theta_dot)/r",
        },
    },
}

USER = {"user:double-pendulum": "double-pendulum", "user:spring-pendulum": "spring-pendulum"}


def _doc_and_derivation(key):
    if key in USER:
        d = derive(UNSEEN[USER[key]].system)
        return derivation_json(d), d
    return derivation_document(key), derivation(key)


def _values(d, rng):
    return {s: rng.uniform(0.3, 1.7) for s in (*d.table.q, *d.table.qd, *d.table.qdd, *d.table.params, d.table.t)}


def _close(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))


def test_every_scene_is_pinned():
    assert sorted(k for k in PINNED if k not in USER) == sorted(SCENES)


@pytest.mark.parametrize(
    "key", [k for k in PINNED if k not in USER] + [pytest.param(k, marks=pytest.mark.slow) for k in USER]
)
def test_served_forms_are_pinned_and_equal_the_engines(key):
    doc, d = _doc_and_derivation(key)
    pins = PINNED[key]
    served = {k: doc[k]["sympy"] for k in ("kinetic", "potential", "hamiltonian")}
    assert served == {k: pins[k] for k in served}
    assert [e["sympy"] for e in doc["equations_of_motion"]] == pins["equations"]
    assert {k: a["sympy"] for k, a in doc["accelerations"].items()} == pins["accelerations"]

    ns = d.table.namespace() | {s.name: s for s in d.table.qdd}
    parse = lambda text: sp.sympify(text, locals=ns)  # noqa: E731
    engine = {
        "kinetic": d.mechanics.T, "potential": d.mechanics.U, "lagrangian": d.mechanics.L,
        "hamiltonian": d.energetics.hamiltonian, "energy": d.energetics.energy,
    }  # fmt: skip
    rng = random.Random(27)
    for _ in range(4):
        at = _values(d, rng)
        for k, expr in engine.items():
            assert _close(float(parse(doc[k]["sympy"]).evalf(subs=at)), float(expr.evalf(subs=at))), (key, k)
        for name, a in zip(d.table.names, d.equations.accelerations, strict=True):
            assert _close(float(parse(doc["accelerations"][name]["sympy"]).evalf(subs=at)), float(a.evalf(subs=at)))
    # each equation is its residual divided by a factor free of velocities and accelerations (the same equation)
    for e, r in zip(doc["equations_of_motion"], d.equations.residuals, strict=True):
        shown = parse(e["sympy"])
        fixed = {s: rng.uniform(0.5, 1.5) for s in (*d.table.params, *d.table.q, d.table.t)}
        ratios = []
        for _ in range(3):
            at = {**_values(d, rng), **fixed}
            ratios.append(float(shown.evalf(subs=at)) / float(r.evalf(subs=at)))
        assert all(_close(x, ratios[0]) for x in ratios), (key, e["sympy"])


def test_served_text_is_what_the_latex_typesets():
    # the double pendulum: the recombined angle in both the text and the LaTeX, nowhere the products
    doc = derivation_document("double-pendulum")
    for pair in [doc["kinetic"], doc["lagrangian"], doc["hamiltonian"], *doc["accelerations"].values()]:
        assert "sin(theta1)*sin(theta2)" not in pair["sympy"]
        assert r"\sin {\theta_{1}} \sin {\theta_{2}}" not in pair["latex"]
    assert r"\cos{\left(\theta_{1} - \theta_{2} \right)}" in doc["kinetic"]["latex"]
    for step in doc["steps"]:
        if step["title"] in ("Kinetic energy", "Energy function h", "Accelerations", "Euler–Lagrange equations"):
            assert "cos(theta1)*cos(theta2)" not in step["sympy"], step["title"]
