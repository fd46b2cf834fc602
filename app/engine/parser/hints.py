"""The parser's help for text it cannot read (app/engine/parser/parse.py): which character is refused and why
(``=`` makes an equation, a quote a string, ``ｓ`` is neither ASCII nor Greek).  Pure Python.
"""

from __future__ import annotations

import unicodedata

from app.engine.parser.rules import ALLOWED_CHARACTERS, ExpressionError


def first_bad_character(text: str) -> int | None:
    for i, ch in enumerate(text):
        if ch not in ALLOWED_CHARACTERS:
            return i
    return None


def characters_error(text: str, columns: list[int]) -> ExpressionError:
    """Every refused character of a text in one message, those refused for one reason together ("'≤' at column
    3 and '≥' at column 9 are not allowed: …"); the part marked runs from the first to the last."""
    if len(columns) == 1:
        return character_error(text, columns[0])
    # reason -> character -> its columns
    by_reason: dict[str, dict[str, list[str]]] = {}
    for i in columns:
        by_reason.setdefault(_why(text[i]), {}).setdefault(text[i], []).append(str(i + 1))
    said = []
    for why, chars in by_reason.items():
        where = [f"{ch!r} at column{'s' if len(cols) > 1 else ''} {_listed(cols)}" for ch, cols in chars.items()]
        said.append(f"{_listed(where)} {'is' if len(where) == 1 else 'are'} not allowed: {why}")
    first, last = columns[0], columns[-1] + 1
    return ExpressionError(
        f"{len(columns)} characters cannot be read: " + "; ".join(said), text[first:last], first, last
    )


def _listed(items: list[str]) -> str:
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def character_error(text: str, i: int) -> ExpressionError:
    ch = text[i]
    return ExpressionError(f"character {ch!r} at column {i + 1} is not allowed: {_why(ch)}", ch, i, i + 1)


def _why(ch: str) -> str:
    """Why a character is refused, with how to type what it means where there is a way."""
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
            "dots over letters (θ̇), the signs · × −, small raised digits (x²) and fractions (½)"
        )
    else:
        why = "only letters, digits, spaces, _ . , ( ) and the signs + - * / ^ are allowed (^ is a power)"
    return why
