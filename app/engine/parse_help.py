"""The parser's help for text it cannot read (app/engine/parse.py): which character is refused and why
(``^`` is not a power, ``=`` makes an equation, ``θ`` is not ASCII), and the text with a ``*`` put between
factors written side by side, when that makes it read.  Pure Python.
"""

from __future__ import annotations

import ast
import io
import tokenize

from app.engine.parse_rules import ALLOWED_CHARACTERS, ExpressionError


def first_bad_character(text: str) -> int | None:
    for i, ch in enumerate(text):
        if ch not in ALLOWED_CHARACTERS:
            return i
    return None


def character_error(text: str, i: int) -> ExpressionError:
    ch = text[i]
    if ch == "^":
        why = "'^' is not a power here: write x**2"
    elif ch == "=":
        why = "an equation is not an expression: write it as one expression equal to zero, e.g. a - (b) for a = b"
    elif ch in "'\"":
        why = "quotes are not allowed: an expression holds no strings"
    elif ord(ch) > 127:
        why = "only ASCII is allowed (write theta, not θ)"
    else:
        why = "only letters, digits, spaces, _ . , ( ) and + - * / ** are allowed"
    return ExpressionError(f"character {ch!r} at column {i + 1} is not allowed: {why}", ch, i, i + 1)


def with_stars(text: str) -> str | None:
    """The text with a * put between factors written side by side ("m R**2 theta_dot"), if that makes it read.

    Two factors meet where a name, number or closing bracket is followed, after spaces, by a name, a number
    or an opening bracket; a name directly followed by "(" is a call and stays one."""
    out, last_end, gaps = [], 0, 0
    previous: tokenize.TokenInfo | None = None
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError, IndentationError):
        return None
    for tok in tokens:
        if tok.type in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER):
            continue
        ends = previous is not None and (
            previous.type in (tokenize.NAME, tokenize.NUMBER) or previous.string == ")"
        )
        starts = tok.type in (tokenize.NAME, tokenize.NUMBER) or tok.string == "("
        call = tok.string == "(" and previous is not None and previous.type == tokenize.NAME and previous.end == tok.start
        if ends and starts and not call and previous is not None:
            out.append(text[last_end : previous.end[1]] + "*")
            last_end = tok.start[1]
            gaps += 1
        previous = tok
    if not gaps:
        return None
    fixed = "".join(out) + text[last_end:]
    try:
        ast.parse(fixed, mode="eval")
    except SyntaxError:
        return None
    return fixed
