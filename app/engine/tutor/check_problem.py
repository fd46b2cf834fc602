"""The problem of one step of one system (app/engine/tutor/check.py): the engine's expression for it, how an
answer may differ from it, the names an answer may use and the mistakes it is diagnosed against.

A problem holds SymPy objects only, so it can be built where the derivation lives and sent to a worker
process with the student's answer.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.derivation.dimensions import Dims, system_dimensions
from app.engine.display.textbook import unicode_text
from app.engine.document.notation import MASS_INERTIA, Inertia, inertia, text
from app.engine.document.report import plain_name
from app.engine.tutor.check_answers import PER_COORDINATE, RELATIONS, STEPS, CheckError, name_kinds
from app.engine.tutor.compare import Groups, Values
from app.engine.tutor.diagnose import catalogue
from app.engine.tutor.mistake_families import Mistake
from app.engine.tutor.mistake_positions import component_keys, points, position_label
from app.engine.tutor.mistakes import absent_names, has_gravity, has_springs


@dataclass(frozen=True)
class Problem:
    """One step of one system, ready to judge answers against."""

    step: str
    coordinate: str | None
    label: str
    truths: tuple[sp.Expr, ...]
    where: tuple[str, ...]  # for ω²: the equilibrium each truth belongs to
    relation: str
    kinds: dict[str, str]
    namespace: dict[str, sp.Symbol]
    groups: Groups
    mistakes: tuple[tuple[Mistake, str, Values], ...]  # (mistake, hint, its values at the sample points)
    latex_names: dict[sp.Symbol, str]
    acceleration: sp.Symbol | None = None
    dimensions: dict[sp.Symbol, Dims] = field(default_factory=dict)  # what the declared units tell
    # whether a spring can be in U: a stiffness declared (N/m), or no units declared to tell (the hints about
    # ½ k × stretch² are given only then)
    springs: bool = True
    # the bodies whose height never changes as the coordinates do, (label, mass): a wedge sliding on the floor
    # has no term in U
    level: tuple[tuple[str, sp.Expr], ...] = ()
    # whether the system has gravity (a g), as ``springs`` says whether it has springs
    gravity: bool = True
    # names a student may expect that the problem has not, with why (g where no body's height changes): the
    # refusal of such a name says why
    absent: dict[str, str] = field(default_factory=dict)
    # the document's letter for the frequency (ω, or Ω where ω is a parameter), for the words of the ω² step
    frequency: str = "ω"
    # for ω²: the reduced coordinate and its value at the asked equilibrium (θ, 0), where an ω² typed with the
    # coordinate still in it is evaluated
    equilibrium: tuple[sp.Symbol, sp.Expr] | None = None
    # for ω²: the reduced coordinate's inertia, its letter and words (I_eff for an angle, m_eff for a length)
    inertia: Inertia = MASS_INERTIA

    def mistake(self, key: str) -> Mistake | None:
        return next((m for m, _, _ in self.mistakes if m.key == key), None)


def conserved_momenta(d: Derivation) -> tuple[sp.Symbol, ...]:
    return d.reduction.momenta if d.reduction is not None else ()


def checkable_equilibria(d: Derivation) -> list:
    """Equilibria whose ω² a student can be asked for: not known to be unstable."""
    red = d.reduction
    return [e for e in red.equilibria if e.stable is not False] if red is not None else []


def asked_equilibrium(d: Derivation):
    """The one equilibrium the ω² step asks about, named on the step ("about θ = 0"): the first not known to be
    unstable that exists for every value of the parameters, else the first not known to be unstable.  One box, one
    equilibrium: ω² at another one is a named mistake, not a right answer."""
    found = checkable_equilibria(d)
    return next((e for e in found if e.exists is None and not _inverse(e.position)), found[0])


def _inverse(position: sp.Expr) -> bool:
    """Whether a position is an inverse cosine or sine, which exists only for some values of the parameters."""
    return bool(position.atoms(sp.acos, sp.asin))


def where_asked(d: Derivation) -> str:
    """The asked equilibrium as running text writes it: "θ = 0"."""
    return equilibrium_text(d, asked_equilibrium(d).position)


def equilibrium_text(d: Derivation, position: sp.Expr) -> str:
    """An equilibrium of the reduction's coordinate as running text writes it: "θ = π", "r⁴ = p_θ²/(mk)"."""
    return _at(plain_name(d.reduction.coordinate), position)  # type: ignore[union-attr]


def exercises(d: Derivation) -> list[tuple[str, str | None]]:
    """The steps a student can check for this system, in the chapter's order."""
    out: list[tuple[str, str | None]] = []
    for step in STEPS:
        if step == "position":
            # each moving component of each body, where the system is given by its particles' positions
            out += [(step, key) for key, _, _ in component_keys(d)]
            continue
        if step in ("kinetic", "potential") and d.mechanics.T is None:
            continue
        if step == "omega_squared" and not checkable_equilibria(d):
            continue
        if step in PER_COORDINATE:
            out += [(step, name) for name in d.table.names]
        else:
            out.append((step, None))
    return out


def _unavailable(d: Derivation, step: str) -> str:
    if step == "position":
        return "this system is given by its energies, not by its bodies' positions"
    if step in ("kinetic", "potential"):
        return "this system is given by its Lagrangian alone, so T and U are not known separately"
    return "this system has no equilibrium with a closed-form ω² that is not unstable"


def step_title(step: str, name: str | None, omega: str = "ω") -> str:
    """A step in words, as a student and a teacher read it ("energy function h", "Euler–Lagrange equation for θ"):
    the one home of the steps' titles (a step the engine does not know comes back as given)."""
    shown = plain_name(name) if name else ""
    return {
        # a position step's name is its component (x₁: x of the first body), so each of a figure's is named apart
        "position": f"position {shown}" if shown else "position",
        "kinetic": "kinetic energy T",
        "potential": "potential energy U",
        "lagrangian": "Lagrangian L",
        "momentum": f"momentum conjugate to {shown}",  # no p_θ in running text: an underscore is code
        "equation": f"Euler–Lagrange equation for {shown}",
        "acceleration": f"acceleration of {shown}",
        "hamiltonian": "energy function h",
        # the frequency's letter is the document's (Ω where ω is a parameter: the rotating wire's rate)
        "omega_squared": f"{omega}² of small oscillations",
    }.get(step, step)


def step_heading(step: str, name: str | None) -> str:
    """A step's title standing alone (a cell, a list), in sentence case: "Kinetic energy T", "Position x₁",
    "Euler–Lagrange equation for θ" (``step_title`` is the same words inside a sentence)."""
    title = step_title(step, name)
    return title[:1].upper() + title[1:]


def problem(d: Derivation, step: str, coordinate: str | None = None, mistakes: bool = True) -> Problem:
    """The problem for one step (a CheckError naming the field when the step or coordinate does not apply).

    With ``mistakes`` the step's catalogue of mistakes is generated and evaluated at the sample points
    (``app.engine.tutor.diagnose``): the costly part, done once per system and step by the service.
    """
    table, eqs = d.table, d.equations
    available = exercises(d)
    steps = list(dict.fromkeys(s for s, _ in available))
    if step not in STEPS:
        raise CheckError(
            f"step: unknown step {str(step)[:40]!r}; the steps are: {', '.join(steps)}", "step", str(step)[:40]
        )
    if step not in steps:
        raise CheckError(
            f"step: {step!r} does not apply: {_unavailable(d, step)}; the steps are: {', '.join(steps)}", "step", step
        )
    k = None
    if step == "position":
        components = {key: (i, a) for key, i, a in component_keys(d)}
        if coordinate not in components:
            given = f"{str(coordinate)[:40]!r} is not" if coordinate else "give"
            raise CheckError(
                f"coordinate: {given} one of this system's moving position components: {', '.join(components)} "
                "(x, y, z of one body; x1, z2, … numbered by body where there are several)",
                "coordinate",
                str(coordinate or "")[:40],
            )
        body, axis = components[coordinate]
        k = 3 * body + axis
    elif step in PER_COORDINATE:
        names = ", ".join(table.names)
        if not coordinate:
            raise CheckError(f"coordinate: the {step} step is per coordinate; give one of: {names}", "coordinate")
        if coordinate not in table.names:
            raise CheckError(
                f"coordinate: {str(coordinate)[:40]!r} is not a coordinate of this system; the coordinates are: {names}",
                "coordinate",
                str(coordinate)[:40],
            )
        k = table.names.index(coordinate)
    else:
        coordinate = None

    where: tuple[str, ...] = ()
    equilibrium: tuple[sp.Symbol, sp.Expr] | None = None
    if step == "position":
        truths = (points(d)[k // 3][k % 3],)  # type: ignore[operator]
    elif step == "kinetic":
        truths = (d.mechanics.T,)
    elif step == "potential":
        truths = (d.mechanics.U,)
    elif step == "lagrangian":
        truths = (d.mechanics.L,)
    elif step == "momentum":
        truths = (eqs.momenta[k],)  # type: ignore[index]
    elif step == "equation":
        truths = (eqs.residuals[k],)  # type: ignore[index]
    elif step == "acceleration":
        truths = (eqs.accelerations[k],)  # type: ignore[index]
    elif step == "hamiltonian":
        truths = (d.energetics.hamiltonian,)
    else:
        truths, where = (asked_equilibrium(d).omega_squared,), (where_asked(d),)
        equilibrium = (table.namespace()[d.reduction.coordinate], asked_equilibrium(d).position)  # type: ignore[union-attr]

    momenta = conserved_momenta(d)
    kinds = name_kinds(table.names, table.parameter_names, tuple(p.name for p in momenta))
    namespace = {**table.namespace(), **{s.name: s for s in table.qdd}, **{p.name: p for p in momenta}}
    groups = Groups((*table.params, *momenta), (*table.q, table.t), (*table.qd, *table.qdd))
    latex_names = {**table.latex_names(), **{p: sp.latex(p) for p in momenta}}
    label = position_label(d, k // 3, k % 3) if step == "position" else step_title(step, coordinate, text("frequency", d))  # type: ignore[operator]
    relation = RELATIONS.get(step, "exact")
    return Problem(
        step,
        coordinate,
        label,
        truths,
        where,
        relation,
        kinds,
        namespace,
        groups,
        catalogue(d, step, k, truths, groups, relation, short_label(step, label)) if mistakes else (),
        latex_names,
        table.qdd[k] if step == "equation" and k is not None else None,
        system_dimensions(d),
        has_springs(d),
        level_bodies(d),
        has_gravity(d),
        absent_names(d),
        text("frequency", d),
        equilibrium,
        inertia(d),
    )


def level_bodies(d: Derivation) -> tuple[tuple[str, sp.Expr], ...]:
    """(label, mass) of each labelled body that moves while its height (z, upward) stays the same."""
    moving = {*d.table.q, d.table.t}
    out = []
    for particle, r in zip(d.system.particles, d.mechanics.positions, strict=False):
        if particle.label and not r[2].free_symbols & moving and any(c.free_symbols & moving for c in r[:2]):
            out.append((particle.label, sp.sympify(particle.mass, locals=d.table.namespace())))
    return tuple(out)


def _at(r: str, position: sp.Expr) -> str:
    """The equilibrium as a reader writes it: r = 0, or r⁴ = p_θ²/(k m) where the position is a root of an
    absolute value (never √Abs p_θ/(m^(1/4) k^(1/4)))."""
    roots = [p.exp.q for p in position.atoms(sp.Pow) if p.exp.is_Rational and p.exp.q > 1]
    if not roots and not position.has(sp.Abs):
        return f"{r} = {unicode_text(position)}"
    n = int(sp.ilcm(*roots, 2)) if roots else 2
    # an even power of |x| is that power of x
    power = sp.powsimp(sp.expand_power_base(position**n, force=True), force=True).replace(sp.Abs, lambda x: x)
    power = sp.factor(sp.powsimp(power, force=True))
    if power.has(sp.Abs) or any(p.exp.is_Rational and p.exp.q > 1 for p in power.atoms(sp.Pow)):
        return f"the equilibrium of {r}"
    superscript = str(n).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return f"{r}{superscript} = {unicode_text(power)}"


def short_label(step: str, label: str) -> str:
    """The label as a hint names it: 'T', 'U', 'equation for θ'."""
    return {"kinetic": "T", "potential": "U", "lagrangian": "L", "hamiltonian": "h"}.get(
        step, label.replace("Euler–Lagrange ", "")
    )
