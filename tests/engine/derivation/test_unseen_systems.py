"""Thirty-one systems the project was not written for, each checked by an independent route (issue 19).

For every system of ``unseen_systems``:

* accelerations, momenta, h and (when T is known) E from the engine against
  ``sympy.physics.mechanics.LagrangesMethod`` (tests/reference.py), at random points;
* the engine's claims (cyclic coordinates, what is conserved, whether h is conserved) along a
  trajectory integrated independently: scipy's DOP853 at rtol 1e-12 on LagrangesMethod's mass
  matrix and forcing, solved numerically at each step;
* the app's own simulation (``auto``) against that trajectory, within its reported error estimate;
* masses and lengths scaled by 1e-6 and 1e6: no refusal, the same accelerations.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from functools import cache

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me
from scipy.integrate import solve_ivp

from app.engine.derivation.derive import Derivation, derive
from app.numerics.methods import METHODS
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from tests import reference as reference_module
from tests.cases import stored
from tests.engine import unseen_systems
from tests.engine.scaling import check_scaled_accelerations, factors_for, scaling_cases
from tests.engine.unseen_systems import UNSEEN
from tests.reference import lagranges_method

pytestmark = pytest.mark.slow  # 31 systems derived and integrated twice

NAMES = sorted(UNSEEN)
SAMPLES = 41


@dataclass(frozen=True)
class Reference:
    """LagrangesMethod's M, forcing (+ Q), momenta, h and T + U as numpy functions of (t, q, q_dot, k)."""

    M: object
    forcing: object
    momenta: object
    h: object
    energy: object | None
    lagrangian: sp.Expr  # in the plain symbols
    plain_q: tuple[sp.Symbol, ...]


@cache
def ours(name: str) -> Derivation:
    return derive(UNSEEN[name].system)


def reference_expressions(name: str) -> dict[str, str | None]:
    """M, forcing + Q, momenta, h, E (None for an L-only system) and L from LagrangesMethod, as ``srepr``."""
    system = UNSEEN[name].system
    lm, qs, read = lagranges_method(system)
    t = me.dynamicsymbols._t
    plain_q = tuple(sp.Symbol(n, real=True) for n in system.coordinates)
    plain_v = tuple(sp.Symbol(f"{n}_dot", real=True) for n in system.coordinates)
    back = {q.diff(t): v for q, v in zip(qs, plain_v, strict=True)}
    back.update(dict(zip(qs, plain_q, strict=True)))
    plain = lambda e: sp.sympify(e).subs(back).subs(t, sp.Symbol("t", real=True))  # noqa: E731
    Q = sp.Matrix([read(system.forces.get(n, "0")) for n in system.coordinates])
    L = plain(sp.Matrix([lm._L])[0])  # LagrangesMethod keeps L as a 1x1 matrix
    # p_k = dL/dq_dot_k and h = sum_k p_k q_dot_k - L, from LagrangesMethod's L
    p = [sp.diff(L, v) for v in plain_v]
    h = sum(pk * v for pk, v in zip(p, plain_v, strict=True)) - L
    energy = None
    if system.lagrangian is None:
        # E = T + U with T = L + U
        U = plain(read(system.potential))
        energy = L + 2 * U
    found = {"M": plain(lm.mass_matrix), "forcing": plain(lm.forcing) + plain(Q), "momenta": sp.Matrix(p)}
    found.update({"h": h, "energy": energy, "L": L})
    return {key: None if e is None else sp.srepr(e) for key, e in found.items()}


@cache
def reference(name: str) -> Reference:
    # LagrangesMethod's results are kept on disk between runs, keyed by this file's and the reference's source
    # (tests/cases.py): it is the slow half of the independent route and never changes on its own
    sources = (__file__, reference_module.__file__, unseen_systems.__file__)
    found = stored(f"unseen-reference-{name}", lambda: reference_expressions(name), sources, ("scenes",))
    e = {key: None if text is None else sp.sympify(text) for key, text in found.items()}
    system = UNSEEN[name].system
    plain_q = tuple(sp.Symbol(n, real=True) for n in system.coordinates)
    plain_v = tuple(sp.Symbol(f"{n}_dot", real=True) for n in system.coordinates)
    args = [sp.Symbol("t", real=True), *plain_q, *plain_v, *(sp.Symbol(p.name, real=True) for p in system.parameters)]
    f = lambda e: sp.lambdify(args, e, modules="numpy", cse=True)  # noqa: E731
    return Reference(
        f(e["M"]),
        f(e["forcing"]),
        f(e["momenta"]),
        f(e["h"]),
        f(e["energy"]) if e["energy"] is not None else None,
        e["L"],
        plain_q,
    )


def parameters(name: str) -> np.ndarray:
    return np.array([p.default for p in UNSEEN[name].system.parameters], dtype=float)


def start(name: str) -> np.ndarray:
    u = UNSEEN[name]
    return np.array([u.start[q][0] for q in u.system.coordinates] + [u.start[q][1] for q in u.system.coordinates])


def ref_accelerations(ref: Reference, t: float, y: np.ndarray, k: np.ndarray) -> np.ndarray:
    M = np.array(ref.M(t, *y, *k), dtype=float)
    f = np.array(ref.forcing(t, *y, *k), dtype=float).ravel()
    return np.linalg.solve(M, f)


@cache
def independent_trajectory(name: str) -> tuple[np.ndarray, np.ndarray]:
    """t and y = (q, q_dot) by scipy DOP853 at rtol 1e-12 on LagrangesMethod's equations."""
    ref, k, y0, n = reference(name), parameters(name), start(name), len(UNSEEN[name].start)
    t = np.linspace(0.0, UNSEEN[name].t_end, SAMPLES)

    def rhs(time, y):
        return np.concatenate([y[n:], ref_accelerations(ref, time, y, k)])

    sol = solve_ivp(rhs, (0.0, t[-1]), y0, method="DOP853", t_eval=t, rtol=1e-12, atol=1e-13)
    assert sol.success, sol.message
    return t, sol.y.T


def engine_function(d: Derivation, expr: sp.Expr):
    table = d.table
    return sp.lambdify([table.t, *table.q, *table.qd, *table.params], expr, modules="numpy")


def close(a, b, rel=1e-9) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return bool(np.all(np.abs(a - b) <= rel * np.maximum(1.0, np.maximum(np.abs(a), np.abs(b)))))


@pytest.mark.parametrize("name", NAMES)
def test_engine_agrees_with_sympy_mechanics(name):
    d, ref = ours(name), reference(name)
    n = len(d.table.names)
    rng = random.Random(name)
    acc = engine_function(d, list(d.equations.accelerations))
    momenta = engine_function(d, list(d.equations.momenta))
    h = engine_function(d, d.energetics.hamiltonian)
    energy = engine_function(d, d.energetics.energy)
    for _ in range(3):
        t = rng.uniform(0.0, 1.0)
        y = np.array([rng.uniform(0.3, 1.3) for _ in range(2 * n)])
        k = parameters(name) * np.array([rng.uniform(0.8, 1.2) for _ in d.table.params])
        assert close(acc(t, *y, *k), ref_accelerations(ref, t, y, k)), "accelerations"
        assert close(momenta(t, *y, *k), np.ravel(ref.momenta(t, *y, *k))), "momenta"
        assert close(h(t, *y, *k), ref.h(t, *y, *k)), "h"
        if ref.energy is not None:
            assert close(energy(t, *y, *k), ref.energy(t, *y, *k)), "E"
    # a coordinate is cyclic exactly when LagrangesMethod's L does not contain it (and no force acts on it)
    system = UNSEEN[name].system
    cyclic = [
        q.name for q in ref.plain_q if sp.diff(ref.lagrangian, q).equals(0) and system.forces.get(q.name, "0") == "0"
    ]
    assert list(d.energetics.cyclic) == cyclic


@pytest.mark.parametrize("name", NAMES)
def test_claims_hold_on_an_independent_trajectory(name):
    d = ours(name)
    t, y = independent_trajectory(name)
    k, n = parameters(name), len(d.table.names)
    columns = [t, *y.T, *(np.full_like(t, v) for v in k)]
    for c in d.energetics.conserved:
        values = np.broadcast_to(engine_function(d, c.expr)(*columns), t.shape)
        scale = max(float(np.max(np.abs(values))), float(np.max(np.abs(y))))
        assert np.max(np.abs(values - values[0])) <= 1e-8 * scale, f"{c.name} is called conserved but drifts"
    if not d.energetics.h_conserved:
        values = np.broadcast_to(engine_function(d, d.energetics.hamiltonian)(*columns), t.shape)
        assert np.ptp(values) > 1e-6 * max(1.0, float(np.max(np.abs(values)))), "h is called not conserved but is"
    assert n == len(UNSEEN[name].start)


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_simulation_agrees_with_the_independent_trajectory_within_its_estimate(name):
    t, y = independent_trajectory(name)
    n = len(UNSEEN[name].start)
    out = simulate(numeric_system(ours(name)), parameters(name), start(name), t[-1], SAMPLES, "auto", 1e-9, 1e-11)
    assert out.trajectory.complete, out.trajectory.stop_reason
    error = float(np.max(np.abs(out.trajectory.y[:, :n] - y[:, :n])))
    estimate = out.estimate.value
    # the estimate may overstate the error, never understate it by more than 10x (docs/numerics.md)
    assert error <= 10 * estimate + 1e-11 * max(1.0, float(np.max(np.abs(y[:, :n])))), (out.method, error, estimate)
    assert estimate < 1e-5, (out.method, estimate)


@pytest.mark.slow
@pytest.mark.parametrize("method", sorted(METHODS))
def test_every_integrator_on_kepler(method):
    t, y = independent_trajectory("kepler-cartesian")
    s = numeric_system(ours("kepler-cartesian"))
    out = simulate(s, parameters("kepler-cartesian"), start("kepler-cartesian"), t[-1], SAMPLES, method, 1e-8, 1e-10)
    error = float(np.max(np.abs(out.trajectory.y[:, :2] - y[:, :2])))
    assert error <= 10 * out.estimate.value + 1e-11, (error, out.estimate.value)
    assert error < 1e-4


def test_the_kapitza_pendulum_as_l_and_as_a_particle_agree():
    # the same physics declared two ways: the L form drops a total time derivative and terms in t alone
    a, b = ours("kapitza-pendulum-as-L"), ours("kapitza-pendulum-as-particle")
    assert sp.simplify(a.equations.accelerations[0] - b.equations.accelerations[0]) == 0
    assert a.energetics.h_equals_e is None and b.energetics.h_equals_e is False
    assert not a.energetics.h_conserved and not b.energetics.h_conserved


def test_the_magnetic_forms_name_no_moving_constraint():
    for name in ("charge-in-a-field-symmetric-gauge", "charge-in-a-field-landau-gauge-with-a-trap"):
        en = ours(name).energetics
        assert en.h_equals_e is False and "magnetic" in en.reason and "time" not in en.reason
    lorentz = ours("charge-in-a-field-lorentz-force").energetics
    assert lorentz.h_equals_e is True and lorentz.h_conserved  # the Lorentz force does no work


UNSEEN_SYSTEMS = {name: u.system for name, u in UNSEEN.items()}
# masses and lengths together (each alone is covered on the chapter's scenes, tests/engine/derivation/test_singularity.py)
SCALINGS = scaling_cases(UNSEEN_SYSTEMS, (("kg", "m"),))


# the triple pendulum's Cramer's rule takes seconds per derivation
SLOW_TO_DERIVE = {"triple-pendulum"}


@pytest.mark.parametrize(
    ("name", "units", "factor"),
    [
        pytest.param(s, u, f, id=f"{s}-{'+'.join(u)}-{f:g}", marks=[pytest.mark.slow] if s in SLOW_TO_DERIVE else [])
        for s, u, f in SCALINGS
    ],
)
def test_scaled_masses_and_lengths_keep_the_accelerations(name, units, factor):
    system = UNSEEN_SYSTEMS[name]
    check_scaled_accelerations(system, factors_for(system, units, factor), ours(name).equations.accelerations)
