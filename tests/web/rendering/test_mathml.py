"""LaTeX to MathML on the server: formulas read without JavaScript; what cannot be converted stays as TeX."""

from xml.etree import ElementTree

import pytest

from app.web.rendering.mathml import ATTRIBUTES, ELEMENTS, MATHML_NS, mathml, sanitised


def test_a_formula_becomes_presentation_mathml():
    out = str(mathml(r"\dot{\theta} = \frac{g}{R}", True))
    assert out.startswith('<math xmlns="http://www.w3.org/1998/Math/MathML" display="block">')
    assert "<mfrac>" in out and "&#x003B8;" in out


def test_what_cannot_be_converted_stays_as_escaped_tex():
    assert str(mathml(r"\frac{1}{")) == r"\frac{1}{"
    assert "<script" not in str(mathml("<script>"))


HOSTILE_TEX = [
    r"\text{<img src=x onerror=alert(1)>}",
    r"\text{<script>alert(1)</script>}",
    r"\mathrm{<svg onload=alert(1)>}",
    r"\text{</math><img src=x onerror=alert(1)>}",
    r"\href{javascript:alert(1)}{x}",
    r"\style{background:url(javascript:alert(1))}{y}",
    r"\color{red\" onmouseover=\"alert(1)}{x}",
    r"\text{&lt;img src=x&gt;}",
]


@pytest.mark.parametrize("tex", HOSTILE_TEX)
@pytest.mark.parametrize("display", [False, True])
def test_whatever_reaches_the_page_as_markup_passes_the_allowlist(tex, display):
    out = str(mathml(tex, display))
    if not out.startswith("<math"):
        assert "<" not in out  # unconverted TeX is escaped text
        return
    tree = ElementTree.fromstring(out)  # well-formed: every < in a text was escaped
    for element in tree.iter():
        assert element.tag.removeprefix("{" + MATHML_NS + "}") in ELEMENTS
        assert set(element.attrib) <= ATTRIBUTES
        assert all(":" not in v and "(" not in v for v in element.attrib.values())
    for forbidden in ("<img", "<script", "<svg", "</math><", " href=", " style=", " onerror=", " onmouseover="):
        assert forbidden not in out.lower()


def test_text_in_a_formula_stays_text():
    out = str(mathml(r"\text{<img src=x onerror=alert(1)>}"))
    assert "<mtext>&lt;img" in out and "<img" not in out


def test_an_element_outside_the_allowlist_becomes_its_text():
    tree = ElementTree.fromstring(
        '<math><mrow><mi>x</mi><foreignObject><b onclick="y">bold</b></foreignObject></mrow></math>'
    )
    out = sanitised(tree)
    assert "<foreignObject" not in out and "<b" not in out and "onclick" not in out
    assert "<mtext>bold</mtext>" in out


def test_the_converters_symbols_stay_character_references():
    out = str(mathml(r"\dot{\theta} = \alpha"))
    assert "&#x003B8;" in out and "&#x003B1;" in out and "&amp;#x" not in out


def test_aligned_rows_become_a_table_with_no_ampersand_shown():
    # the derivation's multi-row steps and broken long results (app/engine/display/breaking.py) read with JavaScript off
    out = str(mathml(r"\begin{aligned}L &= \frac{1}{2} m \dot{x}^{2} \\ &\quad - \frac{1}{2} k x^{2}\end{aligned}"))
    assert out.count("<mtr>") == 2 and "<mtable" in out
    assert "&amp;" not in out and "linebreak" not in out
