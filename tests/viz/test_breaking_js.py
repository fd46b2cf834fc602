"""How a display formula is prepared for KaTeX on the page (static/js/breaking.js, run with node): where a narrow
page may break a row, and the room between stacked rows that hold fractions (issue 40, prof-l 7 and 9)."""

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from app.engine.derivation.derive import derive
from app.engine.document.action_step import action_step
from app.scenes import SCENES

JS = Path(__file__).resolve().parents[2] / "static" / "js"

# slow: out of the fast tier (scripts/test-fast.sh), each test over 0.3 s (docs/testing.md)
pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(shutil.which("node") is None, reason="node is installed with the front-end assets"),
]


def node(body: str, data):
    script = (
        f"import * as m from {json.dumps((JS / 'breaking.js').as_uri())};"
        "import { readFileSync } from 'node:fs';"
        f"const data = JSON.parse(readFileSync(0, 'utf8')); console.log(JSON.stringify(({body})(m, data)));"
    )
    run = subprocess.run(
        ["node", "--input-type=module", "-e", script],
        input=json.dumps(data),
        capture_output=True,
        text=True,
        timeout=30,
    )
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_no_row_may_end_a_line_with_a_relation():
    # the first step's condition: "δq(t₀) = δq(t₁) =" at a line's end and "0" alone on the next, on a phone
    latex = action_step(derive(SCENES["simple-pendulum"].system))["latex"]
    rows = node("(m, tex) => m.alignedRows(tex).map((r) => m.breakable(r))", latex)
    condition = rows[1]
    # the condition is one group: no break inside it, and a break allowed before its "with", after the wide space
    assert r"\allowbreak \text{ with } {\delta q(t_0) = \delta q(t_1) = 0}" in condition
    assert r"\quad\allowbreak " in condition
    # the row's own relation holds what follows it
    assert condition.startswith(r"\delta S =\nobreak  0")
    # a chain a = b = c: each relation holds its right side; the second may begin the next line instead
    chained = node("(m, row) => m.breakable(row)", r"E = \frac{a}{b} = c + d \approx 5.7")
    assert (
        chained
        == r"E =\nobreak  \frac{a}{b} \allowbreak =\nobreak  c \allowbreak +\nobreak  d \allowbreak \approx\nobreak  5.7"
    )
    # only a row wider than its box however it breaks so is broken after a relation as well (the page's second try)
    # the first relation lets go of what follows it; one that continues the equation still begins the next line
    # with what follows it (prof-q 5: the cylinder's "H = Σ p q̇ − L =" ended a line, its fraction below)
    loose = node("(m, row) => m.breakable(row, true)", r"E = \frac{a}{b} = c + d \approx 5.7")
    assert loose == (
        r"E = \frac{a}{b} \allowbreak =\nobreak  c \allowbreak +\nobreak  d \allowbreak \approx\nobreak  5.7"
    )
    # the last try for a row still too wide: a continuing relation may end a line too, kept where that is narrower
    last = node("(m, row) => m.breakable(row, 'after')", r"E = \frac{a}{b} = c + d \approx 5.7")
    assert last == r"E = \frac{a}{b} = c \allowbreak +\nobreak  d \allowbreak \approx\nobreak  5.7"
    # prof-q 5: a row that begins with its relation (an aligned block's "= ∫ …" under "t = …") never leaves it
    # alone on a line, however wide the row
    assert node("(m, row) => m.breakable(row, true)", r"= \int \frac{dy}{\sqrt{E}}") == (
        r"=\nobreak  \int \frac{dy}{\sqrt{E}}"
    )


def test_a_line_breaks_before_a_sign_never_after_it():
    """prof-p 1: on a phone the wedge's H broke after its "−", which sat past the box's edge, and the next line
    began "m g D sin α" with no sign. A + or − between terms at the top level allows a break before it and holds
    the term after it; a sign after a relation, an opening bracket or inside braces or brackets is left alone."""
    row = r"H = \frac{p^{2}}{2 m} - m g D \sin {\alpha} + \left(a - b\right) + x_{1 - k}"
    assert node("(m, row) => m.breakable(row)", row) == (
        r"H =\nobreak  \frac{p^{2}}{2 m} \allowbreak -\nobreak  m g D \sin {\alpha} \allowbreak +\nobreak  "
        r"\left(a - b\right) \allowbreak +\nobreak  x_{1 - k}"
    )
    assert node("(m, row) => m.breakable(row)", r"f = - 4 m g") == r"f =\nobreak  - 4 m g"


def test_stacked_fractions_get_room_between_their_rows():
    latex = r"\begin{aligned}\ddot{x} &= \frac{a}{b} \\ \ddot{y} &= \frac{\begin{aligned}&c \\ &+ d\end{aligned}}{e}\end{aligned}"
    spaced = node("(m, tex) => m.spacedRows(tex)", latex)
    # KaTeX reads \\[0.6em] as a least depth, which a deep fraction passes: the first row ends instead in an
    # invisible copy of itself (no alignment mark) lowered by the gap, so that it is that much deeper; the
    # numerator's own lines, inside its braces, are left as they were, and the last row gets no copy
    assert spaced == latex.replace(
        r"\frac{a}{b} \\ ", r"\frac{a}{b} \raisebox{-0.6em}{$\displaystyle\vphantom{\ddot{x} = \frac{a}{b} }$} \\  ", 1
    )
    # rows without a fraction, a single formula, and the page's data-tex itself are left alone
    plain = r"\begin{aligned}x &= 1 \\ y &= 2\end{aligned}"
    assert node("(m, tex) => [m.spacedRows(tex), m.spacedRows('x = \\\\frac{1}{2}')]", plain) == [
        plain,
        r"x = \frac{1}{2}",
    ]
    # a separator's own space stays with it
    gapped = r"\begin{aligned}a &= \frac{1}{2} \\[4pt] b &= 1\end{aligned}"
    assert r"$} \\[4pt] " in node("(m, tex) => m.spacedRows(tex)", gapped)


def test_a_fraction_too_wide_for_a_phone_has_its_numerator_set_on_more_lines():
    # prof-n 10: the double pendulum's θ̈₁, a fraction whose numerator the engine sets on two lines, is still wider
    # than a phone; the page sets its numerator's terms on more lines, each beginning with its sign
    row = (
        r"\ddot{\theta}_{1} = \frac{\begin{aligned}&a \cos{\left(\theta_{1} - \theta_{2} \right)} - \left(m_{1} + m_{2}"
        r"\right) g \\ &\quad - b^{-2} \sin{\theta} + c\end{aligned}}{l_{1} \left(m_{1} - m_{2}\right)}"
    )
    found = node(
        "(m, row) => { const f = m.fractionRow(row); return { f, terms: m.numeratorTerms(f.num),"
        " two: m.stackedFraction(f, 2, [1, 1, 1, 1]), after: m.fractionRow(row + ' + d').after,"
        " none: m.fractionRow('x = \\\\left(\\\\frac{a}{b} + c\\\\right)') }; }",
        row,
    )
    assert found["f"]["before"] == r"\ddot{\theta}_{1} = "
    assert found["f"]["den"] == r"l_{1} \left(m_{1} - m_{2}\right)"
    # split before each + and − outside braces and brackets: not inside (θ₁ − θ₂), (m₁ + m₂) or the exponent −2
    assert found["terms"] == [
        r"a \cos{\left(\theta_{1} - \theta_{2} \right)}",
        r"- \left(m_{1} + m_{2}\right) g",
        r"- b^{-2} \sin{\theta}",
        r"+ c",
    ]
    assert found["two"] == (
        r"\ddot{\theta}_{1} = \frac{\begin{aligned}&a \cos{\left(\theta_{1} - \theta_{2} \right)} - \left(m_{1} + m_{2}"
        r"\right) g \\ &- b^{-2} \sin{\theta} + c\end{aligned}}{l_{1} \left(m_{1} - m_{2}\right)}"
    )
    # a row going on after its fraction keeps what follows; no fraction at the row's top level, none (one inside
    # a bracket is the bracket's)
    assert found["after"] == " + d" and found["none"] is None


def test_a_fraction_with_a_term_after_it_has_its_numerator_stacked_and_the_term_kept():
    # prof-q 5: the rolling cylinder's H, a fraction followed by − m g s sin α, was clipped on a phone: its numerator
    # is set on lines as a fraction that ends the row is, the term after it kept
    row = r"H = \sum_k p_k \dot{q}_k - L = \frac{a p^{2} + b q^{2} - c p q \cos{\alpha}}{2 m} - \frac{x}{y} - m g s \sin{\alpha}"
    found = node("(m, row) => { const f = m.fractionRow(row); return { f, two: m.stackedFraction(f, 2) }; }", row)
    # the widest fraction (the longest numerator), not the first or the last
    assert found["f"] == {
        "before": r"H = \sum_k p_k \dot{q}_k - L = ",
        "num": r"a p^{2} + b q^{2} - c p q \cos{\alpha}",
        "den": "2 m",
        "after": r" - \frac{x}{y} - m g s \sin{\alpha}",
    }
    assert found["two"] == (
        r"H = \sum_k p_k \dot{q}_k - L = \frac{\begin{aligned}&a p^{2} + b q^{2} \\ &- c p q \cos{\alpha}\end{aligned}}{2 m}"
        r" - \frac{x}{y} - m g s \sin{\alpha}"
    )


def test_a_vector_too_wide_for_a_phone_is_set_as_a_column():
    # prof-q 5: the rolling cylinder's r⃗_cm = (X + s cos α + r sin α, 0, −s sin α + r cos α) was clipped on a phone;
    # a vector given by its components after its = is set as a column, split at its top-level commas only
    rows = [
        r"\vec r_{\mathrm{cm}} = \left(X + s \cos {\alpha}, 0, - s \sin {\alpha} + r \cos {\alpha}\right)",
        r"\vec v = \left(f\left(a, b\right), c_{1, 2}\right)",
        r"T = m \left(a + b\right)",
        r"x = \left(a, b\right) + c",
    ]
    found = node("(m, rows) => rows.map((r) => { const v = m.vectorRow(r); return v && m.columnVector(v); })", rows)
    assert found == [
        r"\vec r_{\mathrm{cm}} = \begin{pmatrix}X + s \cos {\alpha} \\ 0 \\ - s \sin {\alpha} + r \cos {\alpha}\end{pmatrix}",
        r"\vec v = \begin{pmatrix}f\left(a, b\right) \\ c_{1, 2}\end{pmatrix}",
        None,
        None,
    ]
