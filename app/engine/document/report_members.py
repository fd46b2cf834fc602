"""The steps of the members beyond the chapter's core: the forces of constraint and the change of coordinates."""

from __future__ import annotations

import sympy as sp

from app.engine.derivation.derive import Derivation, Transformed
from app.engine.display import meaning
from app.engine.display.breaking import LIMIT, _group, width
from app.engine.display.forms import gathered
from app.engine.display.names import latex
from app.engine.document import notation
from app.engine.document.multipliers import Multipliers, derived_multipliers
from app.engine.document.notation import CONSTRAINT
from app.engine.document.report import Printer, _common_factor, _mapping_step, _step, display
from app.engine.equations.constraints import ConstraintForce
from app.engine.equations.constraints import display as constraint_display
from app.engine.equations.constraints import positive as constraint_positive
from app.engine.equations.transform import collected, compact


def _cartesian_printer(m: Multipliers, pr: Printer) -> Printer:
    """``pr`` with the Cartesian names: x, ẋ, ẍ (x₁, ẋ₁, ẍ₁ for several bodies; ξ₁, η₁, ζ₁ where the system
    already prints x₁, y₁ or z₁) and λ₁, λ₂."""
    names = dict(pr.names)
    # body i's components as x_i, y_i, z_i, or ξ_i, η_i, ζ_i where the system already prints one of those names
    # (notation.cartesian_names, the one rule the Symbols table reads too)
    printed = notation.cartesian_names([s.name for s in m.positions], set(pr.names.values()))
    for s, v, a in zip(m.positions, m.velocities, m.accelerations, strict=True):
        shown = printed[s.name]
        letter, index = latex(shown.rstrip("0123456789")), s.name[1:]
        sub = f"_{{{index}}}" if index else ""
        names |= {s: f"{letter}{sub}", v: rf"\dot{{{letter}}}{sub}", a: rf"\ddot{{{letter}}}{sub}"}
    names |= {lam: notation.multiplier(a)[0] for a, lam in enumerate(m.multipliers, start=1)}
    return Printer(names)


# the sentence, where the letters ξ, η, ζ first appear, that says why the Cartesian components are not x, y, z; a
# scene's own reason for the step keeps it (contract.explained), so that no page prints ξ unexplained
GREEK_CLAUSE = "The Cartesian coordinates are written"
_SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _greek_sentence(m: Multipliers, pr: Printer) -> str:
    """Why the bodies' Cartesian components are ξ, η, ζ: the names x, y, z (x₁, …) the system already prints as
    its own coordinates (the helix's z, the pulley's y₁ and y₂)."""
    taken = set(pr.names.values())
    clash = [s.name for s in m.positions if latex(s.name) in taken or s.name in taken]
    said = [n[0] + n[1:].translate(_SUBSCRIPTS) for n in clash]
    names = said[0] if len(said) == 1 else ", ".join(said[:-1]) + " and " + said[-1]
    indexed = any(s.name[1:] for s in m.positions)
    letters = "ξᵢ, ηᵢ, ζᵢ for body i" if indexed else "ξ, η, ζ"
    whose = "already names a coordinate" if len(said) == 1 else "already name coordinates"
    return f"{GREEK_CLAUSE} {letters} here, since {names} {whose} of this system."


def constraint_steps(d: Derivation, forces: tuple[ConstraintForce, ...], pr: Printer) -> list[dict[str, str]]:
    """The constraints in Cartesian form, the multipliers derived from the Lagrangian that holds them, and
    the forces the multipliers give."""
    if not forces:
        return []
    m = derived_multipliers(d, forces)
    cp = _cartesian_printer(m, pr)
    greek = cp.names.get(m.positions[0], "").startswith(r"\xi")  # the Cartesian names moved off the coordinates'
    lam = [notation.multiplier(a)[0] for a in range(1, len(forces) + 1)]
    newton = [
        rf"{cp.tex(mass)} {cp.tex(acc)} = {cp.tex(gathered(rhs))}" + (_signed(cp.tex(f)) if f != 0 else "")
        for mass, acc, rhs, f in zip(m.masses, m.accelerations, m.newton, m.applied, strict=True)
        if rhs != 0 or f != 0
    ]
    k = len(forces)
    # the cross coefficients Σ_i ∇_i𝒞_a · ∇_i𝒞_b / m_i (a ≠ b): zero where the normals are perpendicular; one that is
    # a multiple of a constraint (the helix's −(2/m)(ξ sin αζ − η cos αζ) = −(2/m)𝒞₂) is zero on the motion
    cross = {(a, b): m.normal[a, b] for a in range(k) for b in range(k) if a != b and m.normal[a, b] != 0}
    on_motion = all(sp.simplify(c.xreplace(m.on_motion)) == 0 for c in cross.values())
    zero = [_vanishing(cp, c, m) for (a, b), c in cross.items() if a < b] if on_motion else []
    shown = [[b for b in range(k) if m.normal[a, b] != 0 and not (on_motion and a != b)] for a in range(k)]
    # each equation divided through by the number its two sides share: (2/m)(ξ² + η²) λ₁ = ξ̇² + η̇², not 4/m and 2
    common = [_shared_number([m.normal[a, b] for b in shown[a]] + [m.right[a]]) for a in range(k)]
    right = [m.right[a] / common[a] for a in range(k)]
    normal = [
        _right(cp, _terms([(_factor(cp, gathered(m.normal[a, b] / common[a])), lam[b]) for b in shown[a]]), gathered(right[a]))
        for a in range(k)
    ]
    path, on_path = on_path_equations(m, cp, pr, lam)
    positive = constraint_positive(d.system, d.table)
    solved = [constraint_display(e, positive) for e in m.solved]
    return [
        _step(
            "constraints",
            "Constraints in Cartesian form",
            [f"{notation.surface(a)[0]} = {(cp if greek else pr).tex(f.g)} = 0" for a, f in enumerate(forces, start=1)],
            [f.g for f in forces],
            "Each constraint the coordinates satisfy silently is written again as a surface 𝒞 = 0 in Cartesian "
            "space; it can only push along its normal, the gradient of 𝒞."
            + (" " + _greek_sentence(m, pr) if greek else ""),
        ),
        _step(
            "multiplier-lagrangian",
            "Lagrangian with the multipliers",
            [rf"L' = {cp.tex(m.lagrangian)}", *newton],
            [m.lagrangian, *m.newton],
            "In Cartesian coordinates every position is free, and each constraint joins the Lagrangian times an "
            "unknown multiplier λ. Its Euler–Lagrange equations are Newton's law, m r̈ = −∇U + λ ∇𝒞: the "
            "constraint pushes along its normal ∇𝒞, with a strength λ still to be found."
            + (" The force along the motion joins them as it is." if any(f != 0 for f in m.applied) else ""),
        ),
        _step(
            "multiplier-equation",
            "The multipliers along the normals",
            # 𝒞̈ = 0 said, not expanded: its expansion (a dozen terms on the turning parabola) is wider than a
            # page or a phone, and the equation for λ below is what it gives
            # each group of rows said in words, as the wedge's page reads: what is differentiated, what vanishes,
            # what is left for the multipliers
            [_said("differentiating each constraint twice:")]
            + [rf"\ddot{{{CONSTRAINT}}}_{{{a}}} = 0" for a in range(1, len(m.twice) + 1)]
            + ([_said(f"the cross coefficient{'s' if len(zero) > 1 else ''}, zero here:")] if zero else [])
            + zero
            + [_said(_left_for(k, bool(cross) and not on_motion))]
            + normal
            + path,
            [*m.twice, *right, *on_path],
            "The constraint holds at every instant, so its second time derivative vanishes. Putting r̈ from "
            "Newton's law into it keeps only the component of the equations along ∇𝒞: an equation for λ alone, "
            "with no acceleration left."
            + (" " + _coupling_sentence(bool(cross), on_motion) if k > 1 else "")
            + (
                f" {ON_PATH_CLAUSE} the coordinates give put in, each equation becomes short, and dividing by "
                "its coefficient gives λ."
                if on_path
                else ""
            ),
        ),
        _step(
            "multiplier",
            "The multipliers solved",
            [rf"{lam[a]} = {pr.tex(e)}" for a, e in enumerate(solved)],
            solved,
            "Solved for λ, with the positions and velocities of the motion put in for x, ẋ, ….",
        ),
        _step(
            "constraint-forces",
            "Forces of constraint",
            [
                # the force on the body the constraint names (``on``): λ times the size of 𝒞's gradient in its position
                rf"{notation.force(a)[0]} = {lam[a - 1]} \left|\frac{{\partial {notation.surface(a)[0]}}}"
                + rf"{{\partial \vec r_{{{f.constraint.on}}}}}\right| = {pr.tex(f.force)}"
                + rf"\quad (\text{{{f.constraint.name}}})"
                for a, f in enumerate(forces, start=1)
            ],
            [f.force for f in forces],
            "The force a constraint exerts on the body it acts on, at r_i, is λ ∂𝒞/∂r_i; its size "
            "F = λ |∂𝒞/∂r_i| is a function of the coordinates and velocities alone, positive along the gradient.",
        ),
    ]


# the sentence that says whether the equations for the multipliers are coupled: derived from the cross coefficients,
# a scene's own reason for the step keeps it (contract.explained)
NORMALS_CLAUSE = "The normals of the constraints are"


def _coupling_sentence(crossed: bool, on_motion: bool) -> str:
    """Whether the equations for λ₁, λ₂, … are coupled, as their cross coefficients Σ_i ∇_i𝒞_a · ∇_i𝒞_b / m_i say."""
    normals = NORMALS_CLAUSE
    if not crossed:
        return f"{normals} perpendicular, so each λ comes from its own equation."
    if on_motion:
        return (
            f"{normals} perpendicular here: on the path every cross coefficient is zero, so each λ comes from its "
            "own equation."
        )
    return f"{normals} not perpendicular here, so the equations for the multipliers are coupled."


def _said(words: str) -> str:
    """A row of words before the rows it introduces (set from the alignment column, as a row without "=" is)."""
    return rf"\text{{{words}}}"


def _left_for(k: int, coupled: bool) -> str:
    """The words before the equations for the multipliers: λ₁ alone, each λ alone, or the multipliers together."""
    # (the row is LaTeX text: a letter of the mathematics leaves \text for math mode, as KaTeX's strict mode asks)
    if k == 1:
        return r"so for }\lambda_1\text{ alone:"
    return "so, for the multipliers together:" if coupled else r"so, for each }\lambda\text{ alone:"


# the words before the equations for the multipliers put on the path, where the positions the coordinates fix are
# written in for the Cartesian ones; and the sentence that says so, which a scene's own reason for the step keeps
# (contract.explained)
ON_PATH = "on the path, "
ON_PATH_CLAUSE = "On the path, with the positions"


def on_path_equations(m: Multipliers, cp: Printer, pr: Printer, lam: list[str]) -> tuple[list[str], list[sp.Eq]]:
    """The equations for the multipliers once more, on the path: where they hold a Cartesian position or velocity,
    each is written with the positions the coordinates fix (ξ = R cos αz, η = R sin αz, ζ = z on the helix, and
    their rates), each side in its textbook form, so that the solved λ follows in one line:
    (2R²/m) λ₁ = α²R²ż².  No rows where the equations hold none (the pulley's, the wedge's).  The rows, and the
    equations they print (Σ_b coefficient λ_b = right side)."""
    k = len(lam)
    cartesian = set(m.positions) | set(m.velocities)
    held = set().union(*(e.free_symbols for e in (*m.normal, *m.right)))
    if not held & cartesian:
        return [], []
    # the positions shown: those whose letter, or whose rate, the equations hold, each as the Positions step
    # prints it (R(1 − cos θ), not −R cos θ + R)
    shown = [s for s, v in zip(m.positions, m.velocities, strict=True) if {s, v} & held]
    where = [(cp.tex(s), pr.tex(_common_factor(m.on_motion[s]))) for s in shown]
    # Σ_b (Σ_i ∇_i𝒞_a · ∇_i𝒞_b / m_i) λ_b = Σ_i ∇_i𝒞_a · (∇_i U − F_i)/m_i − c_a, with r_i = r_i(q, t) and
    # ṙ_i = ṙ_i(q, q̇, t) put in: a cross coefficient that vanishes on the motion is left out, as above
    coefficient = m.normal.applyfunc(lambda e: sp.simplify(e.xreplace(m.on_motion)))
    right = [sp.simplify(m.right[a].xreplace(m.on_motion)) for a in range(k)]
    # each divided through by the number its two sides share: (2R²/m) λ₁ = R(Rθ̇² + g cos θ), not 4R²/m and 2R
    for a in range(k):
        c = _shared_number([coefficient[a, b] for b in range(k) if coefficient[a, b] != 0] + [right[a]])
        coefficient[a, :] = coefficient[a, :] / c
        right[a] = right[a] / c
    rows = [
        _right(
            pr,
            _terms([(_factor(pr, display(coefficient[a, b])), lam[b]) for b in range(k) if coefficient[a, b] != 0]),
            display(right[a]),
        )
        for a in range(k)
    ]
    equations = [
        sp.Eq(sum((coefficient[a, b] * m.multipliers[b] for b in range(k)), sp.Integer(0)), right[a]) for a in range(k)
    ]
    # each position one group ({ξ=R cos αz}: its "=" is not where the row aligns, nor where a phone breaks it),
    # a phone's line break allowed after each \quad between them (static/js/breaking.js)
    words = rf"\text{{{ON_PATH}}}" + r",\quad ".join(f"{{{name}={value}}}" for name, value in where) + r"\text{:}"
    if width(words) > LIMIT:
        # too wide for one line: the words alone, then one position a line
        return [_said(ON_PATH.rstrip(", ") + ":"), *(f"{name} = {value}" for name, value in where), *rows], equations
    return [words, *rows], equations


def _shared_number(sides: list[sp.Expr]) -> sp.Integer:
    """The largest whole number that divides every term of every side (2 in 4/m λ = 2 ẋ²), 1 if none: an
    equation a textbook divides through by it before printing."""
    numbers = [sp.Rational(t.as_coeff_Mul()[0]) for e in sides if e != 0 for t in sp.Add.make_args(sp.expand(e))]
    if not numbers or any(not n.is_Rational for n in numbers):
        return sp.Integer(1)
    shared = sp.gcd([abs(n.p) for n in numbers])
    # only a whole number shared by every numerator, and no denominator made: (1/2)… stays as it is
    return sp.Integer(shared) if shared > 1 and all(n.q == 1 or n.p % shared == 0 for n in numbers) else sp.Integer(1)


def _vanishing(cp: Printer, c: sp.Expr, m: Multipliers) -> str:
    """A cross coefficient that vanishes on the motion, shown vanishing: as a multiple of the constraint it is
    (−(2/m)(ξ sin αζ − η cos αζ) = −(2/m)𝒞₂ = 0), else as it is, = 0."""
    shown = cp.tex(gathered(c))
    for a, g in enumerate(m.constraints, start=1):
        ratio = sp.cancel(c / g)
        if not ratio.free_symbols & set(m.positions):
            factor = "" if ratio == 1 else ("-" if ratio == -1 else _factor(cp, gathered(ratio)) + r"\,")
            return rf"{shown} = {factor}{notation.surface(a)[0]} = 0"
    return f"{shown} = 0"


def _right(cp: Printer, head: str, e: sp.Expr) -> str:
    """The row ``head = e`` of an equation for λ; where it is too wide for a page, a constant times a long sum on the
    right is multiplied out, so that the row breaks at its terms as every long row does (app.engine.display.breaking)."""
    row = f"{head} = {cp.tex(e)}"
    if isinstance(e, sp.Mul) and width(row) > LIMIT:
        spread = sp.expand(e)
        if isinstance(spread, sp.Add):
            return f"{head} = {cp.tex(spread)}"
    return row


def _factor(cp: Printer, e: sp.Expr) -> str:
    """A coefficient before a multiplier: in brackets when it prints as a sum."""
    text = cp.tex(e)
    return rf"\left({text}\right)" if isinstance(cp.form(e), sp.Add) else text


def _signed(text: str) -> str:
    """`` + a`` or `` − a`` for a term joining a sum."""
    return f" - {text[1:].lstrip()}" if text.startswith("-") else f" + {text}"


def _terms(pairs: list[tuple[str, str]]) -> str:
    """coefficient λ + coefficient λ, a negative coefficient's sign taken into the sum: a λ₁ − b λ₂."""
    out = ""
    for coefficient, name in pairs:
        negative = coefficient.startswith("-") and not coefficient.startswith(r"-\left(")
        body = coefficient[1:].lstrip() if negative else coefficient
        # a coefficient 1/D takes the multiplier over its bar, as a textbook writes it: λ₁/m, never (1/m) λ₁
        if body.startswith(r"\frac{1}{"):
            denominator, end = _group(body, len(r"\frac{1}"))
            if end == len(body):
                out += f"{(' - ' if out else '-') if negative else (' + ' if out else '')}\\frac{{{name}}}{{{denominator}}}"
                continue
        sign = (" - " if out else "-") if negative else (" + " if out else "")
        out += f"{sign}{body} {name}"
    return out


def transform_steps(tr: Transformed) -> list[dict[str, str]]:
    """The change of coordinates, the Lagrangian in the new ones and what it reveals."""
    d = tr.derivation
    old = Printer(tr.original.latex_names())
    pr = Printer(d.table.latex_names())
    steps = [
        _step(
            "change-of-coordinates",
            "Change of coordinates",
            [f"{pr.tex(Q)} = {old.tex(f)}" for Q, f in zip(d.table.q, tr.definitions, strict=True)],
            list(tr.definitions),
            tr.change.explanation or "New generalized coordinates, defined from the old ones.",
        ),
        _mapping_step(
            "inverse-map",
            "Inverse map",
            tr.inverse,
            "Solving the definitions for the old coordinates gives the map that is substituted into the declaration.",
            old,
            pr,
        ),
        _step(
            "new-lagrangian",
            "Lagrangian in the new coordinates",
            [f"L = {pr.tex(new_lagrangian(tr))}"],
            new_lagrangian(tr),
            "The same Lagrangian, now a function of the new coordinates and their velocities.",
        ),
    ]
    M = d.equations.mass_matrix
    rows = [rf"{notation.letter('mass_matrix', d)} = {pr.tex(M.applyfunc(display))}"]
    why = "The mass matrix in the new coordinates."
    if tr.decoupled:
        why = "The mass matrix is diagonal: each new coordinate moves with its own inertia, unmixed with the others."
    if tr.reduced_mass is not None:
        rows.append(rf"\mu = {pr.tex(tr.reduced_mass)}")
        why += f" The inertia of {tr.change.relative} is the reduced mass μ."
    steps.append(_step("new-inertia", "Inertia of the new coordinates", rows, M.applyfunc(display).tolist(), why))
    acc = [display(a) for a in d.equations.accelerations]
    steps.append(
        _step(
            "new-equations",
            "Equations in the new coordinates",
            [f"{pr.tex(s)} = {pr.tex(a)}" for s, a in zip(d.table.qdd, acc, strict=True)],
            acc,
            "The Euler–Lagrange equations derived again from the new Lagrangian.",
        )
    )
    for c in d.energetics.conserved:
        if c.name.startswith("p_"):
            back = tr.to_original(c.expr)
            # each side grouped by its own velocities: (m₁ + m₂)Ẋ = m₁ẋ₁ + m₂ẋ₂
            original = display(meaning.by_velocity(back, sorted((s for s in back.free_symbols if s.name.endswith("_dot")), key=str)))
            new = display(meaning.by_velocity(c.expr, d.table.qd))
            steps.append(
                _step(
                    f"conserved:{c.name}",
                    f"Conserved {c.name}",
                    [f"{c.latex_name} = {pr.tex(new)} = {old.tex(original)}"],
                    [new, original],
                    f"{c.reason} Written in the original coordinates it is the quantity on the right.",
                )
            )
    return steps


def new_lagrangian(tr: Transformed) -> sp.Expr:
    """L in the new coordinates, grouped by powers of the velocities (T) minus a compact U."""
    m = tr.derivation.mechanics
    if m.T is None:
        return collected(m.L, tr.derivation.table.qd)
    return collected(m.T, tr.derivation.table.qd) - compact(m.U)
