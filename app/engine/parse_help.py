"""The parser's help for text it cannot read (app/engine/parse.py): which character is refused and why
(``=`` makes an equation, a quote a string, ``ｓ`` is neither ASCII nor Greek).  Pure Python.
"""

from __future__ import annotations

import unicodedata

from app.engine.parse_rules import ALLOWED_CHARACTERS, ExpressionError


def first_bad_character(text: str) -> int | None:
    for i, ch in enumerate(text):
        if ch not in ALLOWED_CHARACTERS:
            return i
    return None


def character_error(text: str, i: int) -> ExpressionError:
    ch = text[i]
    if ch == "=":
        why = "an equation is not an expression: write it as one expression equal to zero, e.g. a - (b) for a = b"
    elif ch in "'\"":
        why = "quotes are not allowed: an expression holds no strings"
    elif unicodedata.decomposition(ch).startswith("<fraction>"):
        # a vulgar fraction (½, ¾): the keyboard's digits and a quotient in brackets say the same
        share = unicodedata.normalize("NFKC", ch).replace("⁄", "/")
        why = f"a fraction is typed with digits and a slash: write ({share})"
    elif ch == "|":
        # bars are a textbook's absolute value: say how it is typed (as in Python; the parser reads it as SymPy's)
        why = "an absolute value |x| is typed abs(x)"
    elif ord(ch) > 127:
        why = (
            "besides the keyboard's letters, digits and signs, you may type Greek letters (θ), primes (θ'), "
            "dots over letters (θ̇), the signs · × − and small raised digits (x²)"
        )
    else:
        why = "only letters, digits, spaces, _ . , ( ) and the signs + - * / ^ are allowed (^ is a power)"
    return ExpressionError(f"character {ch!r} at column {i + 1} is not allowed: {why}", ch, i, i + 1)
