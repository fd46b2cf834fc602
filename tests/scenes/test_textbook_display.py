"""The chapter scenes' Lagrangians and equations of motion in textbook form, pinned as LaTeX.

The strings were produced by running the display canonicaliser (``app.engine.display.textbook``) and
checked by eye: factors in a reader's order (½ m R² θ̇², m g R (1 − cos θ)), each
Euler–Lagrange equation divided by its acceleration's coefficient where the mass matrix is
diagonal (θ̈ + (g/R) sin θ = 0).  A change of the printer that changes a page shows up here.
"""

import re

import pytest
import sympy as sp

from app.engine.display.names import unicode
from app.engine.display.textbook import unicode_text
from app.engine.document.model import Document
from app.engine.document.report import SCALED_CLAUSE
from app.scenes import SCENES
from app.scenes.reasons import reason
from app.service.chapter.derivations import derivation_document

PINNED = {  # fmt: skip
    "damped-pendulum": (
        "\\frac{1}{2} m R^{2} \\dot{\\theta}^{2} - m g R \\left(1 - \\cos {\\theta}\\right)",
        [
            "\\ddot{\\theta} + \\frac{b}{m R^{2}} \\dot{\\theta} + \\frac{g}{R} \\sin {\\theta} = 0",
        ],
    ),
    "helix-bead": (
        "\\frac{1}{2} m \\left(1 + \\alpha^{2} R^{2}\\right) \\dot{z}^{2} - m g z",
        [
            "\\ddot{z} + \\frac{g}{1 + \\alpha^{2} R^{2}} = 0",
        ],
    ),
    "incline-block": (
        "\\frac{1}{2} m \\dot{X}^{2} - m g X \\sin {\\alpha}",
        [
            "\\ddot{X} + g \\sin {\\alpha} = 0",
        ],
    ),
    "movable-incline": (
        "\\frac{1}{2} m \\dot{D}^{2} + \\frac{1}{2} \\left(M + m\\right) \\dot{X}^{2} + m \\dot{D} \\dot{X} \\cos {\\alpha} + m g D \\sin {\\alpha}",
        [
            "\\left(M + m\\right) \\ddot{X} + m \\ddot{D} \\cos {\\alpha} = 0",
            "\\ddot{D} + \\ddot{X} \\cos {\\alpha} - g \\sin {\\alpha} = 0",
        ],
    ),
    "pulley": (
        "\\frac{1}{8} M \\left(\\dot{y}_{1} + \\dot{y}_{2}\\right)^{2} + \\frac{1}{2} m_{1} \\dot{y}_{1}^{2} + \\frac{1}{2} m_{2} \\dot{y}_{2}^{2} + \\frac{1}{2} M g \\left(y_{1} + y_{2}\\right) - m_{1} g y_{1} - m_{2} g y_{2} + M g c",
        [
            "\\left(m_{1} + \\frac{M}{4}\\right) \\ddot{y}_{1} + \\frac{1}{4} M \\ddot{y}_{2} + m_{1} g - \\frac{M g}{2} = 0",
            "\\left(m_{2} + \\frac{M}{4}\\right) \\ddot{y}_{2} + \\frac{1}{4} M \\ddot{y}_{1} + m_{2} g - \\frac{M g}{2} = 0",
        ],
    ),
    "rail-two-body": (
        "\\frac{1}{2} m_{1} \\dot{x}_{1}^{2} + \\frac{1}{2} m_{2} \\dot{x}_{2}^{2} - \\frac{1}{2} k \\left(x_{2} - x_{1} - l_{0}\\right)^{2}",
        [
            "\\ddot{x}_{1} + \\frac{k}{m_{1}} \\left(x_{1} - x_{2} + l_{0}\\right) = 0",
            "\\ddot{x}_{2} + \\frac{k}{m_{2}} \\left(x_{2} - x_{1} - l_{0}\\right) = 0",
        ],
    ),
    "rotating-parabola": (
        "\\frac{1}{2} m \\dot{\\rho}^{2} + 2 m \\alpha^{2} \\rho^{2} \\dot{\\rho}^{2} + \\frac{1}{2} m \\omega^{2} \\rho^{2} - m g \\alpha \\rho^{2}",
        [
            "\\left(1 + 4 \\alpha^{2} \\rho^{2}\\right) \\ddot{\\rho} + 4 \\alpha^{2} \\rho \\dot{\\rho}^{2} + \\left(2 g \\alpha - \\omega^{2}\\right) \\rho = 0",
        ],
    ),
    "simple-pendulum": (
        "\\frac{1}{2} m R^{2} \\dot{\\theta}^{2} - m g R \\left(1 - \\cos {\\theta}\\right)",
        [
            "\\ddot{\\theta} + \\frac{g}{R} \\sin {\\theta} = 0",
        ],
    ),
    "spherical-pendulum": (
        "\\frac{1}{2} m R^{2} \\left(\\dot{\\theta}^{2} + \\dot{\\varphi}^{2} \\sin^{2} {\\theta}\\right) - m g R \\cos {\\theta}",
        [
            "\\ddot{\\theta} - \\dot{\\varphi}^{2} \\sin {\\theta} \\cos {\\theta} - \\frac{g}{R} \\sin {\\theta} = 0",
            "\\ddot{\\varphi} + \\frac{2 \\dot{\\varphi} \\dot{\\theta} \\cos {\\theta}}{\\sin {\\theta}} = 0",
        ],
    ),
    "tabletop-spring": (
        "\\frac{1}{2} m \\left(\\dot{r}^{2} + r^{2} \\dot{\\theta}^{2}\\right) - \\frac{1}{2} k r^{2}",
        [
            "\\ddot{r} - r \\dot{\\theta}^{2} + \\frac{k}{m} r = 0",
            "\\ddot{\\theta} + \\frac{2 \\dot{r} \\dot{\\theta}}{r} = 0",
        ],
    ),
}

# the chapter's nine scenes, and the damped pendulum: ours (beyond the chapter), but one degree of freedom
# printed by the same rules, so pinned with them
CHAPTER = sorted(sid for sid, s in SCENES.items() if not s.beyond_chapter or sid == "damped-pendulum")


def test_the_scenes_with_reasons_of_their_own_are_the_chapter_and_the_damped_pendulum():
    # and, since prof-g 44 and 51, the coupled oscillators and the double pendulum, whose generic captions went;
    # and the physical pendulum (issue 42), the first rigid body, the cylinder rolling on a sliding wedge and the
    # massive pulley
    beyond = ["coupled-oscillators", "double-pendulum", "physical-pendulum", "rolling-cylinder-wedge", "massive-pulley"]
    assert sorted(sid for sid, s in SCENES.items() if s.reasons) == sorted([*CHAPTER, *beyond])


def test_the_chapter_scenes_and_the_damped_pendulum_are_pinned():
    assert sorted(PINNED) == CHAPTER and len(CHAPTER) == 10
    assert SCENES["damped-pendulum"].beyond_chapter


@pytest.mark.parametrize("scene_id", CHAPTER)
def test_lagrangian_and_equations_in_textbook_form(scene_id):
    doc = derivation_document(scene_id)
    lagrangian, equations = PINNED[scene_id]
    assert doc["lagrangian"]["latex"] == lagrangian
    assert [e["latex"] for e in doc["equations_of_motion"]] == equations
    # the steps show the same forms as the results box
    steps = {s["title"]: s["latex"] for s in doc["steps"]}
    assert steps["Lagrangian"] == f"L = {lagrangian}"
    for row in equations:
        assert row.replace(" = 0", "") in steps["Euler–Lagrange equations"]


@pytest.mark.parametrize("scene_id", [*CHAPTER, "physical-pendulum", "rolling-cylinder-wedge", "massive-pulley"])
def test_every_step_has_a_reason_of_its_own(scene_id):
    doc = derivation_document(scene_id)
    table, kinds = SCENES[scene_id].reasons, set()
    for step in doc["steps"]:
        own = reason(table, step["key"])
        assert own, f"{scene_id}: no reason for the step {step['key']!r} ({step['title']})"
        kind = step["key"].partition(":")[0]
        if step["key"] in table or kind not in kinds:
            # a reason given for a kind of step goes to its first step only (none is printed twice in a row)
            # (a reason's full stop gives way to the clause that says which equations are shown scaled)
            assert step["explanation"].startswith(own) or step["explanation"].startswith(f"{own.rstrip('.')}; {SCALED_CLAUSE}")
        kinds.add(kind)
        keys = [s["key"] for s in doc["steps"]]
        if step["key"] == "equilibria" and "reduced-equilibria" in table and "reduced-equilibria" not in keys:
            # the reduction's equilibria are the system's: said once, in the "Equilibria" step, with which is stable
            assert step["explanation"] == f"{own} {table['reduced-equilibria']}"


def test_reasons_name_only_steps_that_exist():
    for scene_id, table in ((s.id, s.reasons) for s in SCENES.values() if s.reasons):
        doc = derivation_document(scene_id)
        keys = [s["key"] for s in doc["steps"]]
        said = " ".join(s["explanation"] for s in doc["steps"])
        for key, text in table.items():
            exists = any(k == key or k.partition(":")[0] == key for k in keys)
            assert exists or text in said, (scene_id, key)


def test_reasons_differ_between_scenes():
    # the same step is explained differently on different pages
    potentials = {SCENES[s].reasons["potential"] for s in CHAPTER}
    assert len(potentials) == len(CHAPTER)


# ---- running text in the LaTeX's order (issue 40) ----------------------------------------------------------

_TEX_LETTER = re.compile(
    r"\\(dot|ddot)\{\\?([A-Za-z]+)\}(?:_\{(\d+)\})?|\\([A-Za-z]+)(?:_\{(\d+)\})?|([A-Za-z])(?:_\{(\d+)\})?"
)
# LaTeX commands that are no letter of the expression (functions, brackets, spacing)
_NOT_LETTERS = {"sin", "cos", "tan", "left", "right", "sqrt", "frac", "tfrac", "cdot", "log", "exp", "sinh", "cosh",
                "tanh", "operatorname", "mathrm", "arccos", "arcsin", "arctan", "pi"}  # fmt: skip
_GREEK_TEX = {"varphi": "phi"}


def _tex_letters(tex: str) -> list[str]:
    """The letters of a LaTeX form in the order it prints them, each as running text writes it (φ̇, x₁, α)."""
    out = []
    for accent, stem, sub, command, command_sub, letter, letter_sub in _TEX_LETTER.findall(tex):
        if accent:
            out.append(unicode(_GREEK_TEX.get(stem, stem) + sub + ("_dot" if accent == "dot" else "_ddot")))
        elif command and command not in _NOT_LETTERS:
            out.append(unicode(_GREEK_TEX.get(command, command) + command_sub))
        elif letter:
            out.append(unicode(letter + letter_sub))
    return out


def _text_letters(text: str) -> list[str]:
    text = re.sub(r"arccos|arcsin|arctan|sin|cos|tan|log|exp", " ", text).replace("π", "")
    return re.findall(r"[A-Za-zα-ωΑ-Ω][\u0307\u0308]?[₀-₉]*", text)


def _pairs(doc: object, coordinates: list[str]):
    """Every expression of a document with its LaTeX and the coordinates it is written in (a change of
    coordinates has its own)."""
    if isinstance(doc, dict):
        if isinstance(doc.get("sympy"), str) and isinstance(doc.get("latex"), str):
            yield doc, coordinates
        own = doc.get("coordinates") if isinstance(doc.get("coordinates"), list) else coordinates
        for v in doc.values():
            yield from _pairs(v, own)
    elif isinstance(doc, list):
        for v in doc:
            yield from _pairs(v, coordinates)


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_running_text_prints_an_expression_in_the_order_of_its_latex(scene_id):
    # prof-g (issue 40): "cos(zα)" and "2αg − ω²" in sentences and labels where the LaTeX beside them reads
    # cos αz and 2gα − ω²: each served expression without fractions or roots (whose layout differs in one
    # line) has its letters in the same order as running text and as LaTeX, and every running-text form the
    # document serves with its twin is that text
    doc = derivation_document(scene_id)
    checked = 0
    for pair, coordinates in _pairs(doc, doc["coordinates"]):
        if "unicode" in pair:
            assert _text_letters(pair["unicode"]) == _tex_letters(pair["latex"]), pair
        tex = pair["latex"]
        if any(mark in tex for mark in ("\\frac", "\\begin", "\\int", "=", "\\sqrt", "^{1/")):
            continue
        # the names a page gives the coordinates and their rates (what moves is printed after the parameters)
        names = {sp.Symbol(n): n for c in coordinates for n in (c, f"{c}_dot", f"{c}_ddot")}
        local = {n.name: n for n in names} | {p: sp.Symbol(p) for p in doc["parameters"]} | {"t": sp.Symbol("t")}
        text = unicode_text(sp.sympify(pair["sympy"], locals=local), names)
        assert _text_letters(text) == _tex_letters(tex), (text, tex)
        checked += 1
    assert checked >= 1


@pytest.mark.slow
def test_the_conical_motions_frequency_is_printed_in_its_angle_alone():
    """prof-m 5: ω² about the spherical pendulum's cone was printed with p_φ in it, though U_eff′(θ₀) = 0 fixes
    p_φ by θ₀. Derived here from U_eff (θ from the upward vertical): p_φ² = −m²gR³ sin⁴θ₀/cos θ₀, and
    ω² = U_eff″/(mR²) = (g/R)(1 + 3 cos² θ₀)/(−cos θ₀)."""
    m, g, R, th, p = (sp.Symbol(n, positive=True) for n in ("m", "g", "R", "theta0", "p_phi"))
    U_eff = p**2 / (2 * m * R**2 * sp.sin(th) ** 2) + m * g * R * sp.cos(th)
    p2 = sp.solve(sp.diff(U_eff, th), p**2)[0]
    textbook = (g / R) * (1 + 3 * sp.cos(th) ** 2) / (-sp.cos(th))
    assert sp.simplify((sp.diff(U_eff, th, 2) / (m * R**2)).subs(p**2, p2) - textbook) == 0
    step = next(s for s in derivation_document("spherical-pendulum")["steps"] if s["key"] == "reduced-equilibria")
    omega_row = step["latex"].split(r"\\")[-1]
    assert "p_{" not in omega_row and r"\theta_{0}" in omega_row
    assert r"\left(1 + 3 \cos^{2} {\theta_{0}}\right) g}{R \cos {\theta_{0}}}" in omega_row
    served = sp.sympify(step["sympy"], locals={n: sp.Symbol(n, real=True) for n in ("g", "R", "theta0")})[-1]
    assert not served.has(sp.Symbol("p_phi", real=True))
    names = {s.name: s for s in served.free_symbols}
    assert sp.simplify(served - textbook.xreplace({g: names["g"], R: names["R"], th: names["theta0"]})) == 0
    assert "fixes p_φ by θ₀" in step["explanation"]
    # the same value at the defaults as the steady motion's own step (θ₀ and ω² as it prints them)
    doc = derivation_document("spherical-pendulum")
    steady = next(s for s in doc["steps"] if s["key"] == "steady-motion:1")["latex"]
    theta0 = float(re.search(r"\\theta &= ([0-9.]+)", steady).group(1))
    printed = float(re.search(r"\\omega\^2 &= ([0-9.]+)", steady).group(1))
    defaults = {p.name: p.default for p in SCENES["spherical-pendulum"].system.parameters}
    value = served.xreplace({names["g"]: defaults["g"], names["R"]: defaults["R"], names["theta0"]: theta0})
    assert float(value) == pytest.approx(printed, abs=0.06)


@pytest.mark.slow
def test_the_pulleys_middle_mass_has_its_acceleration_typeset_in_results():
    """prof-m 6: the statement asks for the accelerations of all three masses; Ÿ was only in the prose of the
    accelerations step. It is derived from Y = −(y₁ + y₂)/2 − c and typeset in the step and in Results."""
    from app.viz.page_model import _summary

    doc = derivation_document("pulley")
    served = doc["dependent_accelerations"]["Y"]
    names = {n: sp.Symbol(n, real=True) for n in ("g", "M", "m1", "m2")}
    Y_ddot = sp.sympify(served["sympy"], locals=names)
    y1, y2 = (sp.sympify(doc["accelerations"][c]["sympy"], locals=names) for c in ("y1", "y2"))
    # Ÿ = −(ÿ₁ + ÿ₂)/2 from the string's length, and the textbook's [4m₁m₂ − M(m₁ + m₂)] g/[4m₁m₂ + M(m₁ + m₂)]
    g, M, m1, m2 = names.values()
    assert sp.simplify(Y_ddot + (y1 + y2) / 2) == 0
    assert sp.simplify(Y_ddot - (4 * m1 * m2 - M * (m1 + m2)) * g / (4 * m1 * m2 + M * (m1 + m2))) == 0
    row = r"\ddot{Y} = " + served["latex"]
    assert row in _summary(Document.model_validate(doc))["accelerations"]
    step = next(s for s in doc["steps"] if s["key"] == "accelerations")
    assert r"\ddot{Y} &= " + served["latex"] in step["latex"]
    # the letter has its Symbols row, in the unit of the heights it is made of
    row = next(r for r in doc["notation"] if r["latex"] == "Y")
    assert (row["meaning"], row["unit"]) == ("height of the middle mass M, measured upward", "m")


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "physical-pendulum", "damped-pendulum", "double-pendulum"])
def test_no_sentence_writes_an_exponential_as_code(scene_id):
    # issue 40, item 3: "varies as e^(σt)", "grows like exp(√(−ω²) t)" are code; the sentence says it in words
    for step in derivation_document(scene_id)["steps"]:
        for code in ("exp(", "e^(", "e^{"):
            assert code not in step["explanation"], (step["title"], step["explanation"])


def test_a_runaway_says_its_rate_in_closed_form():
    # the physical pendulum standing up runs away at √(3g/(2l)), the rate the row beside the sentence prints
    (step,) = [
        s for s in derivation_document("physical-pendulum")["steps"] if s["title"] == "No oscillation about θ = π"
    ]
    assert "it grows exponentially at the rate √(3g/(2l)) instead of oscillating" in step["explanation"]


def _rows(scene_id: str) -> dict[str, list[str]]:
    """Each step's rows without their alignment marks."""
    steps = derivation_document(scene_id)["steps"]
    return {
        s["key"]: s["latex"].removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}").replace("&", "").split(r" \\ ")
        for s in steps
    }


def test_the_helix_and_the_wire_print_each_inertia_in_one_form():
    """prof-n 6: one factor in one form throughout a derivation, a mass first and then its bracket: the wire printed
    ∂L/∂ρ̇ = mρ̇ + 4mα²ρ²ρ̇, (4mα²ρ² + m) ρ̈ and p_ρ = m ρ̇ (1 + 4α²ρ²) beside 𝓜 = m(1 + 4α²ρ²)."""
    helix = _rows("helix-bead")
    inertia = r"m \left(1 + \alpha^{2} R^{2}\right)"
    assert helix["kinetic"] == [rf"T = \frac{{1}}{{2}} {inertia} \dot{{z}}^{{2}}"]
    assert helix["derivatives:z"][1:] == [
        rf"\frac{{\partial L}}{{\partial \dot{{z}}}} = {inertia} \dot{{z}}",
        rf"\frac{{d}}{{dt}}\left(\frac{{\partial L}}{{\partial \dot{{z}}}}\right) = {inertia} \ddot{{z}}",
    ]
    assert helix["mass-matrix"][0] == rf"\mathcal{{M}} = {inertia}"
    assert helix["momenta"] == [rf"p_{{z}} = {inertia} \dot{{z}}"]
    wire = _rows("rotating-parabola")
    inertia = r"m \left(1 + 4 \alpha^{2} \rho^{2}\right)"
    assert wire["derivatives:rho"][1:] == [
        rf"\frac{{\partial L}}{{\partial \dot{{\rho}}}} = {inertia} \dot{{\rho}}",
        rf"\frac{{d}}{{dt}}\left(\frac{{\partial L}}{{\partial \dot{{\rho}}}}\right) = {inertia} \ddot{{\rho}} "
        r"+ 8 m \alpha^{2} \rho \dot{\rho}^{2}",
    ]
    assert wire["mass-matrix"][0] == rf"\mathcal{{M}} = {inertia}"
    assert wire["momenta"] == [rf"p_{{\rho}} = {inertia} \dot{{\rho}}"]
    assert wire["effective-potential"] == [
        r"U_\text{eff}(\rho) = m \left(g \alpha - \tfrac{1}{2} \omega^{2}\right) \rho^{2}",
        rf"m_\text{{eff}} = {inertia}",
    ]
    assert wire["energy-integral"][0].startswith(rf"h = \frac{{1}}{{2}} {inertia} \dot{{\rho}}^{{2}} + ")


def test_a_momentum_and_its_rate_print_the_mass_matrix_entries():
    """∂L/∂q̇ₖ = Σⱼ 𝓜ₖⱼ q̇ⱼ + …: each coefficient as the mass matrix prints it (the pulley's m₁ + M/4, not
    ¼(M + 4m₁)), and d/dt(m r² θ̇) = m r² θ̈ + 2 m r ṙ θ̇ as a textbook differentiates it."""
    pulley = _rows("pulley")
    assert r"\left(m_{1} + \frac{M}{4}\right) \dot{y}_{1}" in pulley["momenta"][0]
    assert r"\left(m_{1} + \frac{M}{4}\right) \dot{y}_{1}" in pulley["derivatives:y1"][1]
    assert r"\left(m_{1} + \frac{M}{4}\right) \ddot{y}_{1}" in pulley["derivatives:y1"][2]
    assert r"m_{1} + \frac{M}{4}" in pulley["mass-matrix"][0]
    spring = _rows("tabletop-spring")["derivatives:theta"]
    assert spring[2] == r"\frac{d}{dt}\left(\frac{\partial L}{\partial \dot{\theta}}\right) = m r^{2} \ddot{\theta} + 2 m r \dot{r} \dot{\theta}"


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "physical-pendulum", "helix-bead"])
def test_an_effective_potential_that_is_u_prints_in_us_form(scene_id):
    """prof-o F8: with no momentum held and no constraint moving, U_eff is U, printed as the potential's step prints
    it in the step and in the results alike: the simple pendulum's U_eff(θ) = mgR(1 − cos θ), never
    −mgR cos θ + mgR beside U = mgR(1 − cos θ)."""
    doc = derivation_document(scene_id)
    rows = _rows(scene_id)
    u = rows["potential"][0].removeprefix("U = ")
    q = doc["effective_potential"]["coordinate"]
    assert doc["effective_potential"]["momenta"] == []
    assert rows["effective-potential"][0].endswith(f") = {u}")
    assert doc["effective_potential"]["potential"]["latex"] == u == doc["potential"]["latex"]
    assert q in {"theta", "z"}
