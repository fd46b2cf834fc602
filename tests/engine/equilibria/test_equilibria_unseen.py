"""Equilibria, steady motions and their stability for systems beyond the chapter (issue 32).

Every expected position, verdict and frequency below is derived by hand in the comments or computed
here independently (numpy/scipy on formulas written out in this file); none is read off the engine.
Every equilibrium the engine lists is checked against the equations of motion, and every verdict
against a short simulation started close to it (test_verdicts_agree_with_simulations).
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np
import pytest
import scipy.linalg
import scipy.optimize
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.document.contract import derivation_json
from app.engine.document.report_modes import normal_mode_steps
from app.engine.equilibria.equilibrium import MAX_EQUILIBRIA, defaults
from app.engine.equilibria.modes import NEUTRAL, STABLE, UNSTABLE, normal_modes
from tests.cases import case_list
from tests.engine import equilibria_systems
from tests.engine.equilibria_systems import MU, SYSTEMS

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

g = 9.81


@cache
def derived(name):
    return derive(SYSTEMS[name])


@cache
def modes(name):
    d = derived(name)
    return normal_modes(d.system, d.mechanics, d.equations, d.reduction)


def rest(name):
    """The equilibria at rest, as {position tuple: Equilibrium}."""
    return {tuple(round(v, 6) for v in e.position.values()): e for e in modes(name).equilibria if not e.momenta}


def steady(name):
    return sorted((e for e in modes(name).equilibria if e.momenta), key=lambda e: next(iter(e.position.values())))


def omegas(e):
    return sorted(m.omega_squared for m in e.modes)


def brent_roots(f, lo, hi, n=20001):
    """Every sign change of f on [lo, hi], refined (the test's own root finder)."""
    xs = np.linspace(lo, hi, n)
    ys = np.array([f(x) for x in xs])
    out = []
    for a, b, fa, fb in zip(xs[:-1], xs[1:], ys[:-1], ys[1:], strict=True):
        if fa == 0:
            out.append(a)
        elif np.isfinite(fa) and np.isfinite(fb) and fa * fb < 0:
            x = scipy.optimize.brentq(f, a, b, xtol=1e-14)
            if abs(f(x)) < 1e-8 * max(1.0, abs(fa), abs(fb)):
                out.append(x)
    return out


def second(f, x, h=1e-4):
    return (f(x + h) - 2 * f(x) + f(x - h)) / h**2


# --- bead on a rotating hoop: phi from the top, so the bottom is phi = pi ---------------------------------
# V = m g R cos(phi) - m R^2 w^2 sin^2(phi)/2; V' = -m R sin(phi) (g + R w^2 cos(phi));
# at 0: omega^2 = -(g/R + w^2); at pi: g/R - w^2; at cos(phi) = -g/(R w^2): w^2 - g^2/(R^2 w^2)


def test_the_slowly_rotating_hoop_has_its_bottom_stable_and_its_top_unstable():
    found = rest("hoop-slow")
    assert set(found) == {(0.0,), (round(math.pi, 6),)}
    assert found[(0.0,)].kind == UNSTABLE and omegas(found[(0.0,)]) == pytest.approx([-(g + 4)])
    bottom = found[(round(math.pi, 6),)]
    assert bottom.kind == STABLE and omegas(bottom) == pytest.approx([g - 4])


def test_the_fast_hoop_has_four_equilibria_the_side_ones_stable():
    found = rest("hoop-fast")
    side = math.acos(-g / 25)
    assert set(found) == {(0.0,), (round(math.pi, 6),), (round(side, 6),), (round(-side, 6),)}
    assert found[(round(math.pi, 6),)].kind == UNSTABLE and omegas(found[(round(math.pi, 6),)]) == pytest.approx(
        [g - 25]
    )
    for s in (side, -side):
        e = found[(round(s, 6),)]
        assert e.kind == STABLE and omegas(e) == pytest.approx([25 - g**2 / 25])
    assert not modes("hoop-fast").solved  # trigonometric: found by SymPy and the search, not provably all


def test_the_elastic_pendulum_in_cartesian_coordinates_hangs_below_its_natural_length():
    m, k, l0 = 1.0, 20.0, 1.0
    hang, stand = -(l0 + m * g / k), l0 - m * g / k
    found = rest("elastic-pendulum-cartesian")
    assert set(found) == {(0.0, round(hang, 6)), (0.0, round(stand, 6))}
    # radial k/m; sideways the tension over the length: g / |y| hanging, -g / y standing on the spring
    assert omegas(found[(0.0, round(hang, 6))]) == pytest.approx(sorted([k / m, g / -hang]))
    assert found[(0.0, round(hang, 6))].kind == STABLE
    assert omegas(found[(0.0, round(stand, 6))]) == pytest.approx(sorted([k / m, -g / stand]))
    assert found[(0.0, round(stand, 6))].kind == UNSTABLE


def free_hoop_u(theta, p=1.0, m=0.2, R=0.5, J=0.1):
    # U_eff = p^2 / (2 (J + m R^2 sin^2)) - m g R cos(theta)
    return p**2 / (2 * (J + m * R**2 * math.sin(theta) ** 2)) - m * g * R * math.cos(theta)


def test_the_free_hoop_at_p_phi_1_turns_steadily_at_plus_and_minus_theta_star():
    m, R = 0.2, 0.5
    roots = brent_roots(lambda x: (free_hoop_u(x + 1e-6) - free_hoop_u(x - 1e-6)) / 2e-6, -3.0, 3.0)
    star = [x for x in roots if abs(x) > 1e-3]
    assert len(star) == 2 and star == pytest.approx([-1.1632, 1.1632], abs=1e-4)  # the figures
    found = steady("free-hoop")
    positions = [e.position["theta"] for e in found]
    assert positions == pytest.approx(sorted([*star, 0.0, math.pi]), abs=1e-7)
    for e in found:
        theta = e.position["theta"]
        assert e.momenta == {"p_phi": 1.0}
        # omega^2 = U_eff'' / (m R^2)
        assert omegas(e)[0] == pytest.approx(second(free_hoop_u, theta) / (m * R**2), rel=1e-4)
        tilted = min(abs(abs(theta) - abs(s)) for s in star) < 1e-9
        assert e.kind == (STABLE if tilted else UNSTABLE)
        if tilted:
            assert omegas(e)[0] == pytest.approx(50.9, abs=0.05)
    # at rest: hanging (phi free, so one neutral direction) and upside down
    at_rest = rest("free-hoop")
    assert at_rest[(0.0, 0.0)].kind == NEUTRAL and at_rest[(round(math.pi, 6), 0.0)].kind == UNSTABLE


def test_a_support_moving_on_a_circle_leaves_no_equilibrium():
    nm = modes("support-on-a-circle")
    assert not nm.equilibria and not nm.unclassified
    assert "No equilibrium" in nm.note and "support moves" in nm.note


def test_the_pendulum_in_an_accelerating_car_hangs_back_at_atan_a_over_g():
    A, length = 3.0, 1.0
    lean = -math.atan(A / g)
    found = rest("accelerating-car")
    assert set(found) == {(round(lean, 6),), (round(lean + math.pi, 6),)}
    assert found[(round(lean, 6),)].kind == STABLE
    assert omegas(found[(round(lean, 6),)]) == pytest.approx([math.hypot(g, A) / length])
    assert omegas(found[(round(lean + math.pi, 6),)]) == pytest.approx([-math.hypot(g, A) / length])
    assert modes("accelerating-car").moving_frame  # the db/dt term is what tilts it


def test_a_total_time_derivative_added_to_l_changes_nothing():
    (e,) = modes("oscillator-with-a-gauge-term").equilibria
    assert e.position == {"x": 0.0} and e.kind == STABLE and omegas(e) == pytest.approx([8.0 / 2.0])


def test_the_penning_trap_is_gyroscopically_stable():
    (e,) = modes("penning-trap").equilibria
    B, k = 3.0, 1.0
    # omega_+- = (B +- sqrt(B^2 - 2 k)) / 2 in the plane, sqrt(k) along the axis
    expected = sorted([(B - math.sqrt(B**2 - 2 * k)) / 2, (B + math.sqrt(B**2 - 2 * k)) / 2, math.sqrt(k)])
    assert e.kind == STABLE and e.linear.gyroscopic
    assert list(e.linear.frequencies) == pytest.approx(expected, rel=1e-9)
    assert expected == pytest.approx([0.1771, 1.0, 2.8229], abs=1e-4)  # the figures
    assert min(omegas(e)) < 0  # K alone says unstable


def collinear_points(mu=MU):
    # dU/dx on the x axis of the rotating frame: x - (1 - mu)(x + mu)/|x + mu|^3 - mu (x - 1 + mu)/|x - 1 + mu|^3
    f = lambda x: x - (1 - mu) * (x + mu) / abs(x + mu) ** 3 - mu * (x - 1 + mu) / abs(x - 1 + mu) ** 3  # noqa: E731
    return brent_roots(f, -3.0, 3.0, 60001)


def test_the_lagrange_points_l4_and_l5_are_stable_and_l1_to_l3_are_not():
    found = rest("restricted-three-body")
    mu = MU
    triangle = [(round(0.5 - mu, 6), round(s * math.sqrt(3) / 2, 6)) for s in (1, -1)]
    line = [(round(x, 6), 0.0) for x in collinear_points()]
    assert len(line) == 3
    assert set(found) == set(triangle) | set(line)
    # lambda^4 + lambda^2 + 27 mu (1 - mu) / 4 = 0: omega^2 = (1 +- sqrt(1 - 27 mu (1 - mu))) / 2
    root = math.sqrt(1 - 27 * mu * (1 - mu))
    expected = sorted([math.sqrt((1 - root) / 2), math.sqrt((1 + root) / 2)])
    assert expected == pytest.approx([0.268, 0.963], abs=1e-3)
    for p in triangle:
        e = found[p]
        assert e.kind == STABLE and e.linear.gyroscopic
        assert list(e.linear.frequencies) == pytest.approx(expected, rel=1e-7)
    assert all(found[p].kind == UNSTABLE for p in line)


def test_a_frame_turning_faster_than_the_oscillator_is_gyroscopically_stable():
    (e,) = modes("rotating-frame-oscillator").equilibria
    k, W = 1.0, 2.0
    # in the inertial frame the oscillator has frequency sqrt(k); seen from the frame, |sqrt(k) +- W|
    assert e.kind == STABLE and e.linear.gyroscopic
    assert list(e.linear.frequencies) == pytest.approx(sorted([abs(math.sqrt(k) - W), math.sqrt(k) + W]))


def coupled_roots(k):
    # the test's own count: Newton from a dense grid over both periods, merged modulo 2 pi
    def grad(v):
        a, b = v
        s = k * (math.sin(a) - math.sin(b))
        return [g * math.sin(a) + s * math.cos(a), g * math.sin(b) - s * math.cos(b)]

    out = []
    for a0 in np.linspace(-math.pi, math.pi, 25):
        for b0 in np.linspace(-math.pi, math.pi, 25):
            x, _, ok, _ = scipy.optimize.fsolve(grad, [a0, b0], full_output=True)
            if ok != 1 or max(abs(v) for v in grad(x)) > 1e-10:
                continue
            x = [(v + math.pi) % (2 * math.pi) - math.pi for v in x]
            x = [math.pi if abs(v + math.pi) < 1e-7 else v for v in x]
            if not any(max(abs(u - w) for u, w in zip(x, y, strict=True)) < 1e-6 for y in out):
                out.append(x)
    return sorted((round(a, 6) + 0.0, round(b, 6) + 0.0) for a, b in out)


@pytest.mark.parametrize(("name", "k"), [("coupled-pendula", 2.0), ("coupled-pendula-soft-spring", 0.01)])
def test_coupled_pendula_list_each_equilibrium_once(name, k):
    found = rest(name)
    assert sorted(found) == coupled_roots(k) and len(found) == 4
    # bottom: omega^2 = g/l and g/l + 2 k/m (m = l = 1)
    assert omegas(found[(0.0, 0.0)]) == pytest.approx([g, g + 2 * k])


def test_masses_a_million_and_a_millionth_still_get_modes():
    found = rest("double-pendulum-extreme-masses")
    m1, m2, l1, l2 = 1e6, 1e-6, 1.0, 0.5
    assert set(found) == {(0.0, 0.0), (0.0, round(math.pi, 6)), (round(math.pi, 6), 0.0), (round(math.pi, 6),) * 2}
    assert not modes("double-pendulum-extreme-masses").singular
    for (a, b), e in found.items():
        M = np.array(
            [[(m1 + m2) * l1**2, m2 * l1 * l2 * math.cos(a - b)], [m2 * l1 * l2 * math.cos(a - b), m2 * l2**2]]
        )
        K = np.diag([(m1 + m2) * g * l1 * math.cos(a), m2 * g * l2 * math.cos(b)])
        expected = np.sort(scipy.linalg.eigvals(K, M).real)
        assert omegas(e) == pytest.approx(expected, rel=1e-8)
        assert e.kind == (STABLE if (a, b) == (0.0, 0.0) else UNSTABLE)


def top_u(theta, I1=1.0, I3=0.5, Mgh=9.81 * 0.2, p_phi=1.0, p_psi=1.0):
    # U_eff = (p_phi - p_psi cos)^2 / (2 I1 sin^2) + p_psi^2 / (2 I3) + M g h cos
    return (
        (p_phi - p_psi * math.cos(theta)) ** 2 / (2 * I1 * math.sin(theta) ** 2)
        + p_psi**2 / (2 * I3)
        + Mgh * math.cos(theta)
    )


def test_the_symmetric_top_written_with_body_rates_precesses_steadily():
    nm = modes("symmetric-top-body-rates")
    assert not nm.failed
    # at rest, the Euler angles' poles: M singular there
    assert sorted(p["theta"] for p in nm.singular) == pytest.approx([0.0, math.pi])
    du = lambda x: (top_u(x + 1e-6) - top_u(x - 1e-6)) / 2e-6  # noqa: E731
    tilted = [x for x in brent_roots(du, -3.1, 3.1) if abs(x) > 1e-3]
    found = steady("symmetric-top-body-rates")
    assert [e.position["theta"] for e in found] == pytest.approx(sorted([*tilted, 0.0]), abs=1e-7)
    for e in found:
        theta = e.position["theta"]
        if theta == 0.0:
            # the sleeping top: U_eff ~ p^2 theta^2 / (8 I1) - M g h theta^2 / 2 near 0, unstable as p^2 < 4 I1 M g h
            assert omegas(e) == pytest.approx([1.0 / 4 - 9.81 * 0.2], rel=1e-5) and e.kind == UNSTABLE
        else:
            assert omegas(e) == pytest.approx([second(top_u, theta)], rel=1e-4) and e.kind == STABLE


def yukawa_u(r, p=1.0, k=1.0, a=2.0):
    return p**2 / (2 * r**2) - k * math.exp(-r / a) / r


def test_the_yukawa_force_has_a_stable_and_an_unstable_circular_orbit():
    roots = brent_roots(lambda r: (yukawa_u(r + 1e-7) - yukawa_u(r - 1e-7)) / 2e-7, 0.05, 60.0)
    assert len(roots) == 2
    found = steady("yukawa")
    assert [e.position["r"] for e in found] == pytest.approx(roots, rel=1e-7)
    inner, outer = found
    assert inner.kind == STABLE and outer.kind == UNSTABLE
    assert omegas(inner) == pytest.approx([second(yukawa_u, roots[0])], rel=1e-4)
    assert omegas(outer) == pytest.approx([second(yukawa_u, roots[1], 1e-3)], rel=1e-3)


def test_the_asymmetric_heavy_top_is_derived_with_its_poles_singular():
    nm = modes("asymmetric-heavy-top")
    assert not nm.failed and not nm.equilibria
    assert sorted(p["theta"] for p in nm.singular) == pytest.approx([0.0, math.pi])


def test_a_negative_or_indefinite_mass_matrix_is_linearized_all_the_same():
    (neg,) = modes("negative-kinetic-energy").equilibria
    assert neg.kind == STABLE and omegas(neg) == pytest.approx([4.0]) and neg.linear.definite == -1
    (mixed,) = modes("indefinite-mass-matrix").equilibria
    assert mixed.kind == STABLE and omegas(mixed) == pytest.approx([4.0, 4.0]) and mixed.linear.definite == 0


def test_a_polynomial_condition_is_solved_exactly_and_says_so():
    nm = modes("double-well")
    assert nm.solved
    found = rest("double-well")
    w = math.sqrt(3.0 / 2.0)
    assert set(found) == {(round(-w, 6),), (0.0,), (round(w, 6),)}
    assert omegas(found[(0.0,)]) == pytest.approx([-3.0]) and omegas(found[(round(w, 6),)]) == pytest.approx([6.0])
    (step, *_) = normal_mode_steps(derived("double-well"), nm)
    assert "These are all the equilibria" in step["explanation"]  # said as physics, not as computer algebra


def test_many_roots_are_all_found_and_never_called_exact():
    c = 20.0
    expected = brent_roots(lambda x: math.sin(x) + x / c, -30.0, 30.0)
    nm = modes("many-roots")
    assert nm.found == len(expected) and not nm.solved
    shown = sorted(e.position["x"] for e in nm.equilibria)
    nearest = sorted(sorted(expected, key=abs)[:MAX_EQUILIBRIA])
    assert shown == pytest.approx(nearest, abs=1e-8)
    for e in nm.equilibria:
        x = e.position["x"]
        assert omegas(e) == pytest.approx([math.cos(x) + 1 / c], rel=1e-7, abs=1e-9)
    (step, *_) = normal_mode_steps(derived("many-roots"), nm)
    assert "exactly" not in step["explanation"] and "others may exist" in step["explanation"]
    assert f"{len(expected)} were found" in step["explanation"]


def test_a_bead_on_a_rotating_rod_runs_away_from_the_axis():
    (e,) = modes("rotating-rod-bead").equilibria
    assert e.kind == UNSTABLE and omegas(e) == pytest.approx([-(1.5**2)])


def test_damping_makes_the_oscillator_asymptotically_stable():
    (e,) = modes("damped-oscillator").equilibria
    m, k, c = 1.0, 4.0, 0.5
    assert e.kind == STABLE and e.linear.damped
    assert all(s.real == pytest.approx(-c / (2 * m)) for s in e.linear.exponents)
    assert list(e.linear.frequencies) == pytest.approx([math.sqrt(k / m - c**2 / (4 * m**2))])


def test_a_vertically_driven_support_keeps_both_rest_points_without_constant_frequencies():
    nm = modes("vertically-driven-pendulum")
    assert not nm.equilibria
    assert sorted(p["theta"] for p in nm.unclassified) == pytest.approx([0.0, math.pi])


@pytest.mark.parametrize("name", ["hoop-fast", "accelerating-car", "penning-trap", "support-on-a-circle"])
def test_the_document_keeps_its_shape_and_claims_nothing_it_cannot_show(name):
    doc = derivation_json(derived(name))
    nm = modes(name)
    assert len(doc["normal_modes"]) == len(nm.equilibria)
    for entry, e in zip(doc["normal_modes"], nm.equilibria, strict=True):
        # the fields the page and API read, and the new ones added beside them
        assert {"equilibrium", "exact", "momenta", "stable", "kind", "coordinates", "modes"} <= set(entry)
        assert entry["frequencies"] == pytest.approx(list(e.linear.frequencies))
        assert len(entry["exponents"]) == 2 * len(e.coordinates) and isinstance(entry["gyroscopic"], bool)
        # complex modes only where velocity terms act (the Penning trap's three oscillations)
        assert len(entry["complex_modes"]) == (3 if name == "penning-trap" else 0)
    step = next(s for s in doc["steps"] if s["title"] == "Equilibria")
    assert ("These are all the equilibria" in step["explanation"]) == nm.solved
    if name == "support-on-a-circle":
        assert "No equilibrium" in step["explanation"]
    if name == "penning-trap":
        modes_step = next(s for s in doc["steps"] if s["title"].startswith("Normal modes about"))
        assert "gyroscopically stable" in modes_step["explanation"]


# --- every listed equilibrium is one ------------------------------------------------------------------


@cache
def accelerations(name):
    d = derived(name)
    table = d.table
    f = sp.lambdify([*table.q, *table.qd, *table.params, table.t], list(d.equations.accelerations), modules="numpy")
    return lambda q, v, t: np.array(f(*q, *v, *[defaults(d.system, d.table)[s] for s in table.params], t), dtype=float)


def state(name, e):
    """q and q_dot at the equilibrium (the cyclic velocities that hold the momenta, for a steady motion)."""
    d = derived(name)
    table = d.table
    q = np.zeros(len(table.q))
    v = np.zeros(len(table.q))
    for i, n in enumerate(table.names):
        q[i] = e.position.get(n, 0.0)
    if e.momenta:
        at = {**defaults(d.system, d.table), **{sp.Symbol(p, real=True): x for p, x in e.momenta.items()}}
        at.update(dict(zip(table.q, q, strict=True)))
        for velocity, expr in d.reduction.cyclic_velocities.items():
            v[table.qd.index(velocity)] = float(sp.sympify(expr).xreplace(at))
    return q, v


# (system, index) for each equilibrium the engine lists (the list kept on disk between runs: tests/cases.py)
LISTED = case_list(
    "equilibria-unseen",
    lambda: [(name, i) for name in sorted(SYSTEMS) for i in range(len(modes(name).equilibria))],
    __file__,
    equilibria_systems.__file__,
)


@pytest.mark.parametrize(("name", "index"), LISTED)
def test_every_listed_equilibrium_satisfies_the_equations_at_all_times(name, index):
    found = modes(name).equilibria
    q, v = state(name, found[index])
    if not np.all(np.isfinite(v)):
        # a steady motion at a pole of the coordinates (the sleeping top at theta = 0): the full equations are
        # 0/0 there, so the reduced condition U_eff' = 0 is checked on both sides instead (it is odd about 0)
        d = derived(name)
        red = d.reduction
        r = d.table.q[d.table.names.index(red.coordinate)]
        at = {**defaults(d.system, d.table), **{sp.Symbol(p, real=True): x for p, x in found[index].momenta.items()}}
        at.update({s: 0.3 for s in d.table.q if s != r})
        du = sp.lambdify(r, sp.sympify(red.equilibrium_condition).xreplace(at))
        x0 = found[index].position[red.coordinate]
        assert abs(du(x0 + 1e-4) + du(x0 - 1e-4)) <= 1e-6 * abs(du(x0 + 0.1))
        assert abs(du(x0 + 1e-4)) <= 1e-2 * abs(du(x0 + 0.1))
        return
    acc = accelerations(name)
    scale = max(1.0, float(np.abs(acc(q + 0.1, v, 0.0)).max()))
    for t in (0.0, 1.3, 2.9):
        assert np.abs(acc(q, v, t)).max() <= 1e-8 * scale, (name, found[index].position, t)


def test_gyroscopic_modes_are_complex_and_solve_the_full_linearization():
    for name in ("penning-trap", "rotating-frame-oscillator", "restricted-three-body"):
        for e in modes(name).equilibria:
            d = derived(name)
            M = np.array(e.mass.xreplace(defaults(d.system, d.table)).evalf().tolist(), dtype=float)
            K = np.array(e.stiffness.xreplace(defaults(d.system, d.table)).evalf().tolist(), dtype=float)
            # G from the equations of motion written out independently: M q'' = f, G = -df/dq_dot at rest
            zero = dict.fromkeys(d.table.qd, 0)
            at = {**defaults(d.system, d.table), **dict(zip(d.table.q, e.position.values(), strict=True))}
            G = np.array(
                [[float(-sp.diff(f, v).xreplace(zero).xreplace(at)) for v in d.table.qd] for f in d.equations.forcing]
            )
            assert len(e.linear.complex_modes) == len(e.linear.frequencies)
            for s, a in e.linear.complex_modes:
                a = np.array(a)
                # (s^2 M + s G + K) a = 0
                residual = (s**2 * M + s * G + K) @ a
                assert np.abs(residual).max() <= 1e-8 * max(1.0, np.abs(K).max(), abs(s) ** 2 * np.abs(M).max())
                assert np.abs(a).max() == pytest.approx(1.0)


@pytest.mark.parametrize("name", ["yukawa", "symmetric-top-body-rates"])
def test_the_user_path_derives_what_it_used_to_refuse(name):
    # these crashed in the steady-motion step ('float' object has no attribute 'evalf') and were refused
    # as "a limit of the engine"; the whole document is served now, steady motions included
    import json

    from app.engine.parser.user_system import UserSystem
    from app.service.users.user_jobs import derive_job

    s = SYSTEMS[name]
    body = {
        "coordinates": list(s.coordinates),
        "parameters": [{"name": p.name, "value": p.default} for p in s.parameters],
        "potential": s.potential,
        "nonnegative": list(s.nonnegative),
    }
    if s.kinetic:
        body["kinetic"] = s.kinetic
    else:
        body["particles"] = [{"mass": p.mass, "position": list(p.position[:2])} for p in s.particles]
    doc = json.loads(derive_job(UserSystem.of(body)))
    served = [e for e in doc["normal_modes"] if e["momenta"]]
    assert len(served) == len(steady(name)) >= 2
