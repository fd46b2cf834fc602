"""LaTeX to MathML on the server: formulas read without JavaScript; what cannot be converted stays as TeX."""

from app.web.mathml import mathml


def test_a_formula_becomes_presentation_mathml():
    out = str(mathml(r"\dot{\theta} = \frac{g}{R}", True))
    assert out.startswith('<math xmlns="http://www.w3.org/1998/Math/MathML" display="block">')
    assert "<mfrac>" in out and "&#x003B8;" in out


def test_what_cannot_be_converted_stays_as_escaped_tex():
    assert str(mathml(r"\frac{1}{")) == r"\frac{1}{"
    assert "<script" not in str(mathml("<script>"))
