"""Long formulas broken across aligned lines: where, and only when too wide."""

from app.engine.display import breaking
from app.engine.display.breaking import broken, broken_row, single, width
from app.service.chapter.derivations import derivation_document


def test_width_counts_a_fraction_once_and_scripts_small():
    assert width(r"\frac{a + b + c}{d}") < width("a + b + c + d")
    assert width(r"x_{1}^{2}") < width("x12")
    assert abs(width(r"\theta") - width("a")) < 0.1  # a command is one glyph


def test_a_short_row_is_left_alone():
    row = r"\ddot{\theta} + \frac{g}{R} \sin {\theta} = 0"
    assert broken_row(row) == [row] and broken(row) == row and single(row) == row


def test_a_long_sum_breaks_at_its_top_level_signs_only():
    terms = [rf"a_{{{i}}} \left(b_{{{i}}} + c_{{{i}}}\right)" for i in range(12)]
    row = "L = " + " + ".join(terms)
    rows = broken_row(row)
    assert len(rows) > 1 and rows[0].startswith("L = a_{0}") and all(r.startswith(r"\quad + ") for r in rows[1:])
    assert all(width(r) <= breaking.LIMIT for r in rows)
    # nothing is cut inside a bracket
    assert all(r.count(r"\left(") == r.count(r"\right)") for r in rows)
    # the pieces put together again are the row
    assert " ".join([rows[0], *(r.removeprefix(r"\quad ") for r in rows[1:])]) == row


def test_a_long_quotient_stacks_its_numerator():
    num = " + ".join(rf"m_{{{i}}} g \sin {{\theta_{{{i}}}}}" for i in range(10))
    row = rf"\ddot{{\theta}} = - \frac{{{num}}}{{l \left(2 m_{{1}} + m_{{2}}\right)}}"
    (out,) = broken_row(row)
    assert out.startswith(r"\ddot{\theta} = - \frac{\begin{aligned}&") and r"\\ &\quad + " in out


def test_an_equation_with_a_long_left_side_keeps_its_right_side_on_the_last_line():
    row = " + ".join(rf"a_{{{i}}} \ddot{{x}}_{{{i}}}" for i in range(16)) + " = 0"
    (out,) = broken_row(row)
    assert out.startswith(r"\begin{aligned}&a_{0}") and out.endswith(r" = 0\end{aligned}")


def test_the_double_pendulum_results_fit_the_limit_or_are_broken():
    doc = derivation_document("double-pendulum")
    for pair in doc["accelerations"].values():
        tex = pair["latex"]
        assert width(tex) <= breaking.LIMIT or r"\begin{aligned}" in tex


def test_a_matrix_is_as_wide_as_its_widest_row_not_its_rows_together():
    entry = r"- \frac{m_{1} + m_{2}}{m_{2}}"
    column = rf"\begin{{pmatrix}}{entry}\\{entry}\end{{pmatrix}}"
    # two entries stacked: one entry's width and the brackets'
    assert width(entry) < width(column) < 1.5 * width(entry)
    square = r"\begin{matrix}k + \kappa & - \kappa\\- \kappa & k + \kappa\end{matrix}"
    assert width(square) < width(r"k + \kappa - \kappa - \kappa k + \kappa")
