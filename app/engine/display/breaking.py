"""Long formulas broken across aligned lines, the way a textbook sets a long result.

Works on the engine's LaTeX (any row, whoever printed it):

* ``width(tex)`` estimates how wide a formula is set, in ems of display math: a fraction is as wide
  as the wider of its numerator and denominator, sub- and superscripts count at script size, and a
  command such as ``\\theta`` is one glyph;
* ``broken(row, limit)`` breaks a row wider than ``limit`` at its top-level ``+`` and ``−`` (after its
  ``=``), continuing each line indented under the first; a quotient whose numerator is the long part
  (the double pendulum's θ̈₁) gets its numerator stacked over the bar instead.  A row that cannot be
  broken there (one long product, a matrix) is returned as it is: the page lets it scroll in its box.
"""

from __future__ import annotations

import re

# ems of display math a formula may take before it is broken: a step's box at 1366 px holds about 65 (17-18 px
# an em), the results box less, a page of the LaTeX export (11 pt, 2 cm margins) about 44 less its indents;
# one limit for all, so the page and the export break at the same places
LIMIT = 36.0
# ems of display math a step's box holds on a phone (390 px wide, about 19 px an em): a formula wider than this
# that the page cannot break at a top-level sign scrolls sideways there
PHONE = 18.0
_COMMAND = re.compile(r"\\([A-Za-z]+|.)")
_ZERO = {"left", "right", "big", "Big", "bigg", "Bigg", "bigl", "bigr", "Bigl", "Bigr", "displaystyle", "limits", "mathrm", "mathbf", "vec", "dot",
         "ddot", "hat", "bar", "tilde", "begin", "end", "text"}  # fmt: skip
_WIDE = {"sin": 1.4, "cos": 1.5, "tan": 1.5, "log": 1.3, "exp": 1.5, "sqrt": 1.0, "quad": 1.0, "qquad": 2.0,
         "sum": 1.2, "int": 0.8, "partial": 0.6, ",": 0.17, ";": 0.28, "!": 0.0, " ": 0.3}  # fmt: skip


def _group(tex: str, i: int) -> tuple[str, int]:
    """The braced group starting at tex[i] == '{' (its content, the index after it), or one character."""
    if i >= len(tex):
        return "", i
    if tex[i] != "{":
        if tex[i] == "\\":
            m = _COMMAND.match(tex, i)
            assert m is not None
            return m.group(0), m.end()
        return tex[i], i + 1
    depth = 0
    for j in range(i, len(tex)):
        if tex[j] == "{" and (j == 0 or tex[j - 1] != "\\"):
            depth += 1
        elif tex[j] == "}" and (j == 0 or tex[j - 1] != "\\"):
            depth -= 1
            if depth == 0:
                return tex[i + 1 : j], j + 1
    return tex[i + 1 :], len(tex)


_MATRICES = {"matrix", "pmatrix", "bmatrix", "vmatrix"}


def _cells(body: str) -> list[list[str]]:
    """A matrix's body cut into rows at its top-level ``\\\\`` and each row into cells at ``&``."""
    rows: list[list[str]] = [[""]]
    depth, i = 0, 0
    while i < len(body):
        c = body[i]
        if body.startswith("\\begin{", i):
            depth += 1
        elif body.startswith("\\end{", i):
            depth -= 1
        if c == "\\" and body[i + 1 : i + 2] == "\\" and depth == 0:
            rows.append([""])
            i += 2
            continue
        if c == "&" and depth == 0:
            rows[-1].append("")
        else:
            rows[-1][-1] += body[i : i + 2] if c == "\\" else c
            i += 1 if c == "\\" else 0
        i += 1
    return rows


def width(tex: str) -> float:
    """The width of a formula set in display style, in ems (an estimate good to about 15 %)."""
    total, i = 0.0, 0
    while i < len(tex):
        c = tex[i]
        if c == "\\":
            m = _COMMAND.match(tex, i)
            assert m is not None
            name, i = m.group(1), m.end()
            if name in ("frac", "dfrac", "tfrac"):
                num, i = _group(tex, i)
                den, i = _group(tex, i)
                total += max(width(num), width(den)) + 0.3
            elif name == "text":
                body, i = _group(tex, i)
                total += 0.5 * len(body)
            elif name == "begin":
                env, i = _group(tex, i)
                close = tex.find(rf"\end{{{env}}}", i)
                if env in _MATRICES and close >= 0:
                    # a matrix is as wide as its widest row, each row its cells side by side a quad apart,
                    # with its brackets; never the sum of its rows, which are stacked
                    rows = _cells(tex[i:close])
                    total += max(sum(width(c) for c in r) + 1.0 * (len(r) - 1) for r in rows) + 0.8
                    i = close + len(rf"\end{{{env}}}")
            elif name == "end":
                _, i = _group(tex, i)
            elif name == "\\":
                total += 0.0
            elif name not in _ZERO:
                total += _WIDE.get(name, 0.6)
        elif c in "^_":
            body, i = _group(tex, i + 1)
            total += 0.7 * width(body)
        elif c in "{}&":
            i += 1
        elif c in "+-=<>":
            total += 1.5  # the operator and the space around it
            i += 1
        elif c == " ":
            i += 1
        else:
            total += 0.55
            i += 1
    return total


def _top_level_signs(tex: str) -> list[int]:
    """Indices of the binary ' + ' and ' - ' of tex outside braces and brackets (\\left( … \\right) or plain)."""
    out, depth, i = [], 0, 0
    while i < len(tex):
        if tex.startswith("\\left", i):
            depth += 1
            i += 5
            continue
        if tex.startswith("\\right", i):
            depth -= 1
            i += 6
            continue
        c = tex[i]
        if c == "\\":
            i += 2
            continue
        if c in "{(":
            depth += 1
        elif c in "})":
            depth -= 1
        elif depth == 0 and c in "+-" and tex[i - 1 : i] == " " and tex[i + 1 : i + 2] == " " and i > 1:
            out.append(i - 1)
        i += 1
    return out


def _lines(tex: str, limit: float) -> list[str]:
    """tex cut at its top-level signs into lines no wider than limit (where the terms allow)."""
    cuts = _top_level_signs(tex)
    if not cuts:
        return [tex]
    pieces, start = [], 0
    for c in cuts:
        pieces.append(tex[start:c])
        start = c + 1
    pieces.append(tex[start:])
    lines = [pieces[0]]
    for piece in pieces[1:]:
        if width(lines[-1] + " " + piece) > limit:
            lines.append(piece)
        else:
            lines[-1] += " " + piece
    return lines


def _stacked_fraction(rhs: str, limit: float) -> str | None:
    """``- \\frac{N}{D}`` with a long N: N's lines stacked over the bar."""
    m = re.match(r"(- )?\\frac", rhs)
    if not m:
        return None
    num, i = _group(rhs, m.end())
    den, j = _group(rhs, i)
    tail = rhs[j:]  # what may follow the quotient on its line: "\approx 5.75"
    if width(tail) > 12 or _top_level_signs(tail):
        return None
    lines = _lines(num, limit)
    if len(lines) < 2:
        return None
    return rf"{m.group(1) or ''}\frac{{{_block(lines)}}}{{{den}}}{tail}"


def broken(tex: str, limit: float = LIMIT) -> str:
    """An expression's LaTeX, broken across aligned lines when wider than ``limit`` ems (else unchanged)."""
    if width(tex) <= limit or r"\begin" in tex:
        return tex
    stacked = _stacked_fraction(tex, limit)
    if stacked is not None:
        return stacked
    lines = _lines(tex, limit)
    return _block(lines) if len(lines) > 1 else tex


def _block(lines: list[str]) -> str:
    """Lines in one aligned block, each after the first indented by a quad."""
    body = r" \\ ".join(("&" if k == 0 else "&\\quad ") + line for k, line in enumerate(lines))
    return rf"\begin{{aligned}}{body}\end{{aligned}}"


def _clauses(row: str) -> list[str]:
    """A row cut after each top-level ",\\quad" (ω² = …, shape (…)) and around words (\\text): its clauses."""
    out, depth, start, i = [], 0, 0, 0
    while i < len(row):
        if depth == 0 and row.startswith(",\\quad ", i):
            out.append(row[start : i + 1])
            start = i = i + len(",\\quad ")
            continue
        if depth == 0 and row.startswith("\\text{", i):
            # words between formulas (an erratum's "toward the origin; later") are a line of their own
            _, end = _group(row, i + len("\\text"))
            if row[start:i].strip():
                out.append(row[start:i].rstrip())
            out.append(row[i:end])
            start = i = end
            continue
        c = row[i]
        if c in "{(":
            depth += 1
        elif c in "})":
            depth -= 1
        i += 2 if c == "\\" else 1
    rest = row[start:].strip()
    return [c for c in out if c.strip()] + ([rest] if rest else [])


def broken_row(row: str, limit: float = LIMIT) -> list[str]:
    """A step's row ``lhs = rhs`` as rows to align: the first ``lhs = part``, the rest continuing under the
    right-hand side (``\\quad + …``); a stacked numerator when the right-hand side is one long quotient; an
    equation ``… = 0`` with a long left side as one block of lines ending in ``= 0``."""
    if width(row) <= limit:
        return [row]
    clauses: list[str] = []
    for clause in _clauses(row):
        # clauses side by side while they fit: "≈ 5.75, shape (…)" stays on one line when it can
        if clauses and width(clauses[-1] + " " + clause) <= limit:
            clauses[-1] += " " + clause
        else:
            clauses.append(clause)
    if len(clauses) > 1:
        first = broken_row(clauses[0], limit)
        rest = (c.removeprefix("\\quad ") for clause in clauses[1:] for c in broken_row(clause, limit))
        return [*first, *(rf"\quad {c}" for c in rest)]
    if r"\begin" in row:
        return [row]
    head, sep, rhs = row.rpartition(" = ")
    if not sep:
        head, rhs = "", row
    if sep and width(rhs) < 3 and width(head) > limit:
        lines = _lines(head, limit)
        return [_block([*lines[:-1], f"{lines[-1]} = {rhs}"])] if len(lines) > 1 else [row]
    stacked = _stacked_fraction(rhs, max(limit - width(head), limit / 2))
    if stacked is not None:
        return [f"{head}{sep}{stacked}"]
    lines = _lines(rhs, max(limit - width(head), limit / 2))
    if len(lines) < 2:
        return [row]
    return [f"{head}{sep}{lines[0]}", *(rf"\quad {line}" for line in lines[1:])]


def single(row: str, limit: float = LIMIT) -> str:
    """A row broken as ``broken_row`` does, as one formula (its lines in one aligned block)."""
    rows = broken_row(row, limit)
    if len(rows) == 1:
        return rows[0]
    return _block([rows[0], *(r.removeprefix("\\quad ") for r in rows[1:])])
