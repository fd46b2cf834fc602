"""Quotients as a textbook writes them (app/engine/display/quotients.py), as the rules and as the documents serve them."""

import sympy as sp

from app.engine.display.quotients import cleared, denominators_grouped, grouped, own_denominators
from app.service.chapter.derivations import derivation_document

r, m, k, R, g, b, M, m1, m2 = sp.symbols("r m k R g b M m1 m2", real=True)
theta, theta_dot, p_r, p_theta = sp.symbols("theta theta_dot p_r p_theta", real=True)


def test_a_sum_over_a_product_splits_when_its_terms_have_different_denominators():
    # r(mθ̇² − k)/m = rθ̇² − kr/m (prof-g 21)
    split = own_denominators(r * (m * theta_dot**2 - k) / m, {r, theta_dot})
    assert split == r * theta_dot**2 - k * r / m
    # Hamilton's kinetic part (p_r² + p_θ²/r²)/(2m): each momentum over its own denominator
    h = own_denominators(k * r**2 / 2 + (p_r**2 + p_theta**2 / r**2) / (2 * m), {r, p_r, p_theta})
    assert set(sp.Add.make_args(h)) == {k * r**2 / 2, p_r**2 / (2 * m), p_theta**2 / (2 * m * r**2)}


def test_a_sum_whose_terms_share_their_denominator_stays_over_it():
    x1, x2, kappa = sp.symbols("x1 x2 kappa", real=True)
    coupled = (kappa * x2 - (k + kappa) * x1) / m
    assert own_denominators(coupled, {x1, x2}) == coupled
    # over a sum (the pulley's accelerations) one denominator stays
    over_sum = g * (3 * M * m2 - M * m1) / (M * m1 + M * m2 + 4 * m1 * m2)
    assert own_denominators(over_sum, {r}) == over_sum


def test_no_fraction_stays_inside_a_denominator():
    chapter = g - 2 * (m1 + m2) * g / (m1 + m2 + 4 * m1 * m2 / M)
    out = cleared(chapter)
    assert sp.simplify(out - chapter) == 0
    for power in out.atoms(sp.Pow):
        if power.exp.is_negative and isinstance(power.base, sp.Add):
            assert all(not sp.denom(t).free_symbols for t in power.base.args), power
    assert grouped(M * m1 + M * m2 + 4 * m1 * m2) == M * (m1 + m2) + 4 * m1 * m2
    # a factor all the terms share is no grouping of some of them
    assert grouped(M * m1 + M * m2 + M * k) == M * m1 + M * m2 + M * k


def test_the_tabletop_serves_its_acceleration_and_hamiltonian_as_a_textbook_prints_them():
    doc = derivation_document("tabletop-spring")
    # r̈ = rθ̇² − (k/m) r, H = p_r²/2m + p_θ²/(2mr²) + ½kr²: kinetic terms first, each over its own denominator
    assert doc["accelerations"]["r"]["latex"] == r"r \dot{\theta}^{2} - \frac{k}{m} r"
    hamiltonian = r"\frac{p_{r}^{2}}{2 m} + \frac{p_{\theta}^{2}}{2 m r^{2}} + \frac{1}{2} k r^{2}"
    assert doc["hamilton"]["hamiltonian"]["latex"] == hamiltonian
    steps = {s["key"]: s["latex"] for s in doc["steps"]}
    assert r"\ddot{r} &= r \dot{\theta}^{2} - \frac{k}{m} r" in steps["accelerations"]
    assert steps["hamiltonian-pq"].endswith(f"= {hamiltonian}")


def test_the_pulley_prints_no_fraction_in_a_denominator():
    doc = derivation_document("pulley")
    shared = r"M \left(m_{1} + m_{2}\right) + 4 m_{1} m_{2}"
    for a in doc["accelerations"].values():
        assert a["latex"].endswith(f"{{{shared}}}")
    assert doc["constraint_forces"][0]["latex"] == rf"\frac{{4 M m_{{1}} m_{{2}} g}}{{{shared}}}"
    middle = next(e for e in doc["errata"] if e["correct"].startswith("Y_ddot"))
    assert middle["correct_latex"] == rf"\ddot{{Y}} = g - \frac{{2 \left(m_{{1}} + m_{{2}}\right) M g}}{{{shared}}}"
    everything = " ".join([*(s["latex"] for s in doc["steps"]), *(e["correct_latex"] for e in doc["errata"])])
    assert "/ M" not in everything


def test_the_spherical_pendulum_orders_its_functions_as_its_coordinates_are_declared():
    doc = derivation_document("spherical-pendulum")
    steps = {s["key"]: s["latex"] for s in doc["steps"]}
    # prof-g 24: sin θ before sin φ in every component, as θ is declared before φ
    assert steps["positions"] == (
        r"\vec r = \left(R \sin {\theta} \cos {\varphi}, R \sin {\theta} \sin {\varphi}, R \cos {\theta}\right)"
    )
    assert r"\sin {\varphi} \sin {\theta}" not in steps["velocities"]


def test_a_factor_every_term_of_a_denominator_holds_goes_in_front():
    """prof-o F5: Hamilton's p_r²/(2m + 2mc²) is printed p_r²/(2m(1 + c²)), as the velocities step writes m(1 + c²)."""
    m, c, r, p = sp.symbols("m c r p_r", real=True)
    out = denominators_grouped(p**2 / (2 * m + 2 * m * c**2) + r, {r, p})
    assert out == p**2 / (2 * m * (1 + c**2)) + r
    assert sp.denom(out - r) == 2 * m * (1 + c**2)
    # a sum with no factor common to all its terms is left to ``grouped``
    M, m1, m2 = sp.symbols("M m1 m2", positive=True)
    assert denominators_grouped(1 / (M * m1 + M * m2 + 4 * m1 * m2), set()) == 1 / (4 * m1 * m2 + M * (m1 + m2))


def test_a_sum_of_masses_below_keeps_the_inertia_as_t_prints_it():
    # the massive pulley's H: p²/(M + 2m₁ + 2m₂) is p²/(2(m₁ + m₂ + M/2)), the 𝓜 = m₁ + m₂ + M/2 of T and 𝓜 q̈ = f
    p = sp.Symbol("p_z", real=True)
    out = denominators_grouped(p**2 / (M + 2 * m1 + 2 * m2), {p})
    assert sp.Mul.make_args(out)[0] == sp.Rational(1, 2) and 1 / (m1 + m2 + M / 2) in sp.Mul.make_args(out)
    # every mass carrying the same number, or no number most carry: nothing to take out this way
    assert denominators_grouped(1 / (M + m1 + m2), set()) == 1 / (M + m1 + m2)
    assert denominators_grouped(1 / (M + 2 * m1 + 3 * m2), set()) == 1 / (M + 2 * m1 + 3 * m2)
    hamiltonian = {s["key"]: s["latex"] for s in derivation_document("massive-pulley")["steps"]}["hamiltonian-pq"]
    assert hamiltonian.endswith(
        r"= \frac{p_{z}^{2}}{2 \left(m_{1} + m_{2} + M / 2\right)} + \left(m_{2} - m_{1}\right) g z"
    )
