"""A typed system's set-up, as its students read it above the boxes: the instructor's words (what each coordinate
is, where it is measured from, where U = 0) and what the system is defined by, typeset as it was typed.

A system the instructor types is a name and expressions; a student cannot answer "T = ?" without knowing what x
is and from where it is measured.  So an assigned system needs a ``setup`` text (refused with what to write when
missing), and the page shows, under it, the system's defining data printed as a textbook prints it (the
particles' masses and positions, T, U or L, the generalized forces) from the parser's reading, never evaluated
(app/engine/tutor/typed_latex.py: pure Python, no SymPy).  What an assigned step asks for is not shown: a T step hides T
(and L, which holds it), a U step hides U (and L), an L step hides T, U and L; the positions are the geometry,
shown always.
"""

from __future__ import annotations

from typing import Any

from app.engine.display.names import latex as name_latex
from app.engine.tutor.typed_latex import typed_latex
from app.errors import Refused
from app.service.tutor.checking import declared

MAX_SETUP = 1000  # characters of a set-up
# the expressions each step would give away if shown, by the system's field
_GIVES_AWAY = {"kinetic": {"kinetic", "lagrangian"}, "potential": {"potential", "lagrangian"},
               "lagrangian": {"kinetic", "potential", "lagrangian"}}
_SYMBOL = {"kinetic": "T", "potential": "U", "lagrangian": "L"}
_AXES = ("x", "y", "z")
SETUP_ADVICE = (
    "say what each coordinate is, where it is measured from and where U = 0 (for example: x is the stretch of the "
    "spring from its natural length; U = 0 at x = 0); students read it above the boxes"
)


def checked_setup(i: int, item: dict[str, Any]) -> str | None:
    """The item's set-up as stored: required (not blank) for a typed system, refused for a scene (its page says it)."""
    text = (item.get("setup") or "").strip()
    if item.get("system") is None:
        if text:
            raise Refused(f"items.{i}.setup: a scene's page sets it up; a set-up is for a system you type", "",
                          ("items", i, "setup"))
        return None
    if not text:
        raise Refused(f"items.{i}.setup: a system you type needs its set-up: {SETUP_ADVICE}", "", ("items", i, "setup"))
    return text


def givens(item: dict[str, Any]) -> list[dict[str, str]]:
    """The typed system's defining data as the students see it: ``[{"label", "latex"}]`` (label: plain words, may
    be empty), without what an assigned step asks for."""
    if item.get("system") is None:
        return []
    try:
        user = declared(item["system"])
    except Refused:  # stored before a rule that now refuses it: its students still get the set-up's words
        return []
    parsed = user.parsed or {}
    hidden = set().union(*(_GIVES_AWAY.get(s["step"], set()) for s in item.get("steps") or []))
    out: list[dict[str, str]] = []
    for i, particle in enumerate(user.particles):
        label = f"Particle {i + 1}" + (f", {particle.label}" if particle.label else "")
        axes = ",\\ ".join(_AXES[: len(particle.position)])
        place = ",\\ ".join(typed_latex(parsed[("particles", i, "position", j)]) for j in range(len(particle.position)))
        mass = typed_latex(parsed[("particles", i, "mass")])
        out.append({"label": label, "latex": rf"\text{{mass }} {mass},\quad ({axes}) = \left({place}\right)"})
    for field in ("kinetic", "potential", "lagrangian"):
        if (field,) in parsed and field not in hidden:
            out.append({"label": "", "latex": f"{_SYMBOL[field]} = {typed_latex(parsed[(field,)])}"})
    for name, _text in user.forces:
        out.append({"label": "Generalized force", "latex": f"Q_{{{name_latex(name)}}} = {typed_latex(parsed[('forces', name)])}"})
    return out
