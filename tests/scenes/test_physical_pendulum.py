"""The physical pendulum (issue 42): a uniform rod pivoted at one end, derived as a rigid body and printed
as a textbook prints it (Taylor § 10.1, Morin § 8.3): T = ⅙ M l² θ̇², U = −½ M g l cos θ, ω² = 3g/(2l)."""

import sympy as sp

from app.service.chapter.derivations import derivation, derivation_document
from tests.scenes.common import S

g, length = S("g"), S("l")


def _steps():
    return {s["key"]: s for s in derivation_document("physical-pendulum")["steps"]}


def test_t_is_the_centres_motion_plus_the_turning_about_the_centre():
    steps = _steps()
    assert r"I_{\mathrm{cm}} &= \frac{M l^{2}}{12}" in steps["bodies"]["latex"]
    # ω is the small-oscillation frequency on this page (ω² = 3g/(2l)): the rod's turning rate is θ̇, never ω
    assert r"\omega" not in steps["bodies"]["latex"], steps["bodies"]["latex"]
    kinetic = steps["kinetic"]["latex"]
    # the rod's two pieces, M l² θ̇²/8 (its centre at l/2 moving at (l/2) θ̇) and M l² θ̇²/24 (its turning), then T
    assert (
        r"T_{\mathrm{rod}} &= \tfrac{1}{2} M v_{\mathrm{cm}}^2 + \tfrac{1}{2} I_{\mathrm{cm}} \dot{\theta}^{2} = "
        r"\frac{1}{8} M l^{2} \dot{\theta}^{2} + \frac{1}{24} M l^{2} \dot{\theta}^{2}"
    ) in kinetic
    assert kinetic.endswith(r"T &= \frac{1}{6} M l^{2} \dot{\theta}^{2}\end{aligned}")


def test_textbook_forms_of_u_l_and_the_equation():
    doc = derivation_document("physical-pendulum")
    assert _steps()["potential"]["latex"] == r"U = - \frac{1}{2} M g l \cos {\theta}"
    assert doc["lagrangian"]["latex"] == r"\frac{1}{6} M l^{2} \dot{\theta}^{2} + \frac{1}{2} M g l \cos {\theta}"
    assert [e["latex"] for e in doc["equations_of_motion"]] == [r"\ddot{\theta} + \frac{3 g}{2 l} \sin {\theta} = 0"]


def test_small_swings_have_omega_squared_three_g_over_two_l():
    (bottom,) = [e for e in derivation("physical-pendulum").reduction.equilibria if e.position == 0]
    # ω² = M g (l/2) / I_pivot with I_pivot = M l²/3: a simple pendulum of length 2l/3
    assert bottom.stable and sp.simplify(bottom.omega_squared - 3 * g / (2 * length)) == 0
