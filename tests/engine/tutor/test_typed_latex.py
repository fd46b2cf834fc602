"""The preview of an answer prints the structure the student typed (app/engine/tutor/typed_latex.py)."""

from __future__ import annotations

import pytest

from app.engine.parser.parse import read
from app.engine.tutor.typed_latex import typed_latex

NAMES = ("M", "m", "g", "R", "X_dot", "theta", "theta_dot", "theta1", "theta2", "a", "b", "c", "x")


@pytest.mark.parametrize(
    ("text", "printed"),
    [
        # a half before a sum stays a half: never (M/2 + m/2) Ẋ²
        ("1/2*(M+m)*X_dot**2", r"\frac{1}{2} \left(M + m\right) \dot{X}^{2}"),
        ("m*R**2*theta_dot**2/2", r"\frac{m R^{2} \dot{\theta}^{2}}{2}"),
        # the student's order of factors and terms is kept
        ("g*m*R*cos(theta) + 1", r"g m R \cos \theta + 1"),
        ("-g/R*sin(theta)", r"-\frac{g}{R} \sin \theta"),
        ("m*g/(2*R)", r"\frac{m g}{2 R}"),
        # nothing cancels or expands
        ("a - (b - c)", r"a - \left(b - c\right)"),
        ("x - x", r"x - x"),
        ("(a + b)**2", r"\left(a + b\right)^{2}"),
        ("sin(theta)**2*m", r"\sin^{2} \theta\, m"),
        ("cos(theta1 - theta2)*a", r"\cos\left(\theta_{1} - \theta_{2}\right)\, a"),
        ("2*3*x", r"2 \cdot 3 x"),
        ("a*(-b)", r"a \left(-b\right)"),
        ("sqrt(g/R)", r"\sqrt{\frac{g}{R}}"),
        ("0.5*m", r"0.5 m"),
        # an absolute value as a textbook prints it, never SymPy's Abs (issue 41, item 3)
        ("m*g*R*abs(cos(theta))", r"m g R \left|\cos \theta\right|"),
        ("Abs(x)**2", r"\left|x\right|^{2}"),
    ],
)
def test_an_answer_is_printed_as_typed(text, printed):
    assert typed_latex(read(text, NAMES)) == printed
