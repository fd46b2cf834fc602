"""Prose into markdown and LaTeX, escaped so that no text can become markup or code.

Titles, statements and explanations come from the scenes and the engine; units,
descriptions and labels may come from a user.  Every such string goes through
one of these two functions before it reaches a notebook's markdown or a LaTeX
document, so a unit like ``$\\input{/etc/passwd}$`` or ``<script>`` is printed
as the characters it is.
"""

from __future__ import annotations

import string
import unicodedata

from app.engine.display.names import GREEK, latex

# CommonMark lets any ASCII punctuation be escaped with a backslash; escaping all of it
# leaves no emphasis, link, HTML tag, heading, list, table or math ($) to open.
_MARKDOWN = str.maketrans({c: "\\" + c for c in string.punctuation})


def markdown_text(text: str) -> str:
    """Plain text for a markdown cell: one line, every ASCII punctuation mark escaped."""
    return " ".join(str(text).split()).translate(_MARKDOWN)


_LATEX_SPECIAL = {
    "\\": r"\textbackslash{}",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "#": r"\#",
    "^": r"\^{}",
    "_": r"\_",
    "%": r"\%",
    "~": r"\~{}",
    "<": r"\textless{}",
    ">": r"\textgreater{}",
    "|": r"\textbar{}",
}
# Characters the prose uses that pdflatex's default input encoding does not know: as math.
_LATEX_SYMBOLS = {
    "∂": r"\partial",
    "∇": r"\nabla",
    "−": "-",
    "×": r"\times",
    "·": r"\cdot",
    "≠": r"\neq",
    "≤": r"\leq",
    "≥": r"\geq",
    "≈": r"\approx",
    "→": r"\to",
    "⇒": r"\Rightarrow",
    "∞": r"\infty",
    "±": r"\pm",
    "√": r"\surd",
    "∫": r"\int",
    "°": r"^\circ",
    "ϕ": r"\phi",
    "ϑ": r"\vartheta",
}
_LATEX_TEXT = {"–": "--", "—": "---", "‘": "`", "’": "'", "“": "``", "”": "''", "…": r"\ldots{}", "\u00a0": "~"}
_SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789", strict=True))
_SUBSCRIPTS = dict(zip("₀₁₂₃₄₅₆₇₈₉", "0123456789", strict=True))
_ACCENTS = {"\u0307": "dot", "\u0308": "ddot", "\u0302": "hat", "\u0303": "tilde", "\u0304": "bar"}
# A Greek letter as the math command the equations print it with, from the one table of names (θ -> \theta,
# and φ -> \varphi: the prose's φ is the equations' one letter, never the closed \phi); the letters with
# no command are written as the Latin letters they look like (Α -> A, ο -> o), ς as \varsigma.
_GREEK_MATH = {char: latex(name) for name, char in GREEK.items()}
_GREEK_MATH |= dict(zip("ΑΒΕΖΗΙΚΜΝΟΡΤΧο", "ABEZHIKMNOPTXo", strict=True)) | {"ς": r"\varsigma"}


def _math_of(char: str) -> str | None:
    if char in _LATEX_SYMBOLS:
        return _LATEX_SYMBOLS[char]
    if char in _SUPERSCRIPTS:
        return "^{" + _SUPERSCRIPTS[char] + "}"
    if char in _SUBSCRIPTS:
        return "_{" + _SUBSCRIPTS[char] + "}"
    return _GREEK_MATH.get(char)


def _plain(char: str) -> str:
    """One character of running text in LaTeX."""
    if char in _LATEX_SPECIAL:
        return _LATEX_SPECIAL[char]
    if char in _LATEX_TEXT:
        return _LATEX_TEXT[char]
    if char == "\n" or char == "\t":
        return " "
    if unicodedata.combining(char):  # an accent the table does not know: the letter stays bare
        return ""
    if " " <= char <= "~":
        return char
    math = _math_of(char)
    if math is not None:
        return f"${math}$"
    # an accented Latin letter keeps its letter; anything else becomes a question mark
    folded = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode()
    return "".join(_LATEX_SPECIAL.get(c, c) for c in folded if " " <= c <= "~") or "?"


def latex_text(text: str) -> str:
    """Running text for a LaTeX document: specials escaped, Unicode the prose uses as math."""
    out: list[str] = []
    text = unicodedata.normalize("NFD", str(text))  # ẋ -> x + combining dot
    i = 0
    while i < len(text):
        char = text[i]
        accent = _ACCENTS.get(text[i + 1]) if i + 1 < len(text) else None
        if accent:
            # q̇ is q followed by a combining dot: \dot{q}
            base = _math_of(char) or (char if char.isascii() and char.isalpha() else None)
            out.append(f"$\\{accent}{{{base}}}$" if base else _plain(char))
            i += 2
            continue
        out.append(_plain(char))
        i += 1
    return "".join(out)
