"""The formula under "The mistake:", said for what it is and in the scale of the student's answer.

The difference line above it already shows yours − correct, at the answer's scale (an equation divided
through is compared with the correct one divided the same way).  The mistake's piece, rescaled the same way,
is then shown only where it adds something, and labelled:

* equal to the difference (up to the step's accepted constant): nothing, one formula is enough;
* equal to minus the difference: "what your T leaves out";
* a term of the correct answer (at the answer's scale): "the correct term";
* a follow-up question's answer is never shown (the question asks for it): after such a mistake, what the
  answer leaves out, when the answer is that mistake and nothing else, unless it is the follow-up's answer;
* anything else: nothing (the name says it).

Bounded by ``PIECE_WORK`` (counted, never timed): past it, nothing is shown.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy as sp

from app.engine.tutor.compare import Groups, differ_by_constant, equal, values
from app.engine.tutor.mistake_families import Mistake


def piece_box(
    mistake: Mistake,
    difference: sp.Expr,
    truth: sp.Expr,
    scale: sp.Expr,
    groups: Groups,
    relation: str,
    what: str,
    whole: bool,
    tex: Callable[[sp.Expr], str],
) -> str:
    """The LaTeX of the labelled piece, or "" when the difference line says it all."""
    d = values(difference, groups)

    def same(x: sp.Expr, y) -> bool:
        v = values(x, groups)
        return equal(v, y) or (relation == "constant" and differ_by_constant(v, y))

    left_out = rf"\text{{what your {what} leaves out: }}"
    fu = mistake.follow_up
    if fu is not None:
        missing = -difference
        # the follow-up's answer itself (a body's kinetic energy) would answer the question for the student
        if not whole or equal(values(missing**2 if fu.relation == "magnitude" else missing, groups),
                              values(fu.truth**2 if fu.relation == "magnitude" else fu.truth, groups)):  # fmt: skip
            return ""
        return left_out + tex(sp.factor_terms(missing))
    if mistake.piece is None:
        return ""
    # the piece at the answer's scale: an equation divided through by m₂ l₂ shows its terms divided so too
    piece = sp.expand(scale * mistake.piece)
    if same(piece, d):
        return ""
    if same(-piece, d):
        return left_out + tex(sp.factor_terms(piece))
    if piece in sp.Add.make_args(sp.expand(scale * truth)):
        return r"\text{the correct term: }" + tex(piece)
    return ""
