"""Declarations of mechanical systems: plain data, no logic.

A system is written the way a textbook states it: names of generalized
coordinates, named parameters, and the mechanics in one of three forms
(particles with a potential, T and U, or L itself).  Expressions are strings in
the project's symbol convention: a coordinate ``q``, its velocity ``q_dot``,
time ``t`` and parameters by name.  The engine parses and derives; nothing in
this module computes anything.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Parameter:
    """A named constant of the system with a default and an allowed range."""

    name: str
    default: float
    unit: str = ""
    min: float | None = None
    max: float | None = None
    description: str = ""


@dataclass(frozen=True)
class Particle:
    """A point mass at a Cartesian position given as expressions of q and t."""

    mass: str
    position: tuple[str, str, str]
    label: str = ""


@dataclass(frozen=True)
class System:
    """The mechanics of a system, in exactly one of three forms.

    * ``particles`` + ``potential``: T is derived from the particles' velocities;
    * ``kinetic`` + ``potential``: T and U given directly;
    * ``lagrangian``: L given directly (then E cannot be told apart from h).

    ``forces`` maps a coordinate to its generalized non-conservative force Q_k,
    so that the equations read d/dt dL/dq_dot - dL/dq = Q.  ``nonnegative``
    names coordinates that are distances (a radius never goes below zero).
    """

    coordinates: tuple[str, ...]
    parameters: tuple[Parameter, ...] = ()
    particles: tuple[Particle, ...] = ()
    kinetic: str | None = None
    potential: str | None = None
    lagrangian: str | None = None
    forces: dict[str, str] = field(default_factory=dict)
    nonnegative: tuple[str, ...] = ()


@dataclass(frozen=True)
class Scene:
    """A chapter example: a system plus what the page and API say about it."""

    id: str
    title: str
    section: str
    system: System
    summary: str = ""
    statement: str = ""
    figure: str = ""
    initial: dict[str, float] = field(default_factory=dict)
    t_end: float = 10.0
    panels: tuple[str, ...] = ()
    errata: tuple[dict[str, str], ...] = ()
