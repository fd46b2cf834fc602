"""POST /api/simulate of a Lagrangian not quadratic in the velocities: the relativistic oscillator (issue 42).

L = −mc²√(1 − ẋ²/c²) − ½kx² has ∂²L/∂q̇² = mγ³, which depends on ẋ; the app solves W ẍ = f at each step.
Checked from outside: h = γmc² + ½kx² stays constant along the app's run, and the period read off the run
agrees with the exact period 4∫₀ᵃ dx/v(x) (scipy's quad on the energy equation, written here by hand), which
grows with the amplitude a, its ratio to the light-speed limit 4a/c falling toward 1.
"""

import math
import unicodedata

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.interpolate import CubicHermiteSpline
from scipy.optimize import brentq

from app.web.api.examples_user import RELATIVISTIC_OSCILLATOR

VALUES = {p["name"]: p["value"] for p in RELATIVISTIC_OSCILLATOR["parameters"]}
M, C, K = VALUES["m"], VALUES["c"], VALUES["k"]


def run(client, amplitude: float, t_end: float, samples: int, tolerance: float = 1e-10) -> dict:
    body = {
        **RELATIVISTIC_OSCILLATOR,
        "initial": {"x": amplitude, "x_dot": 0.0},
        "t_end": t_end,
        "samples": samples,
        "rtol": tolerance,
        "atol": tolerance,
    }
    response = client.post("/api/simulate", json=body)
    assert response.status_code == 200, response.text
    return response.json()


def h_by_hand(x: np.ndarray, v: np.ndarray) -> np.ndarray:
    # h = Σ ẋ ∂L/∂ẋ − L = γmc² + ½kx², γ = 1/√(1 − ẋ²/c²)
    gamma = 1.0 / np.sqrt(1.0 - (v / C) ** 2)
    return gamma * M * C**2 + 0.5 * K * x**2


def exact_period(a: float) -> float:
    """4∫₀ᵃ dx / v(x), v from energy conservation: γ(x) mc² + ½kx² = mc² + ½ka² (at rest at x = a)."""

    def inverse_speed(theta: float) -> float:
        # x = a sin θ removes the 1/√(a − x) end point: dx = a cos θ dθ
        x = a * math.sin(theta)
        gamma = 1.0 + K * (a * a - x * x) / (2.0 * M * C * C)
        # v = c√(1 − 1/γ²) = c√((γ − 1)(γ + 1))/γ, and √(γ − 1) = √(k/2m) a cos θ / c: dx/v is smooth in θ
        v_over_cos = math.sqrt(K / (2.0 * M)) * a * math.sqrt(gamma + 1.0) / gamma
        return a / v_over_cos

    value, _ = quad(inverse_speed, 0.0, math.pi / 2, epsabs=0.0, epsrel=1e-11)
    return 4.0 * value


def measured_period(result: dict) -> float:
    """The mean time between successive upward zero crossings of x, on the run's Hermite interpolant."""
    t = np.array(result["t"])
    x, v = np.array(result["state"]["x"]), np.array(result["state"]["x_dot"])
    spline = CubicHermiteSpline(t, x, v)
    ups = [brentq(spline, t[i], t[i + 1], xtol=1e-14) for i in range(len(t) - 1) if x[i] < 0.0 <= x[i + 1]]
    assert len(ups) >= 2
    return float((ups[-1] - ups[0]) / (len(ups) - 1))


def test_h_is_conserved_along_the_run(client):
    result = run(client, 1.0, 20.0, 2001)
    x, v = np.array(result["state"]["x"]), np.array(result["state"]["x_dot"])
    # visibly relativistic: the bob passes the centre at more than nine tenths of c
    assert np.max(np.abs(v)) > 0.9 * C
    h = h_by_hand(x, v)
    assert np.max(np.abs(h - h[0])) < 1e-7 * h[0]
    # the app reports h as the conserved quantity and draws it: the same values
    assert "h" in result["conserved"]
    assert np.allclose(result["energy"], h, rtol=1e-9)


@pytest.mark.slow
def test_period_grows_with_amplitude_toward_4a_over_c(client):
    amplitudes = (0.05, 1.0, 4.0, 16.0)
    periods = []
    for a in amplitudes:
        expected = exact_period(a)
        # the turns at large amplitude are sharp (ẍ jumps from ±ka/m to about 0 within a short time): a tight tolerance
        measured = measured_period(run(client, a, 3.2 * expected, 3201, tolerance=1e-12))
        assert measured == pytest.approx(expected, rel=1e-6)
        periods.append(measured)
    # the slow limit 2π√(m/k) at small amplitude, longer as the amplitude grows
    slow = 2 * math.pi * math.sqrt(M / K)
    assert slow < periods[0] < 1.005 * slow
    assert all(b > a for a, b in zip(periods, periods[1:], strict=False))
    # the light-speed limit: the bob never reaches c, so T > 4a/c, and T / (4a/c) falls toward 1
    ratios = [T / (4 * a / C) for T, a in zip(periods, amplitudes, strict=True)]
    assert all(b < a for a, b in zip(ratios, ratios[1:], strict=False))
    assert 1.0 < ratios[-1] < 1.002


def test_a_lagrangian_singular_at_rest_is_a_422_saying_why(client):
    # L = ẋ⁴ − x²: ∂²L/∂ẋ² = 12ẋ² vanishes at rest, where the equations do not give ẍ
    response = client.post("/api/derive", json={"coordinates": ["x"], "lagrangian": "x_dot**4 - x**2"})
    assert response.status_code == 422
    detail = unicodedata.normalize("NFC", str(response.json()["detail"]))
    assert "singular at rest (ẋ = 0)" in detail and "invertible at q̇ = 0" in detail


@pytest.mark.slow
def test_the_playground_lists_the_example_and_derives_it(client):
    page = client.get("/playground")
    assert "Relativistic oscillator" in page.text
    doc = client.post("/api/derive", json=RELATIVISTIC_OSCILLATOR)
    assert doc.status_code == 200, doc.text
    skipped = {s["member"]: s["reason"] for s in doc.json()["skipped"]}
    assert "p = ∂L/∂q̇ is not linear in q̇" in skipped["hamilton"]
