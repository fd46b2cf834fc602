"""The multipliers derived from the Cartesian Lagrangian with the constraints agree with the engine's."""

import random
import re

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.display.names import latex
from app.engine.document.multipliers import derived_multipliers
from app.engine.document.notation import cartesian_names
from app.engine.equations.constraints import cartesian_symbols
from app.scenes import SCENES
from app.service.chapter.derivations import derivation_document

CONSTRAINED = sorted(sid for sid, s in SCENES.items() if s.system.constraints)
DERIVATION = ["constraints", "multiplier-lagrangian", "multiplier-equation", "multiplier", "constraint-forces"]


def test_the_constrained_scenes_are_the_chapters_seven_and_the_damped_pendulum():
    assert CONSTRAINED == sorted(
        ["simple-pendulum", "damped-pendulum", "helix-bead", "incline-block", "spherical-pendulum", "pulley",
         "movable-incline", "rotating-parabola"]
    )  # fmt: skip


@pytest.mark.slow
@pytest.mark.parametrize("scene_id", CONSTRAINED)
def test_the_derived_multipliers_equal_the_engines(scene_id):
    d = derive(SCENES[scene_id].system)
    forces = d.constraint_forces
    derived = derived_multipliers(d, forces)
    assert len(derived.solved) == len(forces)
    symbols = sorted(set().union(*(f.multiplier.free_symbols for f in forces), *(e.free_symbols for e in derived.solved)), key=str)
    rng = random.Random(40)
    for _ in range(3):
        point = {s: sp.Float(rng.uniform(0.4, 1.3)) for s in symbols}
        for mine, engine in zip(derived.solved, forces, strict=True):
            a, b = float(mine.xreplace(point)), float(engine.multiplier.xreplace(point))
            assert a == pytest.approx(b, rel=1e-9, abs=1e-12), scene_id


@pytest.mark.parametrize("scene_id", CONSTRAINED)
def test_the_page_derives_the_multiplier_before_the_force(scene_id):
    steps = derivation_document(scene_id)["steps"]
    keys = [s["key"] for s in steps]
    start = keys.index("constraints")
    assert keys[start : start + len(DERIVATION)] == DERIVATION
    # the rows without the alignment marks
    shown = {s["key"]: s["latex"].replace("&", "") for s in steps}
    assert shown["multiplier-lagrangian"].removeprefix(r"\begin{aligned}").startswith("L' = ")
    assert r"\lambda_{1} \left(" in shown["multiplier-lagrangian"] or r"\lambda_{1} z" in shown["multiplier-lagrangian"]
    assert r"\ddot{\mathcal{C}}_{1}" in shown["multiplier-equation"]
    assert shown["multiplier"].removeprefix(r"\begin{aligned}").startswith(r"\lambda_{1} = ")
    # the force step no longer states λ: it was solved for in the step before
    assert r"\lambda_{1} =" not in shown["constraint-forces"]


def test_the_pendulum_multiplier_is_derived_from_newtons_law_on_the_circle():
    shown = {s["key"]: s["latex"] for s in derivation_document("simple-pendulum")["steps"]}
    assert shown["constraints"] == r"\mathcal{C}_{1} = R^{2} - x^{2} - \left(z - R\right)^{2} = 0"
    assert r"m \ddot{x} &= - 2 \lambda_{1} x" in shown["multiplier-lagrangian"]
    assert shown["multiplier"] == r"\lambda_{1} = \frac{m}{2 R} \left(R \dot{\theta}^{2} + g \cos {\theta}\right)"


def test_the_pulley_says_lambda_is_the_tension():
    shown = {s["key"]: s for s in derivation_document("pulley")["steps"]}
    assert "λ itself is the tension" in shown["constraint-forces"]["explanation"]
    assert "λ times ∂𝒞/∂z₁" not in shown["constraint-forces"]["explanation"]
    assert r"\left(\frac{4}{M} + \frac{1}{m_{1}} + \frac{1}{m_{2}}\right) \lambda_{1} &= 4 g" in shown["multiplier-equation"]["latex"]


@pytest.mark.parametrize(("scene_id", "units"), [
    ("simple-pendulum", {"𝒞₁": "m²", "λ₁": "N/m", "L′": "J"}),
    ("pulley", {"𝒞₁": "m", "λ₁": "N"}),
    ("helix-bead", {"𝒞₁": "m²", "λ₁": "N/m", "𝒞₂": "m", "λ₂": "N"}),
])  # fmt: skip
def test_the_symbols_table_gives_each_multiplier_its_unit(scene_id, units):
    rows = {r["unicode"]: r for r in derivation_document(scene_id)["notation"]}
    assert {name: rows[name]["unit"] for name in units} == units
    # the generic letters say how their unit follows, never an empty cell
    assert rows["λ"]["unit"] and rows["𝒞"]["unit"]


@pytest.mark.slow
def test_the_cartesian_names_never_print_as_a_coordinate_of_the_system():
    """prof-h 2: the pulley's coordinates are the heights y₁, y₂, and its Lagrangian with multipliers printed
    ½ m₁ ẏ₁² for the first body's Cartesian y: one letter, two quantities. There the bodies' Cartesian
    coordinates are ξ, η, ζ; elsewhere x, y, z."""
    from app.engine.derivation.derive import derive
    from app.engine.document.report import Printer
    from app.engine.document.report_members import constraint_steps
    from app.scenes import SCENES

    def steps(scene):
        d = derive(SCENES[scene].system)
        return constraint_steps(d, d.constraint_forces, Printer(d.table.latex_names()))

    pulley = " ".join(str(s["latex"]) for s in steps("pulley")[:2])
    assert r"\dot{y}_{1}" not in pulley and r"\dot{\eta}_{1}" in pulley and r"\zeta_{1}" in pulley, pulley
    assert "ξᵢ, ηᵢ, ζᵢ" in steps("pulley")[0]["explanation"]
    pendulum = " ".join(str(s["latex"]) for s in steps("simple-pendulum")[:2])
    assert r"\dot{x}" in pendulum and r"\xi" not in pendulum


def _served(scene_id: str) -> dict[str, str]:
    return {s["key"]: s["latex"] for s in derivation_document(scene_id)["steps"] if s["key"] in DERIVATION}


def test_the_multiplier_steps_print_their_expressions_as_a_textbook_does():
    # issue 40: a number common to a bracket's terms before it, 2λ₁(R − z), never λ₁(2R − 2z); the perfect
    # square of the constraint kept as one, x² + (z − R)²; a right side's sign taken into its bracket
    pendulum = _served("simple-pendulum")
    assert r"m \ddot{z} &= 2 \lambda_{1} \left(R - z\right) - m g" in pendulum["multiplier-lagrangian"]
    # prof-o F6: each equation for λ divided through by the number its two sides share (2/m, not 4/m and a 2)
    assert (
        r"\frac{2}{m} \left(x^{2} + \left(z - R\right)^{2}\right) \lambda_{1} &= "
        r"\dot{x}^{2} + \dot{z}^{2} - g z + g R"
    ) in pendulum["multiplier-equation"]
    assert r"\frac{2 R^{2}}{m} \lambda_{1} &= R \left(R \dot{\theta}^{2} + g \cos {\theta}\right)" in pendulum["multiplier-equation"]
    assert r"\lambda_{1} = \frac{m}{2 R} \left(R \dot{\theta}^{2} + g \cos {\theta}\right)" == pendulum["multiplier"]
    # a coefficient 1/m puts the multiplier over the bar: λ₁/m = g cos α, and the force is m g cos α
    incline = _served("incline-block")
    assert incline["multiplier-equation"].endswith(r"\\ \frac{\lambda_{1}}{m} &= g \cos {\alpha}\end{aligned}")
    assert incline["multiplier"] == r"\lambda_{1} = m g \cos {\alpha}"
    wedge = _served("movable-incline")["multiplier-equation"]
    assert r"-\frac{\cos {\alpha}}{M} \lambda_{1} + \frac{\lambda_{2}}{M} &= g" in wedge
    # the helix's coefficient of λ₂: its numerator collected, 1 + α²(ξ cos αζ + η sin αζ)², and the common α
    # of a bracket before it in Newton's law
    helix = _served("helix-bead")
    assert (
        r"\frac{1 + \alpha^{2} \left(\xi \cos {\alpha \zeta} + \eta \sin {\alpha \zeta}\right)^{2}}{m} \lambda_{2}"
        in helix["multiplier-equation"]
    )
    assert (
        r"m \ddot{\zeta} &= \alpha \lambda_{2} \left(\xi \cos {\alpha \zeta} + \eta \sin {\alpha \zeta}\right) - m g"
        in helix["multiplier-lagrangian"]
    )
    # a term's own sign is never taken out of a whole sum: −2λ₁η − λ₂ cos αζ, not −(2λ₁η + λ₂ cos αζ)
    assert r"m \ddot{\eta} &= - 2 \lambda_{1} \eta - \lambda_{2} \cos {\alpha \zeta}" in helix["multiplier-lagrangian"]


def _multiplier_equation(scene_id):
    return next(s for s in derivation_document(scene_id)["steps"] if s["key"] == "multiplier-equation")


def test_the_helix_says_its_normals_are_perpendicular_and_decouples_the_multipliers():
    """prof-m 2: the helix said its normals were "not perpendicular in general, so … coupled", over a system whose
    cross coefficient −(2/m)(ξ sin αζ − η cos αζ) is −(2/m)𝒞₂, zero on the wire. The sentence follows the engine's
    cross coefficient, which is shown vanishing, and each λ has its own equation."""
    step = _multiplier_equation("helix-bead")
    text, rows = step["explanation"], step["latex"].split(r" \\ ")
    assert "not perpendicular" not in text and "coupled" not in text
    assert "perpendicular here" in text and "each λ comes from its own equation" in text
    assert any(r"= - \frac{2}{m}\,\mathcal{C}_{2} = 0" in r for r in rows)
    lam1 = next(r for r in rows if r"\lambda_{1}" in r)
    lam2 = next(r for r in rows if r"\lambda_{2}" in r)
    assert r"\lambda_{2}" not in lam1 and r"\lambda_{1}" not in lam2
    # the long right side is broken across lines as every long row is (a continuation line follows it)
    assert rows[rows.index(lam2) + 1].startswith(r"&\quad ")


def test_the_wedge_says_its_multipliers_are_coupled():
    step = _multiplier_equation("movable-incline")
    assert "not perpendicular here, so the equations for the multipliers are coupled" in step["explanation"]
    rows = step["latex"].split(r" \\ ")
    assert any(r"\lambda_{1}" in r and r"\lambda_{2}" in r for r in rows)


# a Cartesian letter as the prose writes it: x, y or z, any dots (combining marks), then a subscript digit
_PROSE_CARTESIAN = re.compile("([xyz])[\u0307\u0308]*([₀₁₂₃₄₅₆₇₈₉])")


@pytest.mark.parametrize("scene_id", CONSTRAINED)
def test_the_constraint_steps_prose_uses_the_cartesian_letters_the_page_prints(scene_id):
    """prof-n 4: the pulley announced ξᵢ, ηᵢ, ζᵢ and then wrote ∂𝒞/∂z₃ = 2 and z̈₁ + z̈₂ + 2z̈₃ = 0. Every body's
    component the page renames (notation.cartesian_names) never appears under its old letter in those steps' words."""
    d = derive(SCENES[scene_id].system)
    every = [s.name for triple in cartesian_symbols(len(d.system.particles)) for s in triple]
    printed = cartesian_names(every, {latex(s.name) for s in (*d.table.q, *d.table.params)})
    # a renamed letter that is also the system's own coordinate (the pulley's y₁) may be written: it means that
    own = {s.name for s in (*d.table.q, *d.table.params)}
    renamed = {name for name, shown in printed.items() if shown != name and name not in own}
    subscripts = "₀₁₂₃₄₅₆₇₈₉"
    for step in derivation_document(scene_id)["steps"]:
        if step["key"] not in DERIVATION:
            continue
        for letter, sub in _PROSE_CARTESIAN.findall(step["explanation"] or ""):
            assert letter + str(subscripts.index(sub)) not in renamed, (scene_id, step["key"], step["explanation"])


def test_each_group_of_rows_for_the_multipliers_is_said_in_words():
    """prof-n 3: the helix printed five bare lines. Each group has its words: each constraint differentiated twice,
    the cross coefficient that vanishes, then the equation left for each λ."""
    rows = _multiplier_equation("helix-bead")["latex"].split(r" \\ ")
    said = [r for r in rows if r"\text{" in r]
    assert [r.split(r"\text{", 1)[1] for r in said] == [
        "differentiating each constraint twice:}",
        "the cross coefficient, zero here:}",
        r"so, for each }\lambda\text{ alone:}",
        r"on the path, }{\xi=R \cos {\alpha z}},\quad {\eta=R \sin {\alpha z}},\quad {\zeta=z}\text{:}",
    ]
    # the words stand before what they say: the 𝒞̈ rows, the vanishing coefficient, the λ rows
    assert r"\ddot{\mathcal{C}}_{1}" in rows[rows.index(said[0]) + 1]
    assert r"\mathcal{C}_{2} = 0" in rows[rows.index(said[1]) + 1]
    assert r"\lambda_{1}" in rows[rows.index(said[2]) + 1]
    wedge = _multiplier_equation("movable-incline")["latex"]
    assert r"\text{so, for the multipliers together:}" in wedge


def test_the_helix_puts_its_equations_for_the_multipliers_on_the_path():
    """prof-n 3: the helix ended its step on the Cartesian equations for λ₁ and λ₂, five lines a student cannot
    follow to the solved step. The same equations follow with the positions on the wire written in, each side in
    its short form: (2R²/m) λ₁ = α²R²ż² and ((1 + α²R²)/m) λ₂ = gαR, from which each λ is one division."""
    rows = _multiplier_equation("helix-bead")["latex"].removesuffix(r"\end{aligned}").split(r" \\ ")
    words = r"&\text{on the path, }{\xi=R \cos {\alpha z}},\quad {\eta=R \sin {\alpha z}},\quad {\zeta=z}\text{:}"
    assert rows[-3:] == [
        words,
        r"\frac{2 R^{2}}{m} \lambda_{1} &= \alpha^{2} R^{2} \dot{z}^{2}",
        r"\frac{1 + \alpha^{2} R^{2}}{m} \lambda_{2} &= g \alpha R",
    ]
    wire = _multiplier_equation("rotating-parabola")["latex"].removesuffix(r"\end{aligned}").split(r" \\ ")
    assert wire[-3:] == [
        r"&\text{on the path, }{x=\rho \cos {\omega t}},\quad {y=\rho \sin {\omega t}}\text{:}",
        r"\frac{1 + 4 \alpha^{2} \rho^{2}}{m} \lambda_{1} &= 2 \alpha \dot{\rho}^{2} + 2 \alpha \omega^{2} \rho^{2} + g",
        r"\frac{\lambda_{2}}{m} &= 2 \omega \dot{\rho}",
    ]
    # the pendulum's height as its Positions step prints it, R(1 − cos θ)
    pendulum = _multiplier_equation("simple-pendulum")["latex"]
    assert r"\text{on the path, }{x=R \sin {\theta}},\quad {z=R \left(1 - \cos {\theta}\right)}\text{:}" in pendulum
    # the words say why, after the scene's own reason for the step
    said = _multiplier_equation("helix-bead")["explanation"]
    assert said.startswith("The cylinder's normal") and "dividing by its coefficient gives λ" in said
    # the pulley's and the wedge's equations hold no position: nothing to put on the path
    for scene_id in ("pulley", "movable-incline"):
        step = _multiplier_equation(scene_id)
        assert "on the path" not in step["latex"] and "On the path" not in step["explanation"]


@pytest.mark.slow
@pytest.mark.parametrize("scene_id", CONSTRAINED)
def test_the_equations_on_the_path_give_the_solved_multipliers(scene_id):
    """Each equation on the path, Σ_b coefficient λ_b = right side, holds with the solved λ's put in: its right
    side is the solved λ times its coefficient."""
    from app.engine.document.report import Printer
    from app.engine.document.report_members import _cartesian_printer, on_path_equations

    d = derive(SCENES[scene_id].system)
    m = derived_multipliers(d, d.constraint_forces)
    pr = Printer(d.table.latex_names())
    lam = [f"\\lambda_{{{a}}}" for a in range(1, len(m.multipliers) + 1)]
    rows, equations = on_path_equations(m, _cartesian_printer(m, pr), pr, lam)
    if scene_id in ("pulley", "movable-incline", "incline-block"):
        assert rows == [] and equations == []
        return
    assert len(equations) == len(m.multipliers) and len(rows) == len(equations) + 1
    solved = dict(zip(m.multipliers, m.solved, strict=True))
    # (a Cartesian letter that is also a coordinate, the helix's z, stays)
    cartesian = (set(m.positions) | set(m.velocities)) - {*d.table.q, *d.table.qd}
    for equation in equations:
        # no Cartesian letter is left: the equation is in the coordinates
        assert not equation.free_symbols & cartesian, (scene_id, equation)
        assert sp.simplify(equation.lhs.xreplace(solved) - equation.rhs) == 0, (scene_id, equation)


def test_positions_too_wide_for_one_line_stand_one_a_line(monkeypatch):
    """Where the words and the positions would be wider than a page, the words stand alone and each position has
    its own row, aligned at its = with the equations."""
    from app.engine.document import report_members
    from app.engine.document.report import Printer

    d = derive(SCENES["helix-bead"].system)
    m = derived_multipliers(d, d.constraint_forces)
    pr = Printer(d.table.latex_names())
    lam = [r"\lambda_{1}", r"\lambda_{2}"]
    monkeypatch.setattr(report_members, "LIMIT", 10.0)
    rows, _ = report_members.on_path_equations(m, report_members._cartesian_printer(m, pr), pr, lam)
    assert rows[:4] == [r"\text{on the path:}", r"\xi = R \cos {\alpha z}", r"\eta = R \sin {\alpha z}", r"\zeta = z"]
