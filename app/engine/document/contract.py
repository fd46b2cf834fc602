"""The derivation JSON served by the API (the contract later issues rely on)."""

from __future__ import annotations

import math
import re
from typing import Any, TypeVar

import sympy as sp

from app.engine.algebra import progress
from app.engine.algebra.budget import Skipped, bounded, display_budget, display_work_left, within_budget
from app.engine.algebra.simplify import is_zero, pythagoras
from app.engine.derivation.derive import LARGE_FROM, Derivation, Transformed
from app.engine.derivation.rods import fixed_distances
from app.engine.display import meaning
from app.engine.display.names import MASS_MATRIX, display_names, latex, unicode
from app.engine.display.root_forms import power_form, trig_cancelled
from app.engine.document import notation
from app.engine.document.action_step import kinetic_focus_possible
from app.engine.document.errata import errata_json
from app.engine.document.model import Document
from app.engine.document.report import (
    SCALED_CLAUSE,
    Printer,
    build_steps,
    conserved_form,
    effective_potential,
    energies,
    equation_pairs,
    lagrangian,
    momentum,
    shown_accelerations,
)
from app.engine.document.report import display as _show
from app.engine.document.report_members import (
    GREEK_CLAUSE,
    NORMALS_CLAUSE,
    ON_PATH_CLAUSE,
    constraint_steps,
    new_lagrangian,
    transform_steps,
)
from app.engine.document.report_modes import (
    hamilton_json,
    hamilton_steps,
    limits_step,
    normal_mode_steps,
    normal_modes_json,
)
from app.engine.document.trees import maybe_of_sympy
from app.engine.equations.constraints import ConstraintForce
from app.engine.equilibria.modes import NormalModes
from app.engine.parser.parse import parse_expression
from app.limits import DISPLAY_WORK, FIRST_DISPLAY_WORK, LARGE_DISPLAY_WORK
from app.scenes.reasons import reason
from app.scenes.types import Parameter, Scene

T = TypeVar("T")


def parameters_json(parameters: tuple[Parameter, ...]) -> dict[str, dict[str, Any]]:
    """Parameter name -> default, unit, allowed range and description."""
    return {
        p.name: {"default": p.default, "unit": p.unit, "min": p.min, "max": p.max, "description": p.description}
        for p in parameters
    }


# Each member of the document beyond the equations is computed within its own bound (the derivation's
# MEMBER_WORK, app.engine.derivation.derive); printing it has a bound of the same length. One that runs out is left
# out with a note in "skipped", never a refusal of the system.


def derivation_json(d: Derivation, scene: Scene | None = None, beyond: bool = True) -> dict[str, Any]:
    """Everything derived, with each expression as a sympy string and LaTeX.

    ``scene``, for a chapter scene, adds the scene block and the chapter's errata.
    ``beyond`` adds Hamilton's equations and the normal modes (steps and JSON).
    All display simplification shares one bound of work (DISPLAY_WORK); each member beyond the
    equations has its own bound (MEMBER_WORK), and ``skipped`` lists those left out and why.
    """
    units = DISPLAY_WORK if len(d.table.names) < LARGE_FROM else LARGE_DISPLAY_WORK
    with display_budget(units):
        return _derivation_json(d, scene, beyond)


def printed_document(d: Derivation, scene: Scene | None = None, beyond: bool = True) -> Document:
    """The document of a derivation as the typed model every reader takes (``app.engine.document.model``): printed
    once by ``derivation_json`` and validated once against the model (a fraction of a millisecond); a
    chapter scene's carries its ``id``."""
    printed = derivation_json(d, scene, beyond)
    return Document.model_validate({"id": scene.id, **printed} if scene is not None else printed)


def held_momenta(d: Derivation, scene: Scene | None) -> dict[str, float]:
    """The conserved momenta of a reduction at the scene's initial state and default parameters."""
    red = d.reduction
    if red is None or not red.momenta or scene is None:
        return {}
    table = d.table
    values = {s: p.default for s, p in zip(table.params, d.system.parameters, strict=True)}
    values.update({s: scene.initial.get(s.name, 0.0) for s in (*table.q, *table.qd)})
    return {
        P.name: float(d.equations.momenta[table.names.index(P.name[2:])].xreplace(values).evalf()) for P in red.momenta
    }


def symbol_names(d: Derivation) -> dict[str, dict[str, str]]:
    """How every name the document uses is written (LaTeX, Unicode, plain): read by pages, plots and exports."""
    q = d.table.names
    conserved = [c.name for c in d.energetics.conserved]
    momenta = [f"p_{n}" for n in q]
    return display_names(
        dict.fromkeys([*q, *(f"{n}_dot" for n in q), *(f"{n}_ddot" for n in q), *d.table.parameter_names, "t",
                       *momenta, *conserved])
    )  # fmt: skip


def _shown(expr: sp.Expr) -> sp.Expr:
    """The display form within what is left of the display budget; SymPy's own form when it runs out."""
    return within_budget(lambda: _show(expr), expr, max(display_work_left(DISPLAY_WORK), 1_000))


def _member(value: T | Skipped, fallback: T, skipped: list[Skipped]) -> T:
    """A member's value; a skipped one's note goes to ``skipped`` and ``fallback`` is printed."""
    if isinstance(value, Skipped):
        skipped.append(value)
        return fallback
    return value


def _equation_pairs(d: Derivation, pr: Printer) -> list[dict[str, Any]]:
    """The equations in their textbook rows within what is left of the display budget, else each residual = 0."""
    pairs = within_budget(lambda: equation_pairs(d, pr), None, max(display_work_left(DISPLAY_WORK), 10_000))
    if pairs is not None:
        return pairs
    return [pr.shown(r, f"{pr.tex(r)} = 0", r) for r in d.equations.residuals]


def _accelerations(d: Derivation, pr: Printer, skipped: list[Skipped]) -> dict[str, Any]:
    """Each q_ddot in closed form, or none (with a note) when the engine kept it as M⁻¹f."""
    eqs = d.equations
    MM = MASS_MATRIX[1]
    if eqs.closed_form:
        # as the accelerations step prints them: grouped by coordinate, over one denominator
        shown = within_budget(lambda: shown_accelerations(d), None, max(display_work_left(DISPLAY_WORK), 1_000))
        if shown is None:
            shown = [meaning.by_coordinate(a, d.table.q) for a in eqs.accelerations]
        return {name: pr.pair(a) for name, a in zip(d.table.names, shown, strict=True)}
    skipped.append(Skipped(
        "accelerations",
        f"The accelerations in closed form are left out: solving {MM} q̈ = f symbolically gives expressions too long "
        f"to read ({eqs.closed_form_reason}), so they stay {MM}⁻¹f, with the mass matrix {MM} and f "
        f"({notation.RIGHT_SIDE}) shown, "
        "solved numerically.",
    ))  # fmt: skip
    return {}


def _dependent_accelerations(d: Derivation, scene: Scene | None, pr: Printer) -> dict[str, Any]:
    """The acceleration of each position the scene names that the coordinates fix (``Scene.dependent``), by name:
    for Y(q, t), Ÿ = Σ ∂Y/∂q q̈ + Σ ∂²Y/∂q∂q′ q̇ q̇′ + …, the total time derivative taken twice with each q̈ put in
    from the accelerations (none where they are not in closed form)."""
    if scene is None or not scene.dependent or not d.equations.closed_form:
        return {}
    table = d.table
    names = {s.name: s for s in (*table.q, *table.params, table.t)}
    solved = dict(zip(table.qdd, d.equations.accelerations, strict=True))
    out = {}
    for name, (text, _) in scene.dependent.items():
        position = parse_expression(text, names)
        # Ÿ = d²Y/dt² along the motion, with the accelerations of the coordinates solved for
        second = table.dt(table.dt(position)).xreplace(solved)
        out[name] = pr.pair(_shown(meaning.by_coordinate(sp.factor(second), table.q)))
    return out


def _inequality(pr: Printer, relation: sp.Relational | None) -> dict[str, Any] | None:
    """b > a with each side in its textbook form (R ω² > g), as text and LaTeX; None for none."""
    if relation is None:
        return None
    big, small = relation.args
    return {
        "sympy": f"{sp.sstr(pr.form(big))} > {sp.sstr(pr.form(small))}",
        "latex": f"{pr.tex(big)} > {pr.tex(small)}",
        "tree": None,
    }


def _reversed(relation: sp.Relational | None) -> sp.Relational | None:
    """b > a turned round, a > b (the case where ω² is negative); None for none."""
    return None if relation is None else sp.StrictGreaterThan(relation.rhs, relation.lhs, evaluate=False)


def _derivation_json(d: Derivation, scene: Scene | None, beyond: bool = True) -> dict[str, Any]:
    progress.now("the conserved quantities and the reduction to one coordinate")
    table, eqs, en, red = d.table, d.equations, d.energetics, d.reduction
    pr = Printer(table.latex_names())
    skipped: list[Skipped] = list(d.skipped)
    none: tuple[ConstraintForce, ...] = ()
    forces = _member(d.constraint_forces, none, skipped)
    transformed = _transformed(d, skipped)
    no_steps: list[dict[str, str]] = []
    result: dict[str, Any] = {
        "coordinates": list(table.names),
        "angles": notation.angle_coordinates(d),
        "symbols": symbol_names(d),
        # every letter of the document once, with what it stands for (app/engine/document/notation.py)
        "notation": notation.table(
            d, forces, transformed[0] if transformed is not None else None, scene.coordinate_meanings if scene else {}
        ),
        "parameters": parameters_json(d.system.parameters),
        "kinetic": pr.pair(d.mechanics.T) if d.mechanics.T is not None else None,
        "potential": pr.pair(d.mechanics.U) if d.mechanics.U is not None else None,
        "lagrangian": pr.pair(lagrangian(d, pr)),
        # h and E from the same pieces as T and U; each equation's text is the scaled residual its row shows
        **dict(zip(("hamiltonian", "energy"), map(pr.pair, energies(d, pr)), strict=True)),
        "equations_of_motion": [
            {"coordinate": name, **pair} for name, pair in zip(table.names, _equation_pairs(d, pr), strict=True)
        ],
        "accelerations": _accelerations(d, pr, skipped),
        "dependent_accelerations": _dependent_accelerations(d, scene, pr),
        "mass_matrix": [[pr.pair(x) for x in row] for row in eqs.mass_matrix.tolist()],
        "forcing": [pr.pair(_shown(x)) for x in eqs.forcing],
        "momenta": {name: pr.pair(momentum(d, k)) for k, name in enumerate(table.names)},
        # particles held at a fixed distance from the origin or from each other (rods for the drawing)
        "fixed_distances": fixed_distances(d),
        "generalized_forces": {name: pr.pair(f) for name, f in zip(table.names, d.mechanics.Q, strict=True) if f != 0},
        "cyclic": list(en.cyclic),
        "conserved": [
            {"name": c.name, "latex_name": c.latex_name, **pr.pair(conserved_form(d, pr, c.expr)), "reason": c.reason}
            for c in en.conserved
        ],
        "explicit_time_derivative": pr.pair(en.dL_dt),
        "hamiltonian_equals_energy": en.h_equals_e,
        "hamiltonian_energy_reason": en.reason,
        "hamiltonian_conserved": en.h_conserved,
        "hamiltonian_conserved_reason": en.h_conserved_reason,
        "energy_minus_hamiltonian": pr.pair(en.energy_minus_h),
        # whether a true path can reach a kinetic focus (app/engine/document/action_step.py): the action panel's words
        "kinetic_focus_possible": kinetic_focus_possible(d),
        "effective_potential": None,
        "steps": bounded(
            "steps",
            "The step-by-step derivation",
            d.member_work("steps"),
            lambda: _steps(d, forces, pr, transformed),
            no_steps,
            skipped,
        ),  # fmt: skip
        "scene": scene_json(scene) if scene is not None else None,
        "errata": errata_json(scene, pr.names) if scene else [],
        "constraint_forces": [constraint_force_json(f, pr) for f in forces],
        "transformed": transformed[1] if transformed is not None else None,
        "hamilton": None,
        "normal_modes": [],
        "skipped": [],
    }
    if red is not None:
        coordinate = table.q[table.names.index(red.coordinate)]
        result["effective_potential"] = {
            "coordinate": red.coordinate,
            "momenta": [s.name for s in red.momenta],
            "potential": pr.pair(effective_potential(d), red.momenta[0] if red.momenta else None),
            "mass": pr.pair(red.effective_mass),
            # its letter: I_eff for an angle, m_eff for a length (app/engine/notation.inertia)
            "inertia": {"latex": notation.inertia(d).latex, "unicode": notation.inertia(d).unicode},
            "condition": pr.pair(red.equilibrium_condition),
            "omega_squared": pr.pair(red.omega_squared_at),
            "equilibria": [
                {
                    # a root as a textbook writes it: r₀ = (p_θ²/(m k))^{1/4}
                    "position": {**pr.pair(e.position), "latex": pr.root(e.position), "unicode": pr.root_text(e.position)},
                    # with its running-text form, for the sliders' marks (ω² = 0 where it changes stability)
                    "omega_squared": {**pr.pair(e.omega_squared), "unicode": pr.text(e.omega_squared)},
                    "stable": e.stable,
                    # where it exists (arccos(g/(R w²)) needs R w² > g) and, with no verdict, when it is stable
                    "exists": _inequality(pr, e.exists),
                    "stable_when": _inequality(pr, e.stable_when),
                    # the same condition reversed, where it is unstable (R w² > g at the hoop's bottom)
                    "unstable_when": _inequality(pr, _reversed(e.stable_when)),
                    # r₀ⁿ = C where the root is C^(1/n) (the cone's r₀³ = p_φ² tan α/(m² g)), n = 1 otherwise
                    "power": (root := power_form(e.position))[0],
                    "position_power": pr.pair(root[1]),
                }
                for e in red.equilibria
            ],  # fmt: skip
            # ω² about a steady motion with its r₀ (the momentum eliminated): 3g sin α cos α/r₀
            "omega_squared_steady": (
                pr.pair(
                    trig_cancelled(
                        red.omega_squared_steady.xreplace({coordinate: sp.Symbol(red.coordinate + "0", real=True)})
                    )
                )
                if red.omega_squared_steady is not None
                else None
            ),
        }
    if beyond:
        # built last, so that they never take the chapter's steps' share of the display budget
        add_beyond(d, scene, result, pr, skipped)
    if result["dependent_accelerations"]:
        result["steps"] = with_dependent(result["steps"], result["dependent_accelerations"])
        result["notation"] = with_dependent_letters(result["notation"], scene, d)
    if scene is not None and scene.limits and (compared := limits_step(d, pr, scene.limits)) is not None:
        # the comparison the statement asks for, after the accelerations it compares (Results state it)
        keys = [s["key"] for s in result["steps"]]
        at = keys.index("accelerations") + 1 if "accelerations" in keys else len(keys)
        result["steps"] = [*result["steps"][:at], compared, *result["steps"][at:]]
    if scene is not None:
        # a chapter scene explains each step in its own terms; the generic sentence stays otherwise
        result["steps"] = explained(scene, result["steps"])
    result["steps"] = one_equilibria_step(d, result["steps"])
    result["skipped"] = [{"member": s.member, "reason": s.reason} for s in skipped]
    return result


def with_dependent(steps: list[dict[str, Any]], dependent: dict[str, Any]) -> list[dict[str, Any]]:
    """The accelerations step with a row for each position the coordinates fix (Ÿ under ÿ₁ and ÿ₂), aligned at
    its '=' with theirs."""
    out = []
    for s in steps:
        if s["key"] == "accelerations" and s["latex"].endswith(r"\end{aligned}"):
            rows = "".join(rf" \\ {latex(name + '_ddot')} &= {pair['latex']}" for name, pair in dependent.items())
            texts = "".join(f", {pair['sympy']}" for pair in dependent.values())
            s = {**s, "latex": s["latex"].removesuffix(r"\end{aligned}") + rows + r"\end{aligned}",
                 "sympy": s["sympy"].removesuffix("]") + texts + "]"}  # fmt: skip
        out.append(s)
    return out


def with_dependent_letters(rows: list[dict[str, Any]], scene: Scene | None, d: Derivation) -> list[dict[str, Any]]:
    """The Symbols rows with one for each position the coordinates fix (Y, the middle mass's height), after the
    coordinates' rows, in the unit of the coordinates it is made of."""
    if scene is None:
        return rows
    units = {latex(n): r["unit"] for n in d.table.names for r in rows if r["latex"] == latex(n)}
    added = []
    for name, (text, what) in scene.dependent.items():
        made_of = [n for n in d.table.names if re.search(rf"\b{n}\b", text)]
        unit = units.get(latex(made_of[0]), "") if made_of else ""
        added.append({"latex": latex(name), "unicode": unicode(name), "meaning": what, "unit": unit, "kind": "derived"})
    after = max((i + 1 for i, r in enumerate(rows) if r["kind"] == "coordinate"), default=0)
    return rows[:after] + added + rows[after:]


def explained(scene: Scene, steps: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Each step with the scene's reason for it; a reason given for a kind of step (normal-modes, not
    normal-modes:2) goes to the first of them only, so that no sentence is printed twice in a row."""
    out, said = [], set()
    for s in steps:
        own = scene.reasons.get(s["key"])
        text = own or reason(scene.reasons, s["key"])
        if text and not own:
            text = None if text in said else text
        said.add(text)
        engine = s["explanation"] or ""
        text = text or engine
        # how the equations are scaled is the engine's to say (it is derived): a scene's reason keeps that clause
        if SCALED_CLAUSE in engine and SCALED_CLAUSE not in text:
            text = f"{text.rstrip('.')}; {engine[engine.index(SCALED_CLAUSE) :]}"
        # why the Cartesian letters are ξ, η, ζ is the engine's to say too (it knows which names are taken)
        if GREEK_CLAUSE in engine and GREEK_CLAUSE not in text:
            text = f"{text} {engine[engine.index(GREEK_CLAUSE) :]}"
        # so is whether the equations for the multipliers are coupled (from their cross coefficients)
        if NORMALS_CLAUSE in engine and NORMALS_CLAUSE not in text:
            text = f"{text} {engine[engine.index(NORMALS_CLAUSE) :]}"
        # and that the equations put on the path give each λ by one division (where the step puts them there)
        if ON_PATH_CLAUSE in engine and ON_PATH_CLAUSE not in text:
            text = f"{text} {engine[engine.index(ON_PATH_CLAUSE) :]}"
        out.append({**s, "explanation": text})
    return out


def one_equilibria_step(d: Derivation, steps: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The equilibria said once. With one coordinate and no momentum held, U_eff is U and the reduction's
    equilibria are the system's: its step is left out where the "Equilibria" step (with the small oscillations
    about each after it) is printed, and what it said beyond that step (which is stable) joins it. With momenta
    held, the reduction's rest points are steady motions, and its step is titled so."""
    red = d.reduction
    keys = [s["key"] for s in steps]
    if red is None or "reduced-equilibria" not in keys:
        return steps
    i = keys.index("reduced-equilibria")
    if red.momenta:
        # no steady motion where the system has no equilibrium either: "none" said once, by the Equilibria step
        # (the cylinder on the wedge: U_eff′ = −m g sin α beside ∂U/∂s = −m g sin α)
        none = r"\text{no equilibrium}"
        if not red.equilibria and "equilibria" in keys and none in steps[keys.index("equilibria")]["latex"]:
            return [*steps[:i], *steps[i + 1 :]]
        return [*steps[:i], {**steps[i], "title": "Steady motions and small oscillations"}, *steps[i + 1 :]]
    if "equilibria" not in keys or steps[keys.index("equilibria")]["latex"] == r"\text{not computed}":
        return steps
    reduced = steps[i]
    out = []
    for s in steps:
        if s["key"] == "equilibria" and red.equilibria and reduced["explanation"] not in s["explanation"]:
            s = {**s, "explanation": f"{s['explanation']} {reduced['explanation']}"}
        if s is not reduced:
            out.append(s)
    return out


def _transformed(d: Derivation, skipped: list[Skipped]) -> tuple[Transformed, dict[str, Any]] | None:
    """The declared change of coordinates and its print (None when none is declared), each within its bound."""
    tr = _member(d.transformed, None, skipped)
    if tr is None:
        return None
    what = "The derivation in the declared new coordinates"
    printed = bounded("transformed", what, d.member_work("transformed"), lambda: transformed_json(tr), None, skipped)
    return (tr, printed) if printed is not None else None


def _steps(
    d: Derivation, forces: tuple[ConstraintForce, ...], pr: Printer, transformed: tuple[Transformed, Any] | None
) -> list[dict[str, str]]:
    return build_steps(d) + constraint_steps(d, forces, pr) + (transform_steps(transformed[0]) if transformed else [])


def add_beyond(
    d: Derivation, scene: Scene | None, result: dict[str, Any], pr: Printer, skipped: list[Skipped] | None = None
) -> None:
    """Hamilton's equations after h, the normal modes after them: steps and JSON, each within its own bound."""
    skipped = [] if skipped is None else skipped
    ham = None
    h = _member(d.hamilton, None, skipped)
    if h is not None:
        ham = bounded("hamilton", "Hamilton's equations", d.member_work("hamilton"),
                      lambda: (h, hamilton_steps(d, h), hamilton_json(d, h)), None, skipped)  # fmt: skip
    modes = None
    nm = _member(d.normal_modes(held_momenta(d, scene)), None, skipped)
    if nm is not None:
        modes = bounded("normal_modes", "The equilibria and normal modes", d.member_work("normal_modes"),
                        lambda: (normal_mode_steps(d, nm), normal_modes_json(nm, pr)), None, skipped)  # fmt: skip
    steps = result["steps"]
    keys = [s["key"] for s in steps]
    # Hamilton's equations right after h (and after the power of the forces when there is one)
    after = max(
        (i + 1 for i, k in enumerate(keys) if k in ("hamiltonian", "h-vs-e", "power")),
        default=len(steps),
    )
    # the normal modes after the chapter's own steps, before constraint forces and coordinate changes
    end = next((i for i, k in enumerate(keys) if k in ("constraints", "change-of-coordinates")), len(steps))
    result["steps"] = (
        steps[:after] + (ham[1] if ham else []) + steps[after:end] + (modes[0] if modes else []) + steps[end:]
    )
    result["hamilton"] = ham[2] if ham else None
    result["normal_modes"] = modes[1] if modes else []
    if modes and nm is not None and scene is not None and scene.upward_angles:
        from_below(result["steps"], nm, scene.upward_angles)


def from_below(steps: list[dict[str, Any]], nm: NormalModes, upward: tuple[str, ...]) -> None:
    """Each steady motion's title gives an angle measured from the upward vertical also from the downward one,
    π − θ (the other pages measure θ from below; the two numbers say the same cone)."""
    for number, e in enumerate(nm.equilibria, start=1):
        step = next((s for s in steps if s["key"] == f"steady-motion:{number}"), None)
        shown = [q for q in upward if q in e.position]
        if step is None or not shown:
            continue
        # π − θ: the same direction measured from the downward vertical
        below = ", ".join(f"π − {unicode(q)} = {math.pi - e.position[q]:.4g} rad" for q in shown)
        step["title"] += f" ({below} from the downward vertical)"


def scene_json(scene: Scene) -> dict[str, Any]:
    """The scene as data, the one place it is written out: what the API lists, the document's ``scene`` block
    and the page's facts (statement, figure, panels, defaults, events, the family it is drawn as)."""
    return {
        "id": scene.id,
        "title": scene.title,
        "section": scene.section,
        "summary": scene.summary,
        "statement": scene.statement,
        "figure": scene.figure,
        "run_note": scene.run_note,
        "coordinates": list(scene.system.coordinates),
        "parameters": parameters_json(scene.system.parameters),
        "initial": dict(scene.initial),
        "t_end": scene.t_end,
        "panels": list(scene.panels),
        "beyond_chapter": scene.beyond_chapter,
        "events": [{"name": e.name, "expression": e.expression, "message": e.message} for e in scene.events],
        "family": scene.family,
        "marks": list(scene.marks),
        "answers": list(scene.answers),
        "exact_frequency": scene.exact_frequency,
    }


def constraint_force_json(f: ConstraintForce, pr: Printer) -> dict[str, Any]:
    """One force of constraint: a function of q, q_dot, t and parameters, with its sign convention."""
    direction = unit_gradient(f)
    return {
        "name": f.constraint.name,
        **pr.pair(f.force),
        "convention": f.constraint.convention,
        "slack_when_negative": f.constraint.slack_when_negative,
        "constraint": pr.pair(f.g),
        "particle": f.constraint.on,
        # the unit vector along grad g on that particle (the way a positive force points), for drawing
        "direction": [sp.sstr(e) for e in direction],
        "direction_trees": [maybe_of_sympy(e) for e in direction],
        # every particle the force acts on (a string's tension pulls each mass it holds), for drawing
        "acts_on": acting_on(f),
    }


def acting_on(f: ConstraintForce) -> list[dict[str, Any]]:
    """Each particle i with grad_i g ≠ 0: its number (from 1), the unit vector along grad_i g, and the ratio
    |grad_i g| / |grad_on g|: the force on i is the reported signed size times that ratio along that vector."""
    out = []
    norm_on = sp.sqrt(pythagoras(sp.expand(sum(e**2 for e in f.gradient))))
    for i, grad in enumerate(f.gradients, start=1):
        if all(e == 0 or is_zero(e) for e in grad):
            continue
        norm = sp.sqrt(pythagoras(sp.expand(sum(e**2 for e in grad))))
        out.append({
            "particle": i,
            "ratio_tree": maybe_of_sympy(norm / norm_on),
            "direction_trees": [maybe_of_sympy(e / norm) for e in grad],
        })  # fmt: skip
    return out


def unit_gradient(f: ConstraintForce) -> tuple[sp.Expr, ...]:
    """grad_i g / |grad_i g| on the motion, with sin² + cos² = 1 collapsed in |grad_i g|²."""
    norm = sp.sqrt(pythagoras(sp.expand(sum(e**2 for e in f.gradient))))
    return tuple(e / norm for e in f.gradient)


def _original(tr: Transformed, expr: sp.Expr) -> sp.Expr:
    """A conserved quantity of the new coordinates in the original ones, by meaning: a momentum grouped by
    velocity, an energy with its springs' squares (½k(x₂ − x₁ − l₀)², never multiplied out)."""
    back = tr.to_original(expr)
    velocities = sorted((s for s in back.free_symbols if s.name.endswith("_dot")), key=str)
    if sp.Poly(back, *velocities).total_degree() <= 1 if velocities else False:
        return _show(meaning.by_velocity(back, velocities))
    return _show(meaning.springs(back, tr.original.q))


def transformed_json(tr: Transformed) -> dict[str, Any]:
    """The derivation again in the declared new coordinates, with the maps between the two sets."""
    d = tr.derivation
    old = Printer(tr.original.latex_names())
    pr = Printer(d.table.latex_names())
    names = d.table.names
    full = derivation_json(d, beyond=False)
    by_name = {c.name: c for c in d.energetics.conserved}
    return {
        "coordinates": list(names),
        "definitions": {name: old.pair(f) for name, f in zip(names, tr.definitions, strict=True)},
        "inverse": {q.name: pr.pair(e) for q, e in tr.inverse.items()},
        "lagrangian": pr.pair(new_lagrangian(tr)),
        **{key: full[key] for key in ("accelerations", "momenta", "mass_matrix", "cyclic", "effective_potential")},
        "conserved": [{**c, "original": old.pair(_original(tr, by_name[c["name"]].expr))} for c in full["conserved"]],
        "inertia": {n: pr.pair(m) for n, m in zip(names, tr.inertia, strict=True)},
        "reduced_mass": pr.pair(tr.reduced_mass) if tr.reduced_mass is not None else None,
        "relative_motion": _relative_motion(tr, pr),
    }


def _relative_motion(tr: Transformed, pr: Printer) -> dict[str, str] | None:
    """The relative coordinate's equation as one body of the reduced mass obeys it, μ ẍ = −k (x − l₀), and its
    frequency ω = √(k/μ); None unless its force is linear in it with a constant, positive stiffness."""
    d, relative = tr.derivation, tr.change.relative
    if tr.reduced_mass is None or relative is None or relative not in d.table.names:
        return None
    i = d.table.names.index(relative)
    x, xdd = d.table.q[i], d.table.qdd[i]
    # the force on the relative coordinate: reduced mass times its acceleration
    force = sp.expand(tr.reduced_mass * d.equations.accelerations[i])
    stiffness = sp.factor(sp.cancel(-sp.diff(force, x)))
    if sp.diff(force, x, 2) != 0 or stiffness == 0 or stiffness.free_symbols & {*d.table.q, *d.table.qd}:
        return None
    # force = −K (x − x₀): x₀ is where the force vanishes (the spring's rest length)
    rest = sp.factor(sp.cancel(force.subs(x, 0) / stiffness))
    k = pr.tex(stiffness)
    k = rf"\left({k}\right)" if stiffness.is_Add else k
    return {
        "equation": rf"\mu {pr.tex(xdd)} = -{k} \left({pr.tex(x - rest, x)}\right)",
        "frequency": rf"\omega = \sqrt{{\frac{{{pr.tex(stiffness)}}}{{\mu}}}}",
    }


# What the whole document adds to the first stage, as the page names it while it waits.
PENDING = (
    ("steps", "the step-by-step derivation"),
    ("conserved", "the conserved quantities"),
    ("momenta", "the generalized momenta"),
    ("hamilton", "Hamilton's equations"),
    ("normal_modes", "the normal modes"),
)


def first_stage(d: Derivation) -> dict[str, Any]:
    """The first stage of a document (the playground shows it while the rest is derived): the equations of
    motion and the accelerations (or M and f when they stay M⁻¹f), printed, with what is still pending."""
    table, eqs = d.table, d.equations
    pr = Printer(table.latex_names())
    skipped: list[Skipped] = []
    with display_budget(FIRST_DISPLAY_WORK):
        # the equations first: what the student waits for; the rest of this stage shares what is left
        equations = _equation_pairs(d, pr)
        accelerations = _accelerations(d, pr, skipped)
        document = {
            "stage": "equations",
            "coordinates": list(table.names),
            "angles": notation.angle_coordinates(d),
            "symbols": symbol_names(d),
            "notation": notation.table(d),
            "parameters": parameters_json(d.system.parameters),
            "equations_of_motion": [
                {"coordinate": name, **pair} for name, pair in zip(table.names, equations, strict=True)
            ],
            "accelerations": accelerations,
            "mass_matrix": [[pr.pair(x) for x in row] for row in eqs.mass_matrix.tolist()],
            "forcing": [pr.pair(_shown(x)) for x in eqs.forcing] if not eqs.closed_form else [],
            "skipped": [{"member": s.member, "reason": s.reason} for s in skipped],
            "pending": [{"member": member, "name": name} for member, name in PENDING],
        }
    return document
