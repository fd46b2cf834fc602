"""The chapter's errata, typeset: what the chapter writes, what is correct, and why.

The chapter's formulas are kept as written (order, typos and all) and only typeset: each
ASCII formula is turned into LaTeX token by token (names through ``app.engine.display.names``,
words as text, ``sqrt(…)`` as a root, ``^2`` and ``**2`` as exponents).  The correct side is
parsed when it is an expression and printed in textbook form; a part that is not (``U_eff''``)
is typeset token by token like the chapter's.
"""

from __future__ import annotations

import re
from typing import Any

import sympy as sp

from app.engine.algebra.budget import unbudgeted
from app.engine.display import textbook
from app.engine.display.breaking import single
from app.engine.display.names import GREEK, latex
from app.engine.display.quotients import cleared
from app.scenes.types import Scene

_TOKEN = re.compile(r"\s+|[A-Za-z_][A-Za-z0-9_]*|\d+(?:\.\d+)?|\*\*|''|.", re.S)
_FUNCTIONS = {"sin", "cos", "tan", "exp", "log", "sinh", "cosh"}
_WORD = re.compile(r"[A-Za-z]{3,}")
_SHORT_WORDS = {"is", "of", "on", "in", "to", "at", "an", "as", "or", "by", "if", "i", "e"}
_GLUE = {" ", ".", ",", ";", ":", "'"}


def _differential(token: str) -> bool:
    """dtheta, dX_dot, dU: a d in front of a symbol's name."""
    rest = token[1:]
    return token.startswith("d") and bool(rest) and (rest in GREEK or rest[0].isupper() or rest.endswith("_dot"))


def _is_word(token: str) -> bool:
    """An English word of the prose, not a symbol name."""
    if token in _SHORT_WORDS:
        return True
    plain = bool(_WORD.fullmatch(token)) and token not in GREEK and token not in _FUNCTIONS
    return plain and token != "sqrt" and not _differential(token)


def _words(tokens: list[str], i: int) -> tuple[str, int]:
    """A run of prose from ``tokens[i]`` (words with the spaces and punctuation between them) as text."""
    j = i

    def hyphen(k: int) -> bool:  # action-reaction: a hyphen between two words is part of the prose, not a minus
        return tokens[k] == "-" and k > i and _is_word(tokens[k - 1]) and k + 1 < len(tokens) and _is_word(tokens[k + 1])

    while j < len(tokens) and (_is_word(tokens[j]) or tokens[j].isspace() or tokens[j] in _GLUE or hyphen(j)):
        j += 1
    while j > i + 1 and not _is_word(tokens[j - 1]) and tokens[j - 1] not in (".",):
        j -= 1  # trailing spaces and marks go back to the formula
    text = "".join(" " if t.isspace() else t for t in tokens[i:j])
    return rf"\text{{ {text} }}", j


def _group(tokens: list[str], i: int) -> tuple[list[str], int]:
    """The tokens inside the bracket that opens at ``tokens[i]``, and the index after its close."""
    depth, j = 0, i
    while j < len(tokens):
        depth += {"(": 1, ")": -1}.get(tokens[j], 0)
        if depth == 0:
            return tokens[i + 1 : j], j + 1
        j += 1
    return tokens[i + 1 :], len(tokens)


def _over(tokens: list[str], i: int) -> bool:
    """Whether the bracket opening at ``tokens[i]`` is a numerator: closed, then ``/`` and another bracket."""
    _, j = _group(tokens, i)
    return j + 1 < len(tokens) and tokens[j] == "/" and tokens[j + 1] == "("


def _tex_tokens(tokens: list[str]) -> str:
    out: list[str] = []
    i = 0
    while i < len(tokens):
        tok = tokens[i]
        if tok.isspace():
            out.append(" ")
            i += 1
        elif tok == "(" and _over(tokens, i):
            # (a)/(b), the chapter's displayed fraction written on one line: typeset as the fraction it is
            top, j = _group(tokens, i)
            bottom, i = _group(tokens, j + 1)
            out.append(rf"\frac{{{_tex_tokens(top)}}}{{{_tex_tokens(bottom)}}}")
        elif tok == "∂":
            out.append(r"\partial ")
            i += 1
        elif tok == "sqrt" and i + 1 < len(tokens) and tokens[i + 1] == "(":
            inner, i = _group(tokens, i + 1)
            out.append(rf"\sqrt{{{_tex_tokens(inner)}}}")
        elif tok in ("**", "^") and i + 1 < len(tokens):
            if tokens[i + 1] == "(":
                inner, i = _group(tokens, i + 1)
                out.append(f"^{{{_tex_tokens(inner)}}}")
            else:
                out.append(f"^{{{tokens[i + 1]}}}")
                i += 2
        elif _is_word(tok) and not (tok in _SHORT_WORDS and len(tok) == 1 and tokens[i + 1 : i + 2] != ["."]):
            text, i = _words(tokens, i)
            out.append(text)
        elif tok in _FUNCTIONS:
            out.append(f"\\{tok} ")
            i += 1
        elif _differential(tok):
            out.append("d" + latex(tok[1:]) + " ")
            i += 1
        elif re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", tok):
            out.append(latex(tok) + " ")
            i += 1
        else:
            out.append({"*": r"\,", "'": "'", "''": "''", "{": r"\{", "}": r"\}", "_": r"\_"}.get(tok, tok))
            i += 1
    return "".join(out).strip()


def ascii_tex(text: str) -> str:
    """An ASCII formula of the chapter as LaTeX, kept as written: theta_ddot + (g/R) sin(theta) -> θ̈ + (g/R) sin θ."""
    return _tex_tokens(_TOKEN.findall(text))


# a partial derivative the scene writes with ∂ (∂L/∂x1, −∂L/∂x2): printed as a textbook's ∂, never a d
_PARTIAL = re.compile(r"(-?)∂([A-Za-z_][A-Za-z0-9_]*)/∂([A-Za-z_][A-Za-z0-9_]*)")


def _side(text: str, names: dict[sp.Symbol, str]) -> str:
    """One side of a correct formula: parsed and printed in textbook form, else typeset as written."""
    # ±√…: both branches of a square root, the sign printed before the root
    if text.startswith("±"):
        return r"\pm " + _side(text[1:].strip(), names)
    if partial := _PARTIAL.fullmatch(text):
        sign, top, bottom = partial.groups()
        return ("- " if sign else "") + rf"\frac{{\partial {latex(top)}}}{{\partial {latex(bottom)}}}"
    if "'" in text or any(_is_word(n) for n in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", text)):
        return ascii_tex(text)
    symbols = {n: sp.Symbol(n, real=True) for n in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", text) if n not in _FUNCTIONS}
    try:
        expr = sp.sympify(text, locals={**symbols, "sqrt": sp.sqrt, **{f: getattr(sp, f) for f in _FUNCTIONS}})
    except (sp.SympifyError, SyntaxError, TypeError):
        return ascii_tex(text)
    # dtheta in dL/dtheta is d θ, a differential
    spelled = {s: "d" + latex(s.name[1:]) if _differential(s.name) else latex(s.name) for s in symbols.values()}
    table = {**spelled, **names}
    if isinstance(expr, sp.Tuple | tuple):
        raw = sp.sympify(text, locals={**symbols, **{f: getattr(sp, f) for f in _FUNCTIONS}}, evaluate=False)
        return r"\left(" + ", ".join(_component(r, e, table) for r, e in zip(raw, expr, strict=True)) + r"\right)"
    # no fraction inside a denominator: g/(m₁ + m₂ + 4m₁m₂/M) over 4m₁m₂ + M(m₁ + m₂)
    return textbook.latex(cleared(expr), table)


def _component(raw: sp.Basic, expr: sp.Basic, table: dict[sp.Symbol, str]) -> str:
    """One component of a correct vector: a plain product (R sin θ sin φ) keeps the factors' order as written,
    the order a textbook prints a position in spherical coordinates; anything else in textbook form."""
    factors = raw.args if isinstance(raw, sp.Mul) else ()
    if factors and all(isinstance(f, sp.Symbol | sp.core.function.Application) for f in factors):
        return " ".join(textbook.latex(f, table) for f in factors)
    return textbook.latex(expr, table)


def correct_tex(text: str, names: dict[sp.Symbol, str], approximate_for: str = "") -> str:
    """A correct formula ``lhs = rhs [= …]`` as LaTeX, each side in textbook form where it parses; one that holds
    only under a condition (small swings) as lhs ≈ rhs, then the condition."""
    sides = [_side(part.strip(), names) for part in text.split(" = ")]
    if not approximate_for:
        return " = ".join(sides)
    # θ̈ ≈ −(g/R) θ for |θ| ≪ 1: an approximation is printed with ≈ and the condition it needs
    return r" \approx ".join(sides) + rf", \quad \text{{for }} {approximate_for}"


CELL_EMS = 18.0  # ems of a formula in the errata table's cells (about 400-470 px at 1366 px, 17-18 px an em)


def errata_json(scene: Scene, names: dict[sp.Symbol, str]) -> list[dict[str, Any]]:
    """Each erratum with its two formulas typeset as LaTeX next to the ASCII originals."""
    with unbudgeted():
        return _errata(scene, names)


def _errata(scene: Scene, names: dict[sp.Symbol, str]) -> list[dict[str, Any]]:
    return [
        {
            "chapter": e.chapter,
            "correct": e.correct,
            "reason": e.reason,
            # each formula sits in a table cell, a third of the page: broken to fit it
            # a quotation of the chapter's words is prose, never typeset as a formula
            "chapter_words": e.words,
            "chapter_latex": "" if e.words else single(ascii_tex(e.chapter), CELL_EMS),
            "correct_latex": single(correct_tex(e.correct, names, e.approximate_for), CELL_EMS),
            "approximate": bool(e.approximate_for),
        }
        for e in scene.errata
    ]
