"""The display canonicaliser: reader's order, divided equations, no nested fractions, bounded."""

import pytest
import sympy as sp

from app.engine.algebra.budget import display_budget
from app.engine.display import textbook
from app.engine.document.errata import ascii_tex, correct_tex
from app.engine.parser.symbols import SymbolTable

TABLE = SymbolTable(("theta", "phi"), ("m", "g", "R", "b"))
NAMES = TABLE.latex_names()
theta, phi = TABLE.q
thd, phd = TABLE.qd
thdd, phdd = TABLE.qdd
m, g, R, b = TABLE.params


def tex(expr, **kw):
    return textbook.latex(expr, NAMES, **kw)


def test_numbers_then_parameters_in_a_readers_order():
    assert tex(R**2 * m * thd**2 / 2) == r"\frac{1}{2} m R^{2} \dot{\theta}^{2}"
    assert tex(R * g * m * (1 - sp.cos(theta))) == r"m g R \left(1 - \cos {\theta}\right)"


def test_kinetic_terms_before_potential_ones():
    L = R**2 * m * thd**2 / 2 - R * g * m * (1 - sp.cos(theta))
    assert tex(L) == r"\frac{1}{2} m R^{2} \dot{\theta}^{2} - m g R \left(1 - \cos {\theta}\right)"


def test_equation_divided_by_its_accelerations_coefficient():
    residual = R * m * (R * thdd + g * sp.sin(theta)) + b * thd
    shown = textbook.normalised(residual, m * R**2, True, NAMES, thdd)
    assert sp.simplify(shown - residual / (m * R**2)) == 0  # the same equation
    assert tex(shown, first=thdd) == r"\ddot{\theta} + \frac{b}{m R^{2}} \dot{\theta} + \frac{g}{R} \sin {\theta}"


def test_a_term_divided_by_a_sum_keeps_its_sign_in_front():
    """prof-o F5: a term −m θ φ̇² divided by m(1 + b²) reads −θφ̇²/(1 + b²), never (−1 − b²)θφ̇²/(1 + b²)²
    (SymPy keeps −1/(1 + b²) as 1/(−1 − b²), and the term divided by that left half of it in the moving part)."""
    residual = m * (1 + b**2) * thdd - m * theta * phd**2 + m * g * b
    shown = textbook.normalised(residual, m * (1 + b**2), True, NAMES, thdd)
    assert sp.simplify(shown - residual / (m * (1 + b**2))) == 0
    assert tex(shown, first=thdd) == (
        r"\ddot{\theta} - \frac{\theta \dot{\varphi}^{2}}{1 + b^{2}} + \frac{g b}{1 + b^{2}}"
    )


def test_a_coordinate_dependent_sum_is_not_divided_out():
    residual = m * (1 + 4 * R**2 * theta**2) * thdd + m * g * theta
    shown = textbook.normalised(residual, m * (1 + 4 * R**2 * theta**2), True, NAMES, thdd)
    assert sp.simplify(shown - residual / m) == 0
    assert tex(shown, first=thdd).startswith(r"\left(1 + 4 R^{2} \theta^{2}\right) \ddot{\theta}")


@pytest.mark.parametrize(
    ("residual", "coefficient", "diagonal", "factor"),
    [
        (R * m * (R * thdd + g * sp.sin(theta)) + b * thd, m * R**2, True, m * R**2),
        (m * (1 + 4 * R**2 * theta**2) * thdd + m * g * theta, m * (1 + 4 * R**2 * theta**2), True, m),
        # a leading term with a minus sign: the whole equation is negated, and so is its factor
        (-m * R * thdd - m * g * sp.sin(theta) + m * R * phdd, m * R, False, -m),
    ],
)
def test_the_display_says_the_factor_it_divided_by(residual, coefficient, diagonal, factor):
    """residual = factor × display: the factor ``report.equation_scales`` prints ("the θ equation by mR²")."""
    shown, s = textbook.scaled(residual, coefficient, diagonal, NAMES, thdd)
    assert sp.expand(residual - s * shown) == 0
    assert sp.simplify(s - factor) == 0


def test_no_fraction_inside_a_fraction():
    inner = 1 / sp.sqrt((2 * g - phd**2 / (m * R**2 * sp.sin(theta) ** 2)) / (m * R**2))
    out = tex(inner)
    assert out.count(r"\frac") == 1 and " / " in out


def test_a_bracket_of_negative_terms_is_written_positive():
    assert tex(g * R * (-m - b) * sp.cos(theta)) == r"- \left(m + b\right) g R \cos {\theta}"


@pytest.mark.slow
def test_deterministic_and_bounded():
    expr = sp.expand((theta + phi + thd + phd + m + g) ** 7)  # far beyond the node budget
    assert tex(expr) == sp.latex(expr, symbol_names=NAMES)
    small = R**2 * m * thd**2 / 2 + m * g * R * sp.cos(theta)
    assert tex(small) == tex(sp.sympify(sp.srepr(small)))


def test_errata_formulas_are_typeset_as_written():
    assert ascii_tex("theta_ddot + (g/R) sin(theta) = 0") == r"\ddot{\theta}  + (g /R ) \sin (\theta ) = 0"
    assert r"\text{ is simple harmonic with }" in ascii_tex("x = 0 is simple harmonic with omega = sqrt(g/R)")
    assert ascii_tex("omega = sqrt(g/R)").endswith(r"\sqrt{g /R}")
    assert correct_tex("theta_ddot = -g*sin(theta)/R", NAMES) == r"\ddot{\theta} = - \frac{g}{R} \sin {\theta}"
    assert correct_tex("tau = dL/dtheta = -m*g*R*sin(theta)", NAMES).startswith(r"\tau = \frac{dL}{d\theta}")


def test_prose_formulas_are_unicode_never_code():
    x1, x2 = sp.symbols("x1 x2")
    k, l0 = sp.symbols("k l0")
    assert textbook.unicode_text(1 / (R**2 * m), NAMES) == "1/(mR²)"
    assert textbook.unicode_text(-R * g * m, NAMES) == "−mgR"
    assert textbook.unicode_text(sp.sin(theta) ** 2, NAMES) == "sin² θ"
    assert textbook.unicode_text(sp.sqrt(g / R), NAMES) == "√(g/R)"
    assert textbook.unicode_text(m * g * sp.sin(theta) * sp.cos(theta), NAMES) == "mg sin θ cos θ"
    # a function's power is set apart as the function is: M + m sin²θ, never msin²θ
    assert textbook.unicode_text(m * g * sp.sin(theta) ** 2, NAMES) == "mg sin² θ"
    square = textbook.unicode_text(k * (x2 - x1 - l0) ** 2 / 2, {x1: "x_1", x2: "x_2", sp.Symbol("x1_dot"): ""})
    assert square.startswith("k(x₂ − ") and square.endswith(")²/2")
    for expr in (thd**2 * R**2 * m / 2, (m + b) * g / (R * sp.sin(theta) ** 3), -g * sp.cos(theta - phi)):
        text = textbook.unicode_text(expr, NAMES)
        assert "*" not in text and "**" not in text and "-" not in text, text


def test_a_document_prints_each_expression_once_for_each_set_of_names(monkeypatch) -> None:
    th, l, g = sp.symbols("theta l g")  # noqa: E741
    printed: list[sp.Expr] = []
    doprint = textbook._Printer.doprint
    monkeypatch.setattr(textbook._Printer, "doprint", lambda self, e: printed.append(e) or doprint(self, e))
    expr = -g * sp.sin(th) / l
    names = {th: r"\theta", l: "l", g: "g"}
    with display_budget(10):
        first = textbook.latex(expr, names)
        assert textbook.latex(expr, names) == first and len(printed) == 1
        # other names, or another term first, print again
        assert textbook.latex(expr, {**names, th: r"\phi"}) == first.replace(r"\theta", r"\phi")
        textbook.latex(expr, names, first=g)
        assert len(printed) == 3
    textbook.latex(expr, names)  # outside a document: printed each time
    assert len(printed) == 4


def test_a_mass_comes_before_a_bracket_of_other_parameters():
    """prof-n 6: the helix printed ½(1 + α²R²) m ż², computer-algebra order; a textbook writes ½ m(1 + α²R²) ż².
    A bracket that holds a mass still leads: (m₁ + m₂) g l₁."""
    assert tex((1 + g * R**2) * m * thd**2 / 2) == r"\frac{1}{2} m \left(1 + g R^{2}\right) \dot{\theta}^{2}"
    # half a parameter's square within the bracket as a textbook writes it: m(g − ½b²)θ², not m(g − b²/2)θ²;
    # a mass's half, and a half of a product, keep their bar: (m₁ + M/4)
    assert tex((g - b**2 / 2) * m * theta**2) == r"m \left(g - \tfrac{1}{2} b^{2}\right) \theta^{2}"
    assert tex((g - m / 2) * theta) == r"\left(g - \frac{m}{2}\right) \theta"
    assert tex((g - b * R / 2) * theta) == r"\left(g - \frac{b R}{2}\right) \theta"
    assert tex((m + b) * g * R) == r"\left(m + b\right) g R"


def test_a_velocity_comes_after_an_inertia_that_varies():
    """prof-n 6: the rotating wire printed p_ρ = m ρ̇ (1 + 4α²ρ²) beside 𝓜 = m(1 + 4α²ρ²). A bracket that holds
    positions only is an inertia: the velocity it multiplies comes after it, as the acceleration does. A bracket
    that holds a rate keeps its place after the rates."""
    inertia = 1 + 4 * b**2 * theta**2
    assert tex(m * inertia * thd) == r"m \left(1 + 4 b^{2} \theta^{2}\right) \dot{\theta}"
    assert tex(m * inertia * thd**2 / 2) == r"\frac{1}{2} m \left(1 + 4 b^{2} \theta^{2}\right) \dot{\theta}^{2}"
    assert tex(m * inertia * thdd) == r"m \left(1 + 4 b^{2} \theta^{2}\right) \ddot{\theta}"
    assert tex(m * theta * (g - thd**2)) == r"m \theta \left(g - \dot{\theta}^{2}\right)"


def test_an_inertia_is_divided_out_when_a_single_term_and_kept_when_it_adds_masses():
    m1, m2, M, length, c = sp.symbols("m1 m2 M l c", positive=True)
    # the massive pulley's m₁ + m₂ + M/2 and two masses on one rod, l²(m₁ + m₂): 𝓜 q̈ = f
    assert textbook.masses_summed(m1 + m2 + M / 2)
    assert textbook.masses_summed(length**2 * (m1 + m2))
    # the physical pendulum's M l²/3 is one term; m(1 + c²) adds a length ratio, not masses: both divided out
    assert not textbook.masses_summed(M * length**2 / 3)
    assert not textbook.masses_summed(m * (1 + c**2))
