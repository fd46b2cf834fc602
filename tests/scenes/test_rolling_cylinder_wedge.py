"""A uniform solid cylinder rolling without slipping down a wedge that slides on a frictionless floor (issue 42):
declared as a rigid body on a moving support, its derivation checked against SymPy's own rigid-body mechanics
(``sympy.physics.mechanics``: a ``RigidBody`` and ``LagrangesMethod``) and its accelerations against a closed form
worked out by hand with Newton's laws, then compared with the block that slides on the chapter's wedge."""

import pytest
import sympy as sp
from sympy.physics import mechanics as me

from app.service.chapter.derivations import derivation, derivation_document
from tests.scenes.common import S

SCENE = "rolling-cylinder-wedge"
m, M, r, g, alpha = S("m"), S("M"), S("r"), S("g"), S("alpha")


def _steps():
    return {s["key"]: s for s in derivation_document(SCENE)["steps"]}


def _sympy_mechanics():
    """The same system built with sympy.physics.mechanics: (T, the accelerations (Ẍ, s̈), X, s as functions)."""
    X, s = me.dynamicsymbols("X s")
    Xd, sd = me.dynamicsymbols("X s", 1)
    N = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(N, 0)
    # the wedge, a particle of mass M at its top corner, moving along the floor
    corner = origin.locatenew("corner", X * N.x)
    corner.set_vel(N, Xd * N.x)
    wedge = me.Particle("wedge", corner, M)
    # the cylinder's centre: s down the slope (cos α, −sin α) and r out along its normal (sin α, cos α)
    centre = corner.locatenew(
        "centre", (s * sp.cos(alpha) + r * sp.sin(alpha)) * N.x + (r * sp.cos(alpha) - s * sp.sin(alpha)) * N.z
    )
    centre.set_vel(N, centre.pos_from(origin).dt(N))
    # rolling without slipping down the slope, to the right: the cylinder turns clockwise about y by s/r
    B = N.orientnew("B", "Axis", (-s / r, N.y))
    cylinder = me.RigidBody("cylinder", centre, B, m, (me.inertia(B, 0, m * r**2 / 2, 0), centre))
    cylinder.potential_energy = m * g * centre.pos_from(origin).dot(N.z)
    wedge.potential_energy = 0
    L = me.Lagrangian(N, wedge, cylinder)
    T = me.kinetic_energy(N, wedge, cylinder)
    method = me.LagrangesMethod(L, [X, s])
    method.form_lagranges_equations()
    solved = method.rhs()
    return T, (solved[2], solved[3]), (X, s, Xd, sd)


def _as_engine(expr, d, functions):
    X, s, Xd, sd = functions
    q, qd = d.table.q, d.table.qd
    return expr.subs({Xd: qd[0], sd: qd[1]}).subs({X: q[0], s: q[1]})


@pytest.mark.slow
def test_t_and_the_accelerations_are_those_of_sympy_mechanics():
    d = derivation(SCENE)
    T, (Xdd, sdd), functions = _sympy_mechanics()
    names = {p.name: p for p in d.table.params}
    ours = {m: names["m"], M: names["M"], r: names["r"], g: names["g"], alpha: names["alpha"]}
    assert sp.simplify(_as_engine(T, d, functions).xreplace(ours) - d.mechanics.T) == 0
    for engine, theirs in zip(d.equations.accelerations, (Xdd, sdd), strict=True):
        assert sp.simplify(_as_engine(theirs, d, functions).xreplace(ours) - engine) == 0


def test_the_accelerations_equal_the_closed_form_worked_out_by_hand():
    # Newton, in the wedge's frame, with f the friction up the slope and N the normal push:
    #   along the slope  m (s̈ + Ẍ cos α) = m g sin α − f,   turning  ½ m r² (s̈/r) = f r,  so f = ½ m s̈;
    #   horizontally, the whole system feels no force: (M + m) Ẍ + m s̈ cos α = 0.
    # Hence (3/2) s̈ − m s̈ cos² α/(M + m) = g sin α:
    #   s̈ = 2 (M + m) g sin α/(3M + m + 2m sin² α),   Ẍ = −2 m g sin α cos α/(3M + m + 2m sin² α)
    d = derivation(SCENE)
    names = {p.name: p for p in d.table.params}
    mm, MM, gg, aa = names["m"], names["M"], names["g"], names["alpha"]
    denominator = 3 * MM + mm + 2 * mm * sp.sin(aa) ** 2
    Xdd, sdd = d.equations.accelerations
    assert sp.simplify(sdd - 2 * (MM + mm) * gg * sp.sin(aa) / denominator) == 0
    assert sp.simplify(Xdd + 2 * mm * gg * sp.sin(aa) * sp.cos(aa) / denominator) == 0


def test_the_cylinder_rolls_down_slower_than_the_block_slides_and_pushes_the_wedge_back_less():
    rolling, sliding = derivation(SCENE), derivation("movable-incline")
    names = {p.name: p for p in rolling.table.params}
    Xdd, sdd = rolling.equations.accelerations
    block_X, block_D = (
        a.xreplace({p: names[p.name] for p in sliding.table.params}) for a in sliding.equations.accelerations
    )
    # the cylinder's denominator is the block's, M + m sin² α, with (M + m)/2 added by its turning
    assert (
        sp.simplify(
            block_D / sdd
            - 1
            - (names["M"] + names["m"]) / (2 * (names["M"] + names["m"] * sp.sin(names["alpha"]) ** 2))
        )
        == 0
    )
    assert sp.simplify(Xdd / sdd - block_X / block_D) == 0
    # with the wedge held fixed (M → ∞) the cylinder rolls at 2g sin α/3, the block at g sin α
    assert sp.simplify(sp.limit(sdd, names["M"], sp.oo) - 2 * names["g"] * sp.sin(names["alpha"]) / 3) == 0


def test_t_is_the_centres_motion_plus_the_turning_about_the_centre():
    steps = _steps()
    assert r"I_{\mathrm{cm}} &= \frac{m r^{2}}{2}" in steps["bodies"]["latex"]
    assert (
        r"T_{\mathrm{cylinder}} &= \tfrac{1}{2} m v_{\mathrm{cm}}^2 + \tfrac{1}{2} I_{\mathrm{cm}} "
        r"\left(\frac{\dot{s}}{r}\right)^{2} = \tfrac{1}{2} m \left(\dot{X}^{2} + \dot{s}^{2} + 2 \dot{X} \dot{s} "
        r"\cos {\alpha}\right) + \frac{1}{4} m \dot{s}^{2}"
    ) in steps["kinetic"]["latex"]


def test_the_accelerations_and_the_conserved_momentum_as_a_textbook_prints_them():
    steps = _steps()
    assert steps["accelerations"]["latex"] == (
        r"\begin{aligned}\ddot{X} &= - \frac{2 m g \sin {\alpha} \cos {\alpha}}{3 M + m + 2 m \sin^{2} {\alpha}} \\ "
        r"\ddot{s} &= \frac{2 \left(M + m\right) g \sin {\alpha}}{3 M + m + 2 m \sin^{2} {\alpha}}\end{aligned}"
    )
    assert steps["cyclic"]["latex"] == (
        r"\frac{\partial L}{\partial X} = 0 \;\Rightarrow\; p_{X} = \left(M + m\right) \dot{X} + m \dot{s} \cos {\alpha}"
        r" = \text{const}"
    )


@pytest.mark.slow
def test_the_cylinder_never_leaves_the_slope():
    # the slope's push N along its outward normal n = (sin α, cos α): m a_cm · n = N − m g cos α, and
    # a_cm = (Ẍ + s̈ cos α, −s̈ sin α) gives a_cm · n = Ẍ sin α, so N = m (g cos α + Ẍ sin α)
    d = derivation(SCENE)
    names = {p.name: p for p in d.table.params}
    mm, MM, gg, aa = names["m"], names["M"], names["g"], names["alpha"]
    Xdd, _ = d.equations.accelerations
    normal = sp.factor(sp.simplify(mm * (gg * sp.cos(aa) + Xdd * sp.sin(aa))))
    # N = m g cos α (3M + m)/(3M + m + 2m sin² α): positive for every mass and every angle below π/2
    assert sp.simplify(normal - mm * gg * sp.cos(aa) * (3 * MM + mm) / (3 * MM + mm + 2 * mm * sp.sin(aa) ** 2)) == 0


def test_the_results_show_the_comparison_with_a_block_and_with_a_fixed_wedge():
    # review prof-q 10: the statement asks for the comparison with a block; the Results show it first, the block's
    # accelerations read from the chapter's own sliding wedge (D along the slope, as s is)
    step = _steps()["comparison"]
    rolled, slid, fixed = (sp.sympify(x, locals={"M": M, "m": m, "g": g, "alpha": alpha}) for x in
                           sp.sstr(step["sympy"]).strip("[]").split(", ")[2:5])  # fmt: skip
    block = derivation("movable-incline").equations.accelerations
    names = {s.name: s for s in (*block[0].free_symbols, *block[1].free_symbols)}
    assert sp.simplify(slid - block[1].xreplace({names[n]: S(n) for n in ("M", "m", "g", "alpha")})) == 0
    assert sp.simplify(rolled - derivation(SCENE).equations.accelerations[1]) == 0
    assert sp.simplify(fixed - sp.limit(rolled, M, sp.oo)) == 0
    assert r"\ddot{s}_{\text{sliding}}" in step["latex"] and r"\ddot{s}_{M \to \infty}" in step["latex"]
    assert "What the statement asks" in step["explanation"]
    assert derivation_document(SCENE)["scene"]["answers"] == ["comparison"]
    # the garbled sentence of the accelerations' reason (review prof-q 10)
    assert "has the same numerator over M + m sin² α alone" in _steps()["accelerations"]["explanation"]


def test_that_there_is_no_equilibrium_is_said_once():
    # review prof-q 12: U_eff′ ≠ 0 with p_X held and ∂U/∂s ≠ 0 are one fact; the Equilibria step says it
    steps = derivation_document(SCENE)["steps"]
    assert sum(s["latex"].count(r"\text{no equilibrium}") for s in steps) == 1
    assert "reduced-equilibria" not in [s["key"] for s in steps]


def test_the_rates_from_the_momenta_print_the_determinant_as_h_does():
    # review prof-q 8: one form of det ℳ on the page, over whole numbers (never 3M/2 + m/2 + m sin² α)
    steps = _steps()
    shown = r"3 M + m + 2 m \sin^{2} {\alpha}"
    for key in ("legendre", "hamilton-equations", "hamiltonian-pq", "accelerations"):
        assert shown in steps[key]["latex"], (key, steps[key]["latex"])
        assert "M / 2" not in steps[key]["latex"] and "m / 2" not in steps[key]["latex"], key
