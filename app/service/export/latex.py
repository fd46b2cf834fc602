"""A LaTeX document: the problem, every step of the derivation in ``align*`` (long rows in ``dmath*``), the results.

It uses only the article class, amsmath, amssymb, geometry and breqn, so it compiles
with Debian's texlive-latex-base and texlive-latex-recommended.  Formulas are
the engine's LaTeX (the page's textbook forms, printed by SymPy from validated
expressions); every piece of prose goes through ``latex_text``.
"""

from __future__ import annotations

import re

import sympy as sp

from app.engine.display.breaking import LIMIT, broken_row
from app.service.export.source import Source
from app.service.export.text import latex_text

PREAMBLE = r"""\documentclass[11pt]{article}
\usepackage[T1]{fontenc}
\usepackage{amsmath,amssymb}
\usepackage[margin=2cm]{geometry}
\usepackage{breqn}
\allowdisplaybreaks
% SymPy may print these for a few symbol names; plain fallbacks keep the document compiling
\providecommand{\mathscr}{\mathcal}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5em}
"""


# A row longer than this (characters of LaTeX) that the engine's line breaking could not break is set with
# breqn's dmath*, which breaks it across lines; breqn comes with texlive-latex-recommended.  Rows holding an
# environment (a matrix, a stacked numerator) stay in align*.
LONG_ROW = 250
# ems a row may take on the page (11 pt, 2 cm margins): the engine's own limit, so that the export breaks
# rows where the page does (app.engine.display.breaking)
PAGE_EMS = LIMIT


def _split(latex: str) -> list[str]:
    """The engine's rows, without their alignment marks (its aligned block joins them with ' \\\\ '; an
    environment inside a row, a matrix or a stacked numerator, keeps its own rows)."""
    opening, closing = r"\begin{aligned}", r"\end{aligned}"
    if not (latex.startswith(opening) and latex.endswith(closing)):
        return [latex]
    body = latex[len(opening) : -len(closing)]
    rows, depth, start = [], 0, 0
    for m in re.finditer(r"\\begin\{|\\end\{| \\\\ ", body):
        if m.group(0) == r"\begin{":
            depth += 1
        elif m.group(0) == r"\end{":
            depth -= 1
        elif depth == 0:
            rows.append(body[start : m.start()])
            start = m.end()
    rows.append(body[start:])
    return [row.replace(" &= ", " = ", 1) if " &= " in row else row.removeprefix("&") for row in rows]


def _braced(row: str) -> str:
    # U_\text{eff} -> U_{\text{eff}}: breqn makes _ take exactly one braced argument
    return re.sub(r"_\\text\{([^{}]*)\}", r"_{\\text{\1}}", row)


def _marked(row: str) -> str:
    # a continuation (\quad + …) or a block of lines starts at the alignment column
    if " = " in row and not row.startswith(("\\quad", "\\begin")):
        return row.replace(" = ", " &= ", 1)
    return "&" + row


def _display(rows: list[str]) -> str:
    """Rows as displays: runs of short rows in one align* (aligned at their first '='), long rows broken by dmath*."""
    blocks: list[str] = []
    run: list[str] = []

    def close() -> None:
        # a run holding a block of lines (an equation broken across lines) is set flush left, not at its '='
        flush = any(r.startswith("\\begin{aligned}") for r in run)
        marked = ["&" + r for r in run] if flush else [_marked(r) for r in run]
        blocks.append("\\begin{align*}\n" + " \\\\\n".join(marked) + "\n\\end{align*}")
        run.clear()

    for row in map(_braced, (line for given in rows for line in broken_row(given, PAGE_EMS))):
        if len(row) > LONG_ROW and "\\begin{" not in row:
            if run:
                close()
            blocks.append("\\begin{dmath*}\n" + row + "\n\\end{dmath*}")
        else:
            run.append(row)
    if run:
        close()
    return "\n".join(blocks)


def _align(latex: str) -> str:
    return _display(_split(latex))


def _parameters(source: Source) -> list[str]:
    if not source.parameters:
        return []
    lines = [r"\begin{center}\begin{tabular}{llll}", r"parameter & meaning & value & unit \\ \hline"]
    for p in source.parameters:
        lines.append(
            rf"${_symbol(p.name)}$ & {latex_text(p.description)} & {latex_text(repr(p.default))} & "
            rf"{latex_text(p.unit)} \\"
        )
    lines.append(r"\end{tabular}\end{center}")
    return ["\n".join(lines)]


def _symbol(name: str) -> str:
    """A declared name (letters and digits, checked by the engine) as SymPy typesets it."""
    return sp.latex(sp.Symbol(name))


def _results(source: Source) -> list[str]:
    doc, table = source.document, source.derivation.table
    out = [r"\section*{Results}", r"\subsection*{Equations of motion}"]
    out.append(_display([eq.latex for eq in doc.equations_of_motion]))
    tex = table.latex_names()
    out.append("and, solved for the accelerations,")
    out.append(
        _display(
            [f"{tex[a]} = {doc.accelerations[q].latex}" for q, a in zip(table.names, table.qdd, strict=True)]
        )
    )
    out.append(r"\subsection*{Generalized momenta}")
    out.append(
        _display([f"p_{{{tex[s]}}} = {doc.momenta[q].latex}" for q, s in zip(table.names, table.q, strict=True)])
    )
    out.append(r"\subsection*{Conserved quantities}")
    if doc.conserved:
        for c in doc.conserved:
            out.append(_align(f"{c.latex_name} = {c.latex}"))
            out.append(latex_text(c.reason))
    else:
        out.append("None: no coordinate is cyclic, and h changes with time.")
    out += [r"\subsection*{Is $h$ equal to $E$?}", latex_text(doc.hamiltonian_energy_reason)]
    eff = doc.effective_potential
    if eff:
        out += [r"\subsection*{Effective potential}", _align(r"U_\text{eff} = " + eff.potential.latex)]
    forces = doc.constraint_forces
    if forces:
        out.append(r"\subsection*{Forces of constraint}")
        for f in forces:
            out.append(latex_text(f"{f.name}: {f.convention}"))
            out.append(_align("F = " + f.latex))
    return out


def latex(source: Source) -> str:
    doc = source.document
    tex = source.derivation.table.latex_names()
    symbols = [*source.derivation.table.q, *source.derivation.table.qd]
    start = ", ".join(f"${tex[s]} = {x!r}$" for s, x in zip(symbols, source.initial, strict=True))
    body = [
        rf"\title{{{latex_text(source.title)}}}",
        r"\author{Exported by Lagrange}"
        + (rf"\date{{Section {latex_text(source.section)}}}" if source.section else r"\date{}"),
        r"\begin{document}",
        r"\maketitle",
        r"\section*{The problem}",
        latex_text(source.statement),
    ]
    if source.figure:
        body.append(latex_text(source.figure))
    body += _parameters(source)
    body.append(f"The simulation starts from {start} and runs to $t = {source.t_end!r}$ s.")
    body.append(r"\section*{Derivation}")
    for step in doc.steps:
        body += [
            rf"\subsection*{{{latex_text(step.title)}}}",
            latex_text(step.explanation),
            _align(step.latex),
        ]
    body += _results(source)
    if source.errata:
        body.append(r"\section*{Errata: where the chapter goes wrong}")
        body.append(r"\begin{itemize}")
        for e in source.errata:
            # both formulas typeset, as on the page (never as code)
            chapter, correct = e.chapter_latex, e.correct_latex
            if e.chapter_words and correct:
                # the chapter's fault is in its words: they are quoted as prose
                body.append(
                    rf"\item {latex_text(e.chapter)} Correct is {_display([correct])}"
                    + latex_text(e.reason)
                )
            elif chapter and correct:
                body.append(
                    # an approximation (small swings) is what holds, never "correct" as it stands
                    rf"\item The chapter writes {_display([chapter])} "
                    + ("what holds is" if e.approximate else "correct is")
                    + rf" {_display([correct])}"
                    + latex_text(e.reason)
                )
            else:
                body.append(
                    rf"\item The chapter writes \texttt{{{latex_text(e.chapter)}}}; correct is "
                    rf"\texttt{{{latex_text(e.correct)}}}. {latex_text(e.reason)}"
                )
        body.append(r"\end{itemize}")
    body.append(r"\end{document}")
    return PREAMBLE + "\n\n".join(body) + "\n"
