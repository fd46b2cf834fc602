"""What a practice page needs for one system: each step to try, in the chapter's order, with its
prompt, the names an answer may use, and the engine's own step (revealed on request).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.derivation.dimensions import system_dimensions
from app.engine.display.names import latex, said_all, unicode
from app.engine.document.notation import inertia, letter, practice_axes
from app.engine.document.notation import text as frequency_letter
from app.engine.document.report import Printer, display
from app.engine.tutor.check import conserved_momenta, exercises, offered_names, problem
from app.engine.tutor.check_problem import asked_equilibrium, where_asked
from app.engine.tutor.equilibria_notes import equilibria_notes
from app.engine.tutor.mistake_positions import body_name, component_keys, points
from app.engine.tutor.mistakes import POINTERS, has_springs, pointer, without_springs


def exercise_json(d: Derivation) -> dict[str, Any]:
    """What a practice page needs: each step to try, its prompt and the engine's answer, and how names print."""
    pr = Printer({**d.table.latex_names(), **{p: sp.latex(p) for p in conserved_momenta(d)}})
    items = []
    for step, name in exercises(d):
        pb = problem(d, step, name, mistakes=False)  # the prompts need no catalogue of mistakes
        shown = [display(t) for t in pb.truths]
        if step == "equation":
            latex = f"{pr.tex(shown[0])} = 0"
        elif step == "omega_squared":
            # one equilibrium asked about, named in the step's title; the others are said in the notes
            latex = rf"{_lhs(step, name, pr, d)} = {pr.tex(shown[0])}\ \text{{at}}\ {_where_tex(d, pr)}"
        else:
            latex = f"{_lhs(step, name, pr, d)} = {pr.tex(shown[0])}"
        answer: dict[str, Any] = {"sympy": sp.sstr(shown[0]), "latex": latex}
        if step == "omega_squared":
            # whether the equilibrium is stable, and where the others are, exist and are stable (sentences that wrap)
            answer["notes"] = equilibria_notes(d)
        item = {
            "step": step,
            "coordinate": name,
            "title": f"Position: {pb.label}" if step == "position" else _title(_about(d, step, pb.label)),
            "lhs": _lhs(step, name, pr, d),
            "names": offered_names(step, pb.kinds),
            # the names as the page prints them, each with how it is typed once (θ̇ (type theta_dot))
            "names_said": said_all(offered_names(step, pb.kinds)),
            "answer": answer,
        }
        if step == "acceleration":
            item["acceleration"] = unicode(f"{name}_ddot")  # θ̈, as the box's own lhs prints it
        if step == "position":
            item["note"] = position_note(d)
        items.append(item)
    symbols = {
        s.name: pr.tex(s) for s in (*d.table.q, *d.table.qd, *d.table.qdd, *d.table.params, *conserved_momenta(d))
    }
    # the rule of each step, without its words about springs where the system has none
    springs = has_springs(d)
    # (the frequency's rule in the document's letter: Ω² where ω is a parameter)
    said = {step: pointer(step, frequency_letter("frequency", d), inertia(d)) for step in POINTERS}
    # the positions' rule in the step's letters for the axes (ξ across and ζ up where a coordinate is named z)
    x, _, z = (unicode(n) for n in practice_axes(d))
    said["position"] = said["position"].replace("x across and z up", f"{x} across and {z} up")
    rules = {step: rule if springs else (without_springs(rule) or rule) for step, rule in said.items()}
    return {"exercises": items, "symbols": {**symbols, "t": "t"}, "rules": rules}


# what a positions step is judged against, said on the step; the set-up figure draws no axes, so the directions
# and the origin are said in words (the origin is the one the problem statement names)
POSITION_NOTE = (
    "Measure {x} across and {z} up ({y} is the third direction), from the origin the problem statement names; a position "
    "measured from another origin, the correct one plus a constant length ({example}never a bare number), is "
    "accepted as equivalent.{heights}"
)
METRE = {"m": Fraction(1)}


def position_note(d: Derivation) -> str:
    """The positions' rule in this system's words: its own length as the example of a shift of origin (l₁, d; no
    R where the scene has none), and coordinates named y said to be heights where they are (the pulley's y₁, y₂,
    which a reader could take for the third direction)."""
    known = system_dimensions(d)
    lengths = [s for s in d.table.params if known.get(s) == METRE]
    example = f"such as + {unicode(lengths[0].name)}, " if lengths else "with its units, "
    # a coordinate named y that moves a body up and down (in a z component) and along no y component is a height
    positions = d.mechanics.positions
    heights = [
        q
        for q in d.table.q
        if q.name.rstrip("0123456789") == "y"
        and any(r[2].has(q) for r in positions)
        and not any(r[1].has(q) for r in positions)
    ]
    said = ", ".join(unicode(q.name) for q in heights)
    if heights:
        said = f" Here {said} {'are heights' if len(heights) > 1 else 'is a height'} (measured up, along z), not the third direction."
    x, y, z = (unicode(n) for n in practice_axes(d))
    return POSITION_NOTE.format(heights=said, example=example, x=x, y=y, z=z)


def _title(label: str) -> str:
    """A heading: the label with a capital, unless it opens with a symbol (ω² stays ω²)."""
    return label[0].upper() + label[1:] if label[0].isascii() else label


def _about(d: Derivation, step: str, label: str) -> str:
    """The ω² step names the equilibrium it asks about ("ω² of small oscillations about θ = 0")."""
    return f"{label} about {where_asked(d)}" if step == "omega_squared" else label


def _where_tex(d: Derivation, pr: Printer) -> str:
    red = d.reduction
    r = d.table.q[d.table.names.index(red.coordinate)]  # type: ignore[union-attr]
    return f"{pr.tex(r)} = {pr.tex(asked_equilibrium(d).position)}"


def _body_tex(d: Derivation, i: int) -> str:
    """A body's name as a subscript, its words as text and a parameter in it as mathematics: \\text{mass } m_{1}
    (KaTeX sets no Unicode subscript ₁ in text), \\text{left mass}."""
    names = {unicode(s.name): tex for s, tex in d.table.latex_names().items() if s in d.table.params}
    out: list[str] = []
    words: list[str] = []
    for w in [*body_name(d, i).removeprefix("the ").split(" "), ""]:
        if w and w not in names:
            words.append(w)
            continue
        # the words so far as one text, then the parameter (or the end)
        if words:
            out.append(rf"\text{{{' '.join(words)}{' ' if w else ''}}}")
        if w:
            out.append(names[w])
        words = []
    return " ".join(out)


def _lhs(step: str, name: str | None, pr: Printer, d: Derivation) -> str:
    if step == "position":
        # x, or x with the body's name where there are several (never x₂, which may be a coordinate's name)
        i, a = next((i, a) for key, i, a in component_keys(d) if key == name)
        many = len(points(d)) > 1
        return latex(practice_axes(d)[a]) + (f"_{{{_body_tex(d, i)}}}" if many else "")
    if name is not None:
        q = d.table.q[d.table.names.index(name)]
        qdd = d.table.qdd[d.table.names.index(name)]
    return {
        "kinetic": "T",
        "potential": "U",
        "lagrangian": "L",
        "momentum": f"p_{{{pr.tex(q)}}}" if name else "",
        "equation": "0",
        "acceleration": pr.tex(qdd) if name else "",
        "hamiltonian": "h",
        "omega_squared": f"{letter('frequency', d)}^2",
    }[step]
