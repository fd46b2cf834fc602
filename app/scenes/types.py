"""Declarations of mechanical systems: plain data, no logic.

A system is written the way a textbook states it: names of generalized
coordinates, named parameters, and the mechanics in one of three forms
(particles with a potential, T and U, or L itself).  Expressions are strings in
the project's symbol convention: a coordinate ``q``, its velocity ``q_dot``,
time ``t`` and parameters by name.  The engine parses and derives; nothing in
this module computes anything.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from app.limits import DEFAULT_T_END


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
class Body:
    """A rigid body moving in the x–z plane: its kind, mass, size, where its centre is and how it is turned.

    ``kind`` is one of ``rod``, ``disc``, ``ring``, ``sphere`` (uniform; the engine holds each kind's moment of
    inertia about its centre, app/engine/equations/bodies.py).  ``size`` is the rod's length, or the radius of the disc,
    ring or sphere.  ``centre`` is the centre of mass as expressions of q and t, ``angle`` the body's rotation
    about the axis through its centre normal to the plane (the y axis), so that its angular velocity is
    ω = d(angle)/dt.  ``label`` names it in the derivation ("rod", "pulley").
    """

    kind: str
    mass: str
    size: str
    centre: tuple[str, str, str]
    angle: str
    label: str = ""


@dataclass(frozen=True)
class Constraint:
    """A holonomic constraint g = 0 in Cartesian form, whose force the engine derives.

    ``expression`` is g written in the particles' Cartesian coordinates (``x, y, z``
    for a single particle; ``x1, y1, z1, x2, ...`` for several), parameters and
    ``t``.  By Lagrange's method the constraint pushes particle i with the force
    lambda * grad_i g.  The engine reports, for the particle numbered ``on``
    (from 1), the signed size of that force along grad_i g: positive when the
    force points the way g increases, whatever the normalisation of g.
    ``convention`` says in words what positive means; ``slack_when_negative``
    marks one-sided constraints (a string, a surface one rests on) that cannot
    pull, so a negative value means the constraint has gone slack.
    """

    name: str
    expression: str
    convention: str
    on: int = 1
    slack_when_negative: bool = False


@dataclass(frozen=True)
class CoordinateChange:
    """New generalized coordinates defined as expressions of the old ones.

    ``definitions`` gives each new coordinate (in the order of ``coordinates``)
    as a function of the old coordinates, parameters and ``t``; the engine
    inverts the map, substitutes it into the declaration and derives again.
    ``relative`` optionally names the new coordinate whose inertia is a reduced
    mass (the relative coordinate of a two-body problem).
    """

    coordinates: tuple[str, ...]
    definitions: tuple[str, ...]
    explanation: str = ""
    relative: str | None = None


@dataclass(frozen=True)
class System:
    """The mechanics of a system, in exactly one of three forms.

    * ``particles`` and/or ``bodies`` + ``potential``: T is derived from the particles' velocities and each rigid
      body's translation and rotation;
    * ``kinetic`` + ``potential``: T and U given directly;
    * ``lagrangian``: L given directly (then E cannot be told apart from h).

    ``forces`` maps a coordinate to its generalized non-conservative force Q_k,
    so that the equations read d/dt dL/dq_dot - dL/dq = Q.  ``nonnegative``
    names coordinates that are distances (a radius never goes below zero).

    Optional Cartesian extras: ``constraints`` (holonomic constraints whose
    forces the engine derives by Lagrange multipliers) with
    ``cartesian_potential``, the same U written in the particles' Cartesian
    coordinates (needed for the force's component along each constraint);
    ``coordinate_change``, a second set of coordinates in which the engine
    derives the motion again.
    """

    coordinates: tuple[str, ...]
    parameters: tuple[Parameter, ...] = ()
    particles: tuple[Particle, ...] = ()
    bodies: tuple[Body, ...] = ()
    kinetic: str | None = None
    potential: str | None = None
    lagrangian: str | None = None
    forces: dict[str, str] = field(default_factory=dict)
    nonnegative: tuple[str, ...] = ()
    constraints: tuple[Constraint, ...] = ()
    cartesian_potential: str | None = None
    coordinate_change: CoordinateChange | None = None
    # SymPy expressions already built from this declaration's texts, by text (a user system's, built once in the
    # worker from what the web process read: docs/parsing.md); the engine reads any other text itself
    built: Mapping[str, Any] = field(default_factory=dict, compare=False, repr=False)


@dataclass(frozen=True)
class Erratum:
    """A formula the chapter gets wrong, the correct one, and why.

    ``correct`` reads ``lhs = rhs`` with ``rhs`` in the project's symbol
    convention; ``check`` names the engine result it must equal (the tests
    compare the two), for example ``acceleration:theta``.
    """

    chapter: str
    correct: str
    reason: str
    check: str
    # the chapter's fault is in its words (its statement), not a formula: ``chapter`` is prose, shown as text
    words: bool = False
    # where ``correct`` holds only approximately, the condition for it in LaTeX (|\theta| \ll 1): the table then
    # prints lhs ≈ rhs and the condition, never "=" alone
    approximate_for: str = ""


@dataclass(frozen=True)
class Event:
    """Where the set-up ends: the run stops the first time ``expression`` falls below zero.

    ``expression`` is a function of the coordinates, their rates, ``t`` and the
    parameters, positive while the set-up holds (the block still on its ramp);
    ``message`` says in words what happened there (the page shows it with the time).
    """

    name: str
    expression: str
    message: str


@dataclass(frozen=True)
class Scene:
    """A chapter example: a system plus what the page and API say about it.

    ``panels`` names the optional panels the page should add (the vocabulary and
    which panels are optional: ``app/viz/panels.py``; the others appear wherever
    the derivation supports them).  ``beyond_chapter`` marks a scene that goes past the chapter (normal modes of
    several coordinates, chaos); its ``section`` names the chapter section it
    builds on, and the contents list it under a heading of its own.

    How the scene is drawn and explained is its own data too: ``family`` names its drawing (the set-up
    diagram of ``app/viz/diagrams.py`` and the animation of ``app/viz/mechanism.py``, both kept per family,
    so scenes drawn alike share one), ``marks`` the family's optional marks it adds (``drag``: the damping
    force's arrow), and ``reasons`` (from ``app/scenes/reasons.py``) explains its derivation's steps in its
    own terms, by step key.  A scene without a family is drawn from its particles, like a user's system.

    ``answers`` names the steps (by key, as ``reasons`` does: ``normal-modes`` matches every
    ``normal-modes:N``) that answer what the statement asks; the page's Results box states them, so an
    answer is never only inside the folded bookkeeping.
    """

    id: str
    title: str
    section: str
    system: System
    summary: str = ""
    statement: str = ""
    figure: str = ""
    initial: dict[str, float] = field(default_factory=dict)
    t_end: float = DEFAULT_T_END
    panels: tuple[str, ...] = ()
    errata: tuple[Erratum, ...] = ()
    beyond_chapter: bool = False
    events: tuple[Event, ...] = ()
    family: str = ""
    marks: tuple[str, ...] = ()
    reasons: Mapping[str, str] = field(default_factory=dict)
    answers: tuple[str, ...] = ()
    # the limits the statement asks the accelerations compared with, a parameter and the value it goes to (the
    # massive pulley's M → 0, the massless pulley): the engine's "limits" step states each acceleration and its
    # limit, with their values at the defaults
    limits: tuple[tuple[str, float], ...] = ()
    # where the small-oscillation frequency is exact at every amplitude, the sentence saying so and why (the
    # small-oscillation panel says it in place of "holds as the amplitude goes to zero")
    exact_frequency: str = ""
    # what each coordinate is, in the set-up's words: the Symbols table's meaning of it ("angle of the string
    # from the downward vertical"), in place of the bare "generalized coordinate" a typed system gets
    coordinate_meanings: Mapping[str, str] = field(default_factory=dict)
    # what a reader should know about the simulation itself (how far a run can be trusted), printed beside the
    # simulation's settings, never in the statement of the problem
    run_note: str = ""
    # a chaotic scene: its largest Lyapunov exponent is measured at the default start over this many seconds
    # (app/service/simulations/lyapunov.py), and the sentence saying it opens the run note
    lyapunov_seconds: float = 0.0
    # angles measured from the upward vertical (the spherical pendulum's θ): where a steady motion gives one's
    # value, its angle from the downward vertical, π minus it, is given beside it
    upward_angles: tuple[str, ...] = ()
    # a position the statement names that the constraints fix by the coordinates (the pulley's middle mass,
    # Y = −(y1 + y2)/2 − c), by name, with what it is: its acceleration, derived from the coordinates', is printed
    # beside theirs in the accelerations step and in Results, as the statement asks for it; the Symbols table says
    # what the letter is
    dependent: Mapping[str, tuple[str, str]] = field(default_factory=dict)
