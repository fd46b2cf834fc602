"""How a step's rows are stacked: aligned at their '=' where their left sides differ, flush left where every row
is an equation "… = 0" (aligned at "= 0", the left sides of two Euler–Lagrange equations start at ragged places)."""

from app.service.chapter.derivations import derivation_document


def _rows(latex: str) -> list[str]:
    return latex.removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}").split(r" \\ ")


def test_euler_lagrange_equations_stack_flush_left():
    # prof-c S12: the spherical pendulum's two equations were aligned at "= 0", the second indented far right
    step = next(s for s in derivation_document("spherical-pendulum")["steps"] if s["key"] == "euler-lagrange")
    rows = _rows(step["latex"])
    assert len(rows) == 2
    assert all(r.startswith("&") and r.endswith("= 0") and "&=" not in r for r in rows), rows


def test_definitions_still_align_at_their_equals_sign():
    step = next(s for s in derivation_document("spherical-pendulum")["steps"] if s["key"].startswith("derivatives:"))
    rows = _rows(step["latex"])
    assert len(rows) >= 2 and all("&=" in r for r in rows), rows
