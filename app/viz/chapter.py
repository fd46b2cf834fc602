"""The chapter's table of contents: sections 4.1 to 4.7 and 4.9 (the chapter has no 4.8) in our own words.

Each scene is listed under the section it belongs to (its declared
``section``); a section that teaches something a scene's panels show (a force
of constraint, a conserved momentum, h against E, small oscillations) also
points to those scenes.  Scenes marked ``beyond_chapter`` are listed under a
heading of their own after the chapter's sections (and, as "also shown in",
under the section they build on).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Section:
    number: str
    title: str
    blurb: str
    shown_by: tuple[str, ...] = ()  # panels that illustrate the section in other scenes


SECTIONS: tuple[Section, ...] = (
    Section(
        "4.1",
        "Forces no potential can describe",
        "Friction and drag enter the Euler–Lagrange equations as generalized forces Q on the right-hand side; "
        "the energy then leaks away at the rate those forces do work.",
    ),
    Section(
        "4.2",
        "Constraints, generalized coordinates and the forces that enforce them",
        "A constraint removes a coordinate. Lagrange multipliers bring back the force that holds it, "
        "such as the tension in a pendulum's string.",
        shown_by=("constraint-force",),
    ),
    Section(
        "4.3",
        "The Lagrangian and the Euler–Lagrange equations",
        "Write T and U in coordinates that respect the constraints, form L = T − U, and one equation per "
        "coordinate follows from the stationary action.",
    ),
    Section(
        "4.4",
        "Generalized momenta and cyclic coordinates",
        "When a coordinate is missing from L its momentum is conserved, and the motion reduces to one "
        "coordinate in an effective potential.",
        shown_by=("momenta",),
    ),
    Section(
        "4.5",
        "Several particles",
        "Centre of mass and reduced mass, strings that tie bodies together, and a wedge that recoils under "
        "the block sliding on it.",
    ),
    Section(
        "4.6",
        "The energy function h = Σ p q̇ − L",
        "The quantity conserved when L does not depend on time explicitly, built from the momenta and the Lagrangian.",
    ),
    Section(
        "4.7",
        "When h is not the energy",
        "A constraint that moves with time feeds energy in or out: h stays constant while E changes.",
        shown_by=("h-vs-e",),
    ),
    Section(
        "4.9",
        "Small oscillations about an equilibrium",
        "Near a minimum of the effective potential every system swings like a spring: ω² is U_eff″ over the "
        "effective inertia (a mass for a length, a moment of inertia for an angle).",
        shown_by=("small-oscillations",),
    ),
)

BEYOND = Section(
    "+",
    "Beyond the chapter",
    "Where a course goes next: normal modes of several coordinates, beats, Hamilton's equations and chaos.",
)

_NUMBER = re.compile(r"4\.\d")


def _listed(numbers: list[str]) -> str:
    """Section numbers as a reader says them, runs joined: 4.1, …, 4.7, 4.9 -> "4.1 to 4.7 and 4.9"."""
    runs: list[list[int]] = []
    for k in sorted(int(n.split(".")[1]) for n in numbers):
        if runs and k == runs[-1][-1] + 1:
            runs[-1].append(k)
        else:
            runs.append([k])
    said = [f"4.{r[0]} to 4.{r[-1]}" if len(r) > 2 else ", ".join(f"4.{k}" for k in r) for r in runs]
    return said[0] if len(said) == 1 else ", ".join(said[:-1]) + " and " + said[-1]


# What "the chapter" is, said once for every page that refers to it; its sections are the ones listed above (it
# has no 4.8)
ABOUT = (
    f"The chapter is a set of lecture notes on Lagrangian mechanics (sections {_listed([s.number for s in SECTIONS])}"
    "): generalized coordinates and constraints, the Euler–Lagrange equations from Hamilton's principle, generalized "
    "momenta and cyclic coordinates, systems of particles, and the Hamiltonian against the energy, each taught "
    "through worked examples. Every scene here is one of those examples, derived again step by step from its Lagrangian. "
    "The notes are unpublished (a student's summary of a lecture course), so a page's section number points into "
    "them only; a course taught from another book (Taylor, Morin) can ignore both the numbers and the table at the "
    "foot of each page of where the notes print a formula wrongly."
)


def section_numbers(section: str) -> list[str]:
    """The section numbers a scene's ``section`` text names ("4.6–4.7" -> ["4.6", "4.7"])."""
    found = _NUMBER.findall(section or "")
    if len(found) == 2 and ("–" in section or "-" in section):
        lo, hi = int(found[0][2]), int(found[1][2])
        return [f"4.{k}" for k in range(lo, hi + 1)]
    return found


def table_of_contents(scenes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Sections in order, each with its own scenes and the scenes that illustrate it elsewhere."""
    toc = []
    chapter = [s for s in scenes if not s.get("beyond_chapter")]
    for section in SECTIONS:
        own = [s for s in chapter if section.number in section_numbers(s["section"])[:1]]
        also = [
            s
            for s in scenes
            if s not in own
            and (section.number in section_numbers(s["section"]) or any(p in s["panels"] for p in section.shown_by))
        ]
        toc.append(
            {"number": section.number, "title": section.title, "blurb": section.blurb, "scenes": own, "also": also}
        )
    beyond = [s for s in scenes if s.get("beyond_chapter")]
    if beyond:
        toc.append(
            {"number": BEYOND.number, "title": BEYOND.title, "blurb": BEYOND.blurb, "scenes": beyond, "also": []}
        )
    return toc
