"""Each erratum's correct formula is what the engine derives (parsed from the text itself)."""

import re

import pytest
import sympy as sp

from app.engine.derivation.derive import substitute_cyclic
from app.scenes import SCENES
from app.service.chapter.derivations import derivation
from tests.reference import numerically_equal, random_point
from tests.scenes.common import S, read, transformed

ERRATA = [(sid, i) for sid, s in sorted(SCENES.items()) for i in range(len(s.errata))]


def engine_result(scene_id: str, check: str):
    """The engine's value that an erratum's check names."""
    d = derivation(scene_id)
    table, eqs, red = d.table, d.equations, d.reduction
    kind, *args = check.split(":")
    index = table.names.index(args[0]) if args and args[0] in table.names else None
    if kind == "acceleration":
        return eqs.accelerations[index]
    if kind == "linear-acceleration":
        # the acceleration linearised about rest at q = 0: what small swings obey
        q, qd = table.q[index], table.qd[index]
        acc = eqs.accelerations[index]
        return sp.diff(acc, q).xreplace({q: 0, qd: 0}) * q
    if kind == "reduced-acceleration":
        return substitute_cyclic(eqs.accelerations[index], red)
    if kind == "reduced-force":
        return red.effective_mass * substitute_cyclic(eqs.accelerations[index], red)
    if kind == "dL/dq":
        return eqs.dL_dq[index]
    if kind == "potential-force":
        return -sp.diff(d.mechanics.U, table.q[index])
    if kind == "equation":
        return eqs.residuals[index]
    if kind == "speed-squared":
        return d.mechanics.speeds_squared[int(args[0]) - 1]
    if kind == "position":
        r = d.mechanics.positions[int(args[0]) - 1]
        return r if len(args) == 1 else r["xyz".index(args[1])]
    if kind == "point-acceleration":
        c = d.mechanics.positions[int(args[0]) - 1]["xyz".index(args[1])]
        acc = dict(zip(table.qdd, eqs.accelerations, strict=True))
        return table.dt(table.dt(c)).xreplace(acc)
    if kind == "lagrangian":
        return d.mechanics.L
    if kind == "potential":
        return d.mechanics.U
    if kind == "energy-minus-h":
        return d.energetics.energy_minus_h
    if kind == "radial-speed":
        # E = m_eff r_dot^2 / 2 + U_eff (the page's letter for the engine's E_r), solved for r_dot (outgoing branch)
        return sp.sqrt(2 * (S("E") - red.effective_potential) / red.effective_mass)
    if kind == "time-integrand":
        return red.time_integral.function.xreplace({S("E_r"): S("E")})
    if kind == "omega-squared":
        return red.equilibria[int(args[0])].omega_squared
    if kind == "taylor-coefficient":
        # the (q - q0)^2 coefficient of U_eff's Taylor series about the equilibrium
        e = red.equilibria[int(args[0])]
        r = table.q[table.names.index(red.coordinate)]
        return sp.diff(red.effective_potential, r, 2).xreplace({r: e.position}) / 2
    if kind == "transformed-momentum":
        tr = transformed(scene_id)
        new = tr.derivation
        return tr.to_original(new.equations.momenta[new.table.names.index(args[0])])
    raise AssertionError(f"unknown check {check!r}")


def free(*exprs):
    return sorted(set().union(*(sp.sympify(e).free_symbols for e in exprs)), key=str)


@pytest.mark.parametrize(("scene_id", "index"), ERRATA)
def test_erratum_correct_formula_is_the_engines(scene_id, index):
    e = SCENES[scene_id].errata[index]
    assert e.chapter and e.reason and " = " in e.correct
    # the formula after the last '=' is the one compared
    # ±: both branches of a root; the outgoing one is compared
    correct = read(e.correct.rsplit("=", 1)[1].strip().removeprefix("±"))
    ours = engine_result(scene_id, e.check)
    kind = e.check.split(":")[0]
    if kind == "position" and isinstance(ours, tuple):
        assert len(correct) == 3
        for a, c in zip(ours, correct, strict=True):
            assert numerically_equal(a, c, free(a, c)), (a, c)
    elif kind == "potential":
        # a potential is fixed up to a constant
        for q in derivation(scene_id).table.q:
            assert numerically_equal(sp.diff(ours, q), sp.diff(correct, q), free(ours, correct))
    elif kind == "equation":
        # an equation = 0 is fixed up to a constant factor
        points = free(ours, correct)
        ratios = {round(complex(sp.N((ours / correct).xreplace(random_point(points, s)))).real, 9) for s in range(3)}
        assert len(ratios) == 1 and ratios != {0.0}, ratios
    elif kind == "radial-speed":
        assert numerically_equal(ours**2, correct**2, free(ours, correct))
    else:
        assert numerically_equal(ours, correct, free(ours, correct)), (ours, correct)


def test_every_scene_with_chapter_formulas_has_errata():
    # the chapter states formulas for these examples, and each has mistakes
    with_errata = {sid for sid, s in SCENES.items() if s.errata}
    assert with_errata == {
        "simple-pendulum",
        "incline-block",
        "tabletop-spring",
        "spherical-pendulum",
        "rail-two-body",
        "pulley",
        "movable-incline",
        "rotating-parabola",
    }


@pytest.mark.parametrize(
    ("scene_id", "check", "chapter"),
    [
        # the chapter's formulas, re-typed: each must differ from the engine's result
        ("spherical-pendulum", "acceleration:theta", "sin(theta)*cos(theta)*phi_dot**2 - g*sin(theta)/R"),
        ("pulley", "acceleration:y1", "-g - 4*m2*g/(m1 + m2 + 4*m1*m2/M)"),
        ("movable-incline", "point-acceleration:2:z", "-(M + m)*g*sin(alpha)*cos(alpha)/(M + m*sin(alpha)**2)"),
        ("tabletop-spring", "omega-squared:0", "4*k"),
        ("tabletop-spring", "time-integrand", "sqrt(2*E_r/m - p_theta**2/(2*m*r**2) - k*r**2/2)"),
    ],
)
def test_the_chapters_versions_are_rejected(scene_id, check, chapter):
    ours = engine_result(scene_id, check)
    wrong = read(chapter)
    assert not numerically_equal(ours, wrong, free(ours, wrong))


# names that belong in mathematics, never left in a quotation as words
MATH_WORDS = {"partial", "sqrt", "dot", "ddot", "frac", "theta", "omega", "alpha", "phi", "rho", "tau", "kappa"}


def _text_and_math(tex: str) -> tuple[list[str], str]:
    """The \\text{…} runs of a formula, and the rest with every command taken out."""
    texts = re.findall(r"\\text\{([^{}]*)\}", tex)
    rest = re.sub(r"\\text\{[^{}]*\}|\\(?:begin|end)\{\w+\}", " ", tex)
    return texts, re.sub(r"\\[A-Za-z]+", " ", rest)


@pytest.mark.parametrize("scene_id", sorted(sid for sid, s in SCENES.items() if s.errata))
def test_every_errata_quotation_is_typeset_mathematics(client, scene_id):
    """What the chapter writes is quoted as mathematics (issue 40): ∂ as ∂, not the word "partial" in brackets;
    every name a symbol of its own (m₄ m₁ m₂, never "m4m1m2" run together); words only in prose runs."""
    errata = client.get(f"/api/scenes/{scene_id}/derivation").json()["errata"]
    assert errata
    for e in errata:
        for tex in (e["chapter_latex"], e["correct_latex"]):
            texts, math = _text_and_math(tex)
            for run in texts:
                assert not set(re.findall(r"[A-Za-z]+", run)) & MATH_WORDS, (scene_id, run)
            # outside prose, letters come one at a time (a symbol, with its subscript), or as a differential dx
            words = [w for w in re.findall(r"[A-Za-z]{2,}", math) if not re.fullmatch(r"d[A-Za-z]", w)]
            assert words == [], (scene_id, tex)
            # a digit straight after a letter is a name run together (m4m1m2): an index is a subscript, m_{4}
            assert not re.search(r"[A-Za-z]\d", math), (scene_id, tex)


def test_the_chapters_garbled_formulas_are_quoted_as_printed(client):
    """The chapter's misprints are quoted legibly, and the reason says what is wrong with them."""
    rail = client.get("/api/scenes/rail-two-body/derivation").json()["errata"]
    assert r"\partial /\partial x_{1}" in rail[0]["chapter_latex"]
    assert r"\dot{m}_{1}" in rail[1]["chapter_latex"] and "dot on the mass m₁" in rail[1]["reason"]
    pulley = client.get("/api/scenes/pulley/derivation").json()["errata"]
    assert all(r"m_{4}  m_{1}  m_{2}" in e["chapter_latex"] and r"\frac{" in e["chapter_latex"] for e in pulley)
    assert "m₄" in pulley[0]["reason"]
    parabola = client.get("/api/scenes/rotating-parabola/derivation").json()["errata"][0]
    assert r"\partial r /\partial t" in parabola["chapter_latex"]
    pendulum = client.get("/api/scenes/simple-pendulum/derivation").json()["errata"]
    # the torque is Γ (τ is the action panel's duration) and a partial derivative
    assert pendulum[1]["correct_latex"].startswith(r"\Gamma = \frac{\partial L}{\partial \theta}")
    # the correction is the small-swing equation, not the chapter's own equation again
    # prof-k 8: the linear equation holds only for small swings, so it is printed with ≈ and its condition
    assert pendulum[2]["correct_latex"] == r"\ddot{\theta} \approx - \frac{g}{R} \theta, \quad \text{for } |\theta| \ll 1"


def test_the_tabletop_radial_speed_has_both_signs_and_the_pages_letter(client):
    # prof-e 19: an undefined E_r and no ± in the "Correct" column, beside a "Why" that writes ±√(2(E − U_eff)/m)
    errata = client.get("/api/scenes/tabletop-spring/derivation").json()["errata"]
    speed, integrand = (e["correct_latex"] for e in errata if e["chapter"].startswith(("r_dot", "t = integral")))
    assert speed.startswith(r"\dot{r} = \pm \sqrt{") and integrand.startswith(r"\frac{dt}{dr} = \pm ")
    assert "E_{r}" not in speed + integrand and "2 E -" in speed.replace("\\left(", "")


@pytest.mark.slow
def test_errata_quote_words_as_words_and_vectors_in_textbook_order(client):
    # prof-e 15: a remark about the chapter's statement typeset in the maths font
    first = client.get("/api/scenes/incline-block/derivation").json()["errata"][0]
    assert first["chapter_words"] is True and first["chapter_latex"] == ""
    page = client.get("/scenes/incline-block").text
    assert '<td data-label="The chapter writes">The statement of the helix bead problem, repeated word for word.</td>' in page
    # prof-e 23: (R sin θ cos φ, R sin θ sin φ, R cos θ), not R sin φ sin θ
    sphere = client.get("/api/scenes/spherical-pendulum/derivation").json()["errata"]
    position = next(e["correct_latex"] for e in sphere if e["correct"].startswith("r = ("))
    assert r"R \sin {\theta} \sin {\varphi}" in position and r"\sin {\varphi} \sin {\theta}" not in position
    # prof-e 7: the torque's reason speaks of the ω the chapter put in (g/R, in s⁻²), not of a √(g/R) it never wrote
    torque = next(e for e in client.get("/api/scenes/simple-pendulum/derivation").json()["errata"] if "tau" in e["chapter"])
    assert "√(g/R)" not in torque["reason"] and "s⁻²" in torque["reason"]
