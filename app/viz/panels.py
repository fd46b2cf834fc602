"""The panels a page can show: the one list of names, titles, explanations and availability rules.

A panel is shown when its rule holds for the derivation.  Most panels are shown
wherever their rule holds; an ``optional`` one also needs the scene (or the
playground) to ask for it in its ``panels`` declaration, because it teaches
something only some scenes are about (the effective potential of the chapter's
section 4.4, a Poincaré section).  The templates read titles and texts from
here, the page model evaluates the rules, and the browser draws the names it
is given (static/js/plots.js maps each name to its drawing).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from app.engine.document.model import Document, NormalModesAt
from app.viz.exprtree import document_tree, evaluate, leaves


@dataclass(frozen=True)
class Facts:
    """What the rules look at: the derivation document and what the page model built from it."""

    doc: Document
    reduction: dict[str, Any] | None  # the page's one-coordinate reduction (expression trees), if any
    mechanism_dim: int | None  # 2 or 3 when the mechanism can be drawn
    scene: bool  # a chapter scene (with a work-precision report), not a user's system

    @property
    def dof(self) -> int:
        return len(self.doc.coordinates)

    @property
    def conservative(self) -> bool:
        """No generalized force and no explicit time: h is conserved."""
        return not self.doc.generalized_forces and self.doc.hamiltonian_conserved


def constant_accelerations(doc: Document) -> bool:
    """Whether every acceleration is a constant (no coordinate, velocity or t in it): motion in t².

    Such a motion is integrated exactly by any method of order two or more, so an error
    against run time chart would show round-off and timing noise only."""
    q = doc.coordinates
    moving = [*q, *(f"{c}_dot" for c in q), "t"]
    names = [*moving, *doc.parameters]
    trees = [document_tree(pair, names) for pair in doc.accelerations.values()]
    # no closed form (M⁻¹f kept factored, a large system) is never constant here
    return bool(trees) and all(t is not None and not (leaves(t) & set(moving)) for t in trees)


def oscillating_equilibria(doc: Document) -> list[NormalModesAt]:
    """Equilibria at rest (not steady motions of a reduction) with at least one mode that oscillates."""
    return [e for e in doc.normal_modes if e.stable and not e.momenta and any(m.omega_squared > 0 for m in e.modes)]


def linear_equations(doc: Document) -> bool:
    """Whether every acceleration is linear (affine) in the coordinates and velocities, at the default parameters.

    Tested on the document's own trees: an affine a(y) satisfies a(u + v) = a(u) + a(v) - a(0) at any u, v;
    three pairs of points in general position, to 10⁻⁹ of the values' size."""
    q = doc.coordinates
    moving = [*q, *(f"{c}_dot" for c in q)]
    names = [*moving, "t", *doc.parameters]
    found = [document_tree(pair, names) for pair in doc.accelerations.values()]
    trees = [t for t in found if t is not None]
    if not trees or len(trees) < len(found):
        return False
    base = {k: float(v.default) for k, v in doc.parameters.items()} | {"t": 0.0}
    zero = base | dict.fromkeys(moving, 0.0)
    for k in range(3):
        u = base | {n: 0.31 + 0.17 * k + 0.07 * i for i, n in enumerate(moving)}
        v = base | {n: -0.23 + 0.11 * k - 0.05 * i for i, n in enumerate(moving)}
        w = base | {n: u[n] + v[n] for n in moving}
        for t in trees:
            try:
                a, b, c, d = (evaluate(t, e) for e in (w, u, v, zero))
            except (ArithmeticError, ValueError, KeyError):
                return False
            if not abs(a - (b + c - d)) <= 1e-9 * max(1.0, abs(a), abs(b), abs(c), abs(d)):
                return False
    return True


def method_matters(f: Facts) -> bool:
    """Whether the choice of integrator teaches something about this system: a dissipative run (no conserved
    energy, where a symplectic method loses its advantage), or a nonlinear system with two or more degrees of
    freedom and no conserved momentum to reduce it (a candidate for chaos, like the double pendulum).  A linear
    system, or one a conserved momentum reduces to one degree of freedom, is integrated well by every method."""
    return not f.conservative or can_be_chaotic(f)


def can_be_chaotic(f: Facts) -> bool:
    """Two or more degrees of freedom, no conserved momentum and equations not linear: a candidate for chaos.

    A conserved momentum (a cyclic coordinate's) leaves one degree of freedom of two (the cone, the spherical
    pendulum); linear equations separate into normal modes (the coupled oscillators). Either way the motion is
    integrable: a Poincaré section would be closed curves only, and every method integrates it well."""
    momenta = any(c.name.startswith("p_") for c in f.doc.conserved)
    return f.dof >= 2 and not momenta and not linear_equations(f.doc)


@dataclass(frozen=True)
class Panel:
    name: str
    title: str
    text: str
    rule: str  # the availability rule in words
    available: Callable[[Facts], bool]
    optional: bool = False  # shown only where declared
    # shown open only where this holds; elsewhere it is one click away, under "details" (None: always open)
    open_when: Callable[[Facts], bool] | None = None
    # the explanation where generalized forces Q act (no potential describes them), if it differs
    forced_text: str | None = None
    # a sentence added only where a coordinate is an angle
    angles_text: str | None = None
    # the explanation where no true path reaches a kinetic focus, if it differs
    no_focus_text: str | None = None
    # sentences added only where the system has several coordinates (on one they would speak of nothing)
    several_text: str | None = None


PANELS: tuple[Panel, ...] = (
    Panel(
        "animation-2d",
        "The mechanism",
        "The simulated motion with a fading trail. Play, pause or drag the time slider; the dotted cursor on every "
        "plot follows the same instant. Drag a body to choose where it starts, and the round handle at the end of "
        "its arrow to choose how fast it starts.",
        "the mechanism moves in a plane",
        lambda f: f.mechanism_dim == 2,
    ),
    Panel(
        "animation-3d",
        "The mechanism in three dimensions",
        "The simulated motion with a fading trail; drag the background to turn the view, drag a body to choose "
        "where it starts. Play, pause or drag the time slider; the dotted cursor on every plot follows the same "
        "instant.",
        "the mechanism moves in space",
        lambda f: f.mechanism_dim == 3,
    ),
    Panel(
        "energy",
        "Energy against time",
        "Kinetic energy T, potential energy U, their sum E and the energy function h. The lower plot shows how far E "
        "and h have moved since t = 0: numerical drift, or a real loss where a force dissipates.",
        "always",
        lambda f: True,
    ),
    Panel(
        "h-vs-e",
        "h and E",
        "With a constraint that moves, or a term in T linear in the velocities, h and E differ, and when L does "
        "not depend on time h is the one conserved; the lower plot shows the difference E − h.",
        "h and E differ",
        lambda f: f.doc.hamiltonian_equals_energy is False,
    ),
    Panel(
        "momenta",
        "Conserved momenta",
        "The conserved momenta (a cyclic coordinate's, a sum of momenta such as the total momentum, or the angular "
        "momentum J of a rotation that leaves L unchanged) and, below, their change since t = 0, which only "
        "numerical error can produce.",
        "a generalized momentum is conserved",
        lambda f: any(c.name.startswith(("p_", "P_", "J")) for c in f.doc.conserved),
    ),
    Panel(
        "phase",
        "Phase portrait",
        "A coordinate against its rate of change: the blue curve is this run and the red dot the current state. "
        "With one degree of freedom (or a reduction to one) the grey curves are level sets of the energy function h, "
        "each a possible orbit; green dots mark stable equilibria, red diamonds unstable ones, and the dashed red "
        "curve through an unstable one separates motions of different kinds.",
        "always (level sets with one degree of freedom or a reduction to one)",
        lambda f: True,
        angles_text="An angle that goes round full circles is shown wrapped into (−π, π].",
    ),
    Panel(
        "effective-potential",
        "Effective potential",
        "U_eff of the remaining coordinate with the run's energy level (dashed). The motion stays where U_eff lies "
        "below the level, between the turning points (purple diamonds); the red dot is the current state, drawn "
        "inside a diamond whenever the motion is at a turning point.",
        "a reduction to one coordinate",
        lambda f: f.reduction is not None,
        optional=True,
    ),
    Panel(
        "small-oscillations",
        "Small oscillations",
        "The frequency of small oscillations predicted at the nearest stable equilibrium (its square is "
        "U_eff″ over the effective inertia), beside the one measured from the simulated motion.",
        "a reduction to one coordinate with a closed-form ω²",
        lambda f: f.reduction is not None and f.reduction.get("omega_squared") is not None,
        optional=True,
    ),
    Panel(
        "modes",
        "Normal modes",
        "Near a stable equilibrium every small motion is a sum of normal modes, each a fixed shape oscillating at "
        "its own frequency. Tick the modes to superpose and set their amplitudes; the drawing plays that sum. The "
        "table compares each predicted frequency with the one measured from a small-amplitude simulation.",
        "two or more coordinates and an equilibrium with an oscillating mode",
        lambda f: f.dof >= 2 and bool(oscillating_equilibria(f.doc)),
    ),
    Panel(
        "poincare",
        "Poincaré section",
        "Several orbits with the same energy, each marked where it crosses a plane in one direction. An orbit "
        "that keeps to a curve is regular (quasi-periodic); one whose points scatter over an area is chaotic. Which "
        "you see depends on the energy: near a stable equilibrium nearly every orbit is regular, high above it nearly "
        "every orbit is chaotic, and in between both lie side by side; the start sets the energy.",
        "two conservative degrees of freedom, no conserved momentum, and equations not linear (else the motion is "
        "integrable: the section would be closed curves)",
        lambda f: f.dof == 2 and f.conservative and can_be_chaotic(f),
        optional=True,
    ),
    Panel(
        "constraint-force",
        "Force of constraint",
        "The force that holds the constraint, derived with a Lagrange multiplier and evaluated along the run.",
        "a constraint force is derived",
        lambda f: bool(f.doc.constraint_forces),
    ),
    Panel(
        "action",
        "The action",
        "Hamilton's principle: the true motion makes the action S = ∫ L dt stationary among paths with the same "
        "ends. Drag the dashed path (or use ε) to vary one coordinate by ε sin(nπt/τ) over a time τ (n = 1, 2, …: the shape); the lower plots show L "
        "along both paths and S against ε, flat at ε = 0. Move τ past the kinetic focus and the true path stops "
        "being a minimum: it becomes a saddle of S.",
        "always (every system has an L)",
        lambda f: True,
        several_text="Varying one coordinate alone, with the others kept on the true path, has a focus of its own. "
        "It comes at the same time as the focus for all the coordinates varied together, or later, or never; the "
        "readout says which variation each focus belongs to.",
        # where no true path reaches a kinetic focus (app/engine/document/action_step.py decides, the derivation's first
        # step says the same), the sentence about moving τ past one would be false
        no_focus_text="Hamilton's principle: the true motion makes the action S = ∫ L dt stationary among paths "
        "with the same ends. Drag the dashed path (or use ε) to vary one coordinate by ε sin(nπt/τ) over a time τ "
        "(n = 1, 2, …: the shape); the lower plots show L along both paths and S against ε, flat at ε = 0. Here L "
        "is at most linear in the coordinates and its mass matrix is constant, so there is no kinetic focus: the "
        "true path is a minimum of S for every τ.",
        # with a force Q no potential describes, Hamilton's principle reads δS + ∫ Q δq dt = 0: S alone is not
        # stationary, and there is no kinetic focus of S to speak of
        forced_text="With a force that no potential describes, the true motion does not make S = ∫ L dt "
        "stationary: Hamilton's principle becomes δS + ∫ Q δq dt = 0, where Q is the generalized force. Drag the "
        "dashed path (or use ε) to vary one coordinate q by δq = ε sin(nπt/τ) over a time τ; the lower plots show L "
        "along both paths and S against ε. Its slope at ε = 0 is not zero: it equals −∫ Q sin(nπt/τ) dt, the work "
        "the force does along the variation δq per unit of ε, with the sign reversed; the readout shows both.",
    ),
    Panel(
        "work-precision",
        "Error against run time",
        "Every method over a sweep of tolerances: the error of the final state against the run time (lower left is "
        "better), measured once for the scene's default parameters and initial state (it takes seconds, so it does "
        "not follow the sliders). The star is this run's own error estimate.",
        "a chapter scene (its report is measured once per scene) whose motion is not a polynomial in t",
        # with constant accelerations every method of order two or more is exact: the chart would be noise
        lambda f: f.scene and not constant_accelerations(f.doc),
        open_when=method_matters,
    ),
)

BY_NAME = {p.name: p for p in PANELS}
NAMES = tuple(BY_NAME)
OPTIONAL = tuple(p.name for p in PANELS if p.optional)


def shown(facts: Facts, declared: Sequence[str]) -> list[str]:
    """The panels a page shows, in the registry's order: every available one, optional ones only if declared."""
    wanted = set(declared)
    return [p.name for p in PANELS if (not p.optional or p.name in wanted) and p.available(facts)]


def folded(facts: Facts, names: Sequence[str]) -> list[str]:
    """Those of the shown panels ``names`` that sit closed under "details" on this page (their open rule fails)."""
    rules = {n: BY_NAME[n].open_when for n in names}
    return [n for n, rule in rules.items() if rule is not None and not rule(facts)]


def texts(
    forced: bool = False, angles: bool = True, focus: bool = True, several: bool = True
) -> dict[str, dict[str, str]]:
    """Title and explanation of every panel (for the templates); ``forced``: generalized forces Q act;
    ``angles``: some coordinate is an angle; ``focus``: a true path can reach a kinetic focus; ``several``: the
    system has more than one coordinate."""

    def text(p: Panel) -> str:
        said = (
            p.forced_text if forced and p.forced_text else p.no_focus_text if not focus and p.no_focus_text else p.text
        )
        # the focus of each coordinate's own variations, said only where there is more than one coordinate (and
        # a focus to speak of)
        if several and p.several_text and said == p.text:
            said = f"{said} {p.several_text}"
        return f"{said} {p.angles_text}" if angles and p.angles_text else said

    return {p.name: {"title": p.title, "text": text(p)} for p in PANELS}
