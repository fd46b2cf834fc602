"""The playground's default start (issue 40, items 45 and 46): a cyclic coordinate turns at the steady motion's rate."""

import json
import math

import pytest

from app.engine.derivation.derive import derive
from app.engine.document.contract import printed_document
from app.engine.parser.user_system import UserSystem
from app.viz.user_page import model_of
from tests.web.pages.test_playground_prof_d import CONE

KEPLER = {
    "coordinates": ["r", "phi"],
    "nonnegative": ["r"],
    "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "k", "value": 2.0}],
    "lagrangian": "m/2*(r_dot**2 + r**2*phi_dot**2) + k/r",
}


def model(spec):
    user = UserSystem.of(spec)
    return model_of(user, printed_document(derive(user.system())), ["auto"])


def start(m) -> dict[str, float]:
    """The initial state the page's controls hold."""
    return {c["name"]: float(c["value"]) for c in m["initial"]}


@pytest.mark.slow
@pytest.mark.parametrize(
    ("spec", "rate"),
    [
        # the cone: p_φ² = m² g cot α r³, so φ̇² = g cot α / r at r = 1
        (CONE, math.sqrt(9.81 / math.tan(0.5))),
        # Kepler: p_φ² = m k r, so φ̇² = k/(m r³): the circular orbit through r = 1
        (KEPLER, math.sqrt(2.0)),
    ],
    ids=["cone", "kepler"],
)
def test_a_cyclic_coordinate_starts_near_the_steady_motion(spec, rate):
    """With the steady motion's momentum through r = 1 (p_φ ∝ r² φ̇ in both), from r = 1.1: φ̇(0) = rate/1.1², and
    r oscillates about 1 (a start on the steady motion made every plot a point, prof-f 37)."""
    m = model(spec)
    assert start(m)["r"] == pytest.approx(1.1) and start(m)["phi_dot"] == pytest.approx(rate / 1.1**2, rel=1e-5)
    assert "near the steady motion through r = 1" in m["initial_note"] and "φ̇(0)" in m["initial_note"]
    assert "r oscillates about 1" in m["initial_note"]
    # the starting rate with its unit (prof-f 35: a rate printed bare, or "per second")
    assert f"φ̇(0) = {start(m)['phi_dot']:.4g} rad/s " in m["initial_note"], m["initial_note"]


def test_a_system_without_a_reduction_starts_at_rest():
    spring = {"coordinates": ["x"], "parameters": [{"name": "m", "value": 1.0}, {"name": "k", "value": 1.0}],
              "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}  # fmt: skip
    m = model(spring)
    assert start(m) == {"x": 1.0, "x_dot": 0.0} and "initial_note" not in m


PENDULUM = {
    "coordinates": ["theta"],
    "parameters": [
        {"name": "m", "value": 1.0, "unit": "kg"},
        {"name": "g", "value": 9.8, "unit": "m/s^2"},
        {"name": "R", "value": 1.0, "unit": "m"},
    ],
    "lagrangian": "m/2*R**2*theta_dot**2 + m*g*R*cos(theta)",
}


@pytest.mark.slow
@pytest.mark.parametrize(("spec", "letter"), [(PENDULUM, "I_eff"), (KEPLER, "m_eff")])
def test_the_small_oscillation_panel_names_the_inertia_as_the_steps_do(spec, letter):
    # prof-n 5: "predicted from ω² = U_eff″/m_eff" beside a pendulum whose steps print I_eff = m R²
    client = json.loads(model(spec)["client_json"])
    assert client["reduction"]["inertia"] == letter
