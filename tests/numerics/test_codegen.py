"""Generated right-hand sides against the engine's expressions, evaluated independently by SymPy."""

import random

import numpy as np
import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.numerics.system import numeric_system
from app.scenes import SCENES
from app.scenes.types import Parameter, System
from tests.numerics.extreme_cases import system_for
from tests.numerics.systems import DOUBLE_PENDULUM

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

KEYS = sorted(SCENES) + ["stiff-spring"]


def random_point(s, rng):
    y = np.array([rng.uniform(0.3, 1.2) for _ in range(2 * s.n)])
    k = np.array([rng.uniform(0.5, 2.0) for _ in s.parameter_names])
    return rng.uniform(0.0, 2.0), y, k


def substitution(s, t, y, k):
    table = s.derivation.table
    values = {table.t: sp.Float(t, 30)}
    values.update({q: sp.Float(v, 30) for q, v in zip(table.q, y[: s.n], strict=True)})
    values.update({v: sp.Float(x, 30) for v, x in zip(table.qd, y[s.n :], strict=True)})
    values.update({p: sp.Float(x, 30) for p, x in zip(table.params, k, strict=True)})
    return values


@pytest.mark.parametrize("key", KEYS)
def test_rhs_matches_the_engine(key):
    s = system_for(key)
    rng = random.Random(11)
    for _ in range(3):
        t, y, k = random_point(s, rng)
        values = substitution(s, t, y, k)
        expected = [float(a.xreplace(values).evalf(30)) for a in s.derivation.equations.accelerations]
        got = s.f(t, y, k)
        np.testing.assert_allclose(got[: s.n], y[s.n :])
        np.testing.assert_allclose(got[s.n :], expected, rtol=1e-11, atol=1e-11)
        compiled = np.empty(2 * s.n)
        s.bound("rhs")(t, y, k, compiled)
        np.testing.assert_allclose(compiled, got, rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("key", KEYS)
def test_hamilton_form_is_consistent(key):
    """ham(q, p(q, v)) gives back v, and p_dot equals dp/dt along the motion (central differences)."""
    s = system_for(key)
    rng = random.Random(5)
    for _ in range(3):
        t, y, k = random_point(s, rng)
        z = np.concatenate([y[: s.n], s.momenta(t, y, k)])
        out = np.empty(2 * s.n)
        s.python["ham"](t, z, k, out)
        np.testing.assert_allclose(out[: s.n], y[s.n :], rtol=1e-12, atol=1e-12)
        eps = 1e-5
        F = s.f(t, y, k)
        dp = (s.momenta(t + eps, y + eps * F, k) - s.momenta(t - eps, y - eps * F, k)) / (2 * eps)
        np.testing.assert_allclose(out[s.n :], dp, rtol=1e-6, atol=1e-7)


@pytest.mark.parametrize("key", KEYS)
def test_jacobian_matches_differences(key):
    s = system_for(key)
    rng = random.Random(3)
    t, y, k = random_point(s, rng)
    J = s.jacobian(t, y, k)
    assert J is not None
    for j in range(2 * s.n):
        h = 1e-6
        up, down = y.copy(), y.copy()
        up[j] += h
        down[j] -= h
        np.testing.assert_allclose(J[:, j], (s.f(t, up, k) - s.f(t, down, k)) / (2 * h), rtol=1e-6, atol=1e-6)


def test_double_pendulum_and_solved_form_agree():
    """Compact symbolic accelerations and the M, f + LDL^T route give the same numbers."""
    from app.numerics import generate

    d = derive(DOUBLE_PENDULUM)
    names = generate.Names.of(d)
    original = generate._compact
    try:
        generate._compact = lambda *args: False
        solved = numeric_system(d)
    finally:
        generate._compact = original
    compact = numeric_system(d)
    assert "_x0" in solved.sources["rhs"] and "_x0" not in compact.sources["rhs"]
    rng = random.Random(2)
    for _ in range(5):
        t, y, k = random_point(compact, rng)
        np.testing.assert_allclose(solved.f(t, y, k), compact.f(t, y, k), rtol=1e-11, atol=1e-12)
    assert names.q == ["q0", "q1"]


def test_user_names_never_reach_the_source():
    """Parameters named like Python's own names (out, y, k, math) are renamed before printing."""
    system = System(
        coordinates=("x",),
        parameters=tuple(Parameter(n, 2.0, min=0.1) for n in ("out", "y", "k", "math")),
        kinetic="out*x_dot**2/2",
        potential="y*k*math*x**2/2",
    )
    s = numeric_system(derive(system))
    for name in ("out", "y", "k", "math"):
        assert f"{name} =" not in s.sources["rhs"].replace("out[", "")
    # x'' = -(y k math / out) x = -(8/2) x
    np.testing.assert_allclose(s.f(0.0, np.array([0.5, 0.0]), np.array([2.0, 2.0, 2.0, 2.0])), [0.0, -2.0])


def test_numeric_path_never_simplifies(monkeypatch):
    d = derive(DOUBLE_PENDULUM)

    def refuse(*args, **kwargs):
        raise AssertionError("simplify called on the numeric path")

    monkeypatch.setattr(sp, "simplify", refuse)
    monkeypatch.setattr(sp.Expr, "simplify", refuse)
    s = numeric_system(d)
    assert s.f(0.0, np.array([0.1, 0.2, 0.0, 0.0]), np.ones(5)).shape == (4,)


def test_structure_flags():
    assert system_for("simple-pendulum").separable
    assert not system_for("spherical-pendulum").separable  # M depends on theta
    assert not system_for("damped-pendulum").separable  # a velocity-dependent force
    assert system_for("spherical-pendulum").periodic == (True, True)
    assert system_for("stiff-spring").periodic == (False, True)
    assert system_for("rotating-parabola").energy_name == "h"
    assert system_for("damped-pendulum").energy_name is None
