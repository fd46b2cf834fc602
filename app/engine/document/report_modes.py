"""Hamilton's equations and the normal modes as derivation steps and as JSON.

Steps follow ``app.engine.document.report`` (``{"key", "title", "latex", "sympy",
"explanation"}``); the JSON blocks are the derivation document's ``hamilton``
and ``normal_modes``, with numbers at the default parameters.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import sympy as sp

from app.engine.algebra.budget import memoized
from app.engine.algebra.simplify import pythagoras
from app.engine.derivation.derive import Derivation
from app.engine.derivation.dimensions import add_dims, parse_unit, system_dimensions, unit_latex, unit_text
from app.engine.display.breaking import PHONE, width
from app.engine.display.forms import whole_denominator
from app.engine.display.names import latex
from app.engine.display.root_forms import trig_cancelled
from app.engine.display.textbook import unicode_text
from app.engine.document import notation
from app.engine.document.damping import damped
from app.engine.document.report import Printer, _step, display, plain_name
from app.engine.equations.hamilton import Hamilton
from app.engine.equations.reduction import Equilibrium as ReducedEquilibrium
from app.engine.equilibria.equilibrium import MAX_EQUILIBRIA, Equilibrium, Mode, defaults
from app.engine.equilibria.modes import NEUTRAL, STABLE, NormalModes
from app.engine.equilibria.stability import Linear


def _show(expr: sp.Expr) -> sp.Expr:
    """Hamilton's expressions are compact as built: only common factors are pulled out (once per document:
    the steps and the JSON block show the same ones)."""
    return memoized("hamilton-shown", expr, lambda: sp.factor_terms(_collapsed(expr)))


def _collapsed(expr: sp.Expr) -> sp.Expr:
    """sin² + cos² of one argument collapsed (p_θ/(mR²), not p_θ/(mR² sin² θ + mR² cos² θ)), kept only when that
    shortens the expression: collapsing expands, and the double pendulum's ṗ₁ over (m₁ + m₂ sin²(θ₁ − θ₂))² would
    come back multiplied out, several times as long."""
    collapsed = pythagoras(expr)
    return collapsed if sp.count_ops(collapsed) < sp.count_ops(expr) else expr


def _hamiltonian_shown(ham: Hamilton) -> sp.Expr:
    """H as built, its completed squares (p_x + eBy/2)² kept whole: pulling common factors out of them would
    print (2p_x + eBy)²/(8m), so each square of a sum holding a momentum stands in as one symbol meanwhile."""
    squares = {
        w: sp.Dummy()
        for w in ham.hamiltonian.atoms(sp.Pow)
        if w.exp == 2 and w.base.is_Add and w.base.has(*ham.momenta)
    }
    return _show(ham.hamiltonian.xreplace(squares)).xreplace({v: w for w, v in squares.items()})


def hamilton_printer(d: Derivation, ham: Hamilton) -> Printer:
    """The derivation's printer, with the momentum of coordinate q printed p_q."""
    names = d.table.latex_names()
    for P in ham.momenta:
        names[P] = latex(P.name)
    return Printer(names)


def hamilton_steps(d: Derivation, ham: Hamilton) -> list[dict[str, str]]:
    table = d.table
    pr = hamilton_printer(d, ham)
    qn = [pr.tex(s) for s in table.q]
    pn = [pr.tex(P) for P in ham.momenta]
    # ṗ_θ: the dot on the p, not over its subscript (app.engine.display.names, the one home of a dotted name)
    pdn = [latex(f"{P.name}_dot") for P in ham.momenta]
    vn = [pr.tex(v) for v in table.qd]
    # over whole numbers, as the accelerations are: the rolling cylinder's ṡ over m(3M + m + 2m sin² α)/2's double
    velocities = [whole_denominator(_show(v)) for v in ham.velocities]
    H = _hamiltonian_shown(ham)
    p_dot = [_show(x) for x in ham.p_dot]
    forced = any(f != 0 for f in d.mechanics.Q)
    offsets = any(b != 0 for b in ham.offsets)
    Mu = notation.text("mass_matrix", d)
    return [
        _step(
            "legendre",
            "Velocities from the momenta",
            [f"{vn[k]} = {pr.tex(v)}" for k, v in enumerate(velocities)],
            velocities,
            (
                f"The momenta are linear in the velocities, p = {Mu} q̇ + b (b, the momenta at rest, comes from the "
                f"terms of L linear in q̇); solving for the velocities gives q̇ = {Mu}⁻¹ (p − b)."
                if offsets
                else f"The momenta are linear in the velocities, p = {Mu} q̇; solving for the velocities gives "
                f"q̇ = {Mu}⁻¹ p."
            ),
        ),
        _step(
            "hamiltonian-pq",
            "Hamiltonian H(q, p)",
            [rf"H = \sum_k p_k \dot{{q}}_k - L = {pr.tex(H)}"],
            H,
            "The same h, now written in the coordinates and momenta: "
            + (f"H = ½ (p − b)·{Mu}⁻¹(p − b) − L(q, q̇ = 0)." if offsets else f"H = ½ p·{Mu}⁻¹p − L(q, q̇ = 0)."),
        ),
        _step(
            "hamilton-equations",
            "Hamilton's equations",
            [rf"{vn[k]} = \frac{{\partial H}}{{\partial {pn[k]}}} = {pr.tex(v)}" for k, v in enumerate(velocities)]
            + [
                rf"{pdn[k]} = -\frac{{\partial H}}{{\partial {qn[k]}}}"
                + (f" + Q_{{{qn[k]}}}" if d.mechanics.Q[k] != 0 else "")
                + f" = {pr.tex(x)}"
                for k, x in enumerate(p_dot)
            ],
            [*velocities, *p_dot],
            "Two first-order equations per coordinate replace each second-order Euler–Lagrange equation"
            + (", with the generalized forces added to ṗ." if forced else "."),
        ),
    ]


def hamilton_json(d: Derivation, ham: Hamilton) -> dict[str, Any]:
    pr = hamilton_printer(d, ham)
    return {
        "hamiltonian": pr.pair(_hamiltonian_shown(ham)),
        "momenta": {name: P.name for name, P in zip(d.table.names, ham.momenta, strict=True)},
        "equations": [
            {"coordinate": name, "q_dot": pr.pair(_show(v)), "p_dot": pr.pair(_show(x))}
            for name, v, x in zip(d.table.names, ham.velocities, ham.p_dot, strict=True)
        ],
    }


def _figures(x: float) -> str:
    """A number found numerically, as a textbook prints a measured-looking value: four significant figures (an
    equilibrium's θ = 2.486 and held p_φ = 1.307, a mode's ω²: not θ = 2.48602, p_φ = 1.30733)."""
    return f"{x:.4g}"


# a number beside a closed form is the value at the scene's default parameters, and says so
AT_DEFAULTS = r"\quad \text{at the defaults}"
PER_SECOND_SQUARED = r"\,\mathrm{s}^{-2}"


# the longest exact shape component printed (SymPy's operation count); a longer one is shown as its number
SHAPE_MAX_OPS = 12


def _exact_shape(e: Equilibrium, m: Mode, d: Derivation) -> list[sp.Expr] | None:
    """The shape of a mode of two coordinates in closed form, normalised as the numbers are (the largest
    component 1), when ω² is exact and the other component is short; None otherwise."""
    if m.exact is None or len(m.shape) != 2 or sp.count_ops(m.exact) > SHAPE_MAX_OPS:
        return None
    # (K − ω² M) a = 0; with a_i = 1 one row gives A_ri + A_rj a_j = 0, so a_j = −A_ri / A_rj
    A = e.stiffness - m.exact * e.mass
    i = max(range(2), key=lambda k: abs(m.shape[k]))
    j = 1 - i
    defaults = {s: p.default for p in d.system.parameters for s in d.table.params if s.name == p.name}
    for r in range(2):
        if sp.cancel(A[r, j]) == 0:
            continue
        other = sp.factor(sp.cancel(-A[r, i] / A[r, j]))
        # the closed form must reproduce the numbers at the default parameters, else the numbers are shown
        value = complex(other.xreplace(defaults).evalf()) if other.free_symbols <= set(defaults) else None
        if value is None or abs(value - m.shape[j]) > 1e-9 * max(1.0, abs(m.shape[j])):
            return None
        if sp.count_ops(other) > SHAPE_MAX_OPS:
            return None
        return [sp.Integer(1), other] if i == 0 else [other, sp.Integer(1)]
    return None


def _named_radicand(e: Equilibrium, pr: Printer, d: Derivation) -> tuple[sp.Expr, str, str] | None:
    """Where an exact ω² is wider than a phone's box and holds the square root of a long radicand (the double
    pendulum's), that radicand named once, as a textbook sets a long formula: (the root √R, its name's LaTeX Δ,
    the row "Δ = R"); None where every ω² fits or has no such root."""
    exact = [m.exact for m in e.modes if m.exact is not None and not m.exact.is_number]
    if not any(width(pr.tex(x)) > PHONE for x in exact):
        return None
    roots = [p for x in exact for p in x.atoms(sp.Pow) if p.exp == sp.S.Half and isinstance(p.base, (sp.Add, sp.Mul))]
    if not roots:
        return None
    radicand = max((p.base for p in roots), key=sp.count_ops)
    tex = notation.radicand(d)[0]
    # a product c·(a + b) written as the sum c a + c b, which a narrow page can break at its signs:
    # Δ = (m₁ + m₂)²(l₁ − l₂)² + 4(m₁ + m₂)m₂l₁l₂, not (m₁ + m₂)((m₁ + m₂)(l₁ − l₂)² + 4m₂l₁l₂)
    shown = radicand
    sums = [f for f in sp.Mul.make_args(radicand) if isinstance(f, sp.Add)]
    if isinstance(radicand, sp.Mul) and sums:
        widest = max(sums, key=sp.count_ops)
        shown = sp.Add(*[radicand / widest * term for term in sp.Add.make_args(widest)])
    expanded = pr.tex(shown)
    square = _completed_square(radicand, exact, sp.sqrt(radicand), pr)
    # the shorter of the two: Δ = [(M + m)g + kl]² − 4Mgkl, not its six terms multiplied out
    if square is not None and width(square) < width(expanded):
        expanded = square
    return sp.sqrt(radicand), tex, f"{tex} = {expanded}"


def _completed_square(radicand: sp.Expr, exact: list[sp.Expr], root: sp.Expr, pr: Printer) -> str | None:
    """The radicand of ω² = c (A ± √Δ) as a textbook prints the discriminant b² − 4ac of a quadratic in ω²: the
    square of the term A beside the root, less (or plus) what is left when that is a single product,
    Δ = [(M + m)g + kl]² − 4Mgkl; None where what is left is a sum, or no ω² has that form."""
    mark = sp.Dummy("root")
    for x in exact:
        if not x.has(root):
            continue
        numerator = sp.fraction(sp.together(x.xreplace({root: mark})))[0]
        sums = [f for f in sp.Mul.make_args(numerator) if isinstance(f, sp.Add) and f.has(mark)]
        if len(sums) != 1 or sums[0].coeff(mark) not in (1, -1):
            continue
        beside = sums[0] - sums[0].coeff(mark) * mark
        if beside == 0 or beside.has(mark) or not isinstance(beside, sp.Add):
            continue
        # Δ = A² − P: P a single product (4Mgkl), or Δ = A² + P where P is negative
        left = sp.factor(sp.expand(beside**2 - radicand))
        if left == 0 or isinstance(left, sp.Add) or any(isinstance(f, sp.Add) for f in sp.Mul.make_args(left)):
            continue
        sign, size = ("-", left) if not left.could_extract_minus_sign() else ("+", -left)
        return rf"\left[{pr.tex(beside)}\right]^{{2}} {sign} {pr.tex(size)}"
    return None


def _with_radicand(exact: sp.Expr, root: sp.Expr, name: str, pr: Printer) -> str | None:
    """ω² with the named radicand, its factor before a bracket of the sum that holds the root, as a textbook
    prints a long quotient: g/(2m₁l₁l₂) [(m₁ + m₂)(l₁ + l₂) − √Δ]; None where the root is not in it so."""
    if not exact.has(root):
        return None
    mark = sp.Dummy("root")
    # ω² = c (A ± √Δ) / D: the sum A ± √Δ in brackets, c / D before it
    numerator, denominator = sp.fraction(sp.together(exact.xreplace({root: mark})))
    sums = [f for f in sp.Mul.make_args(numerator) if isinstance(f, sp.Add) and f.has(mark)]
    if len(sums) != 1:
        return None
    inside = sums[0]
    sign = inside.coeff(mark)
    rest = inside - sign * mark
    if sign not in (1, -1) or rest == 0 or rest.has(mark):
        return None
    term = rf"\sqrt{{{name}}}"
    first = pr.tex(rest)
    if first.startswith("-"):
        # A negative: the root leads, √Δ − (m₁ + m₂)(l₁ + l₂), and a sum of two negatives keeps its order
        body = rf"{'-' if sign < 0 else ''}{term} - {first[1:].lstrip()}"
    else:
        body = f"{first} {'-' if sign < 0 else '+'} {term}"
    # \Bigl[ … \Bigr], not \left[ … \right]: the bracket is no group, so a phone's box may go on to a new line
    # after its ∓, as a textbook breaks a long bracket, instead of scrolling sideways
    return rf"{pr.tex(numerator / inside / denominator)} \Bigl[{body}\Bigr]"


def _where(e: Equilibrium, pr: Printer, d: Derivation) -> str:
    table = d.table
    sym = {s.name: s for s in table.q}
    parts = []
    for name, value in e.position.items():
        exact = e.exact.get(name) if e.exact else None
        parts.append(f"{pr.tex(sym[name])} = {pr.root(exact) if exact is not None else _figures(value)}")
    # a held momentum p_θ = 1 kg·m²/s carries its unit, as every number on the page does
    held = [rf"{pr.tex(sp.Symbol(n))} = {_figures(v)}{momentum_unit(d, n)}" for n, v in e.momenta.items()]
    return r",\; ".join(parts + held)


def _reduced(e: Equilibrium, d: Derivation) -> ReducedEquilibrium | None:
    """The reduction's symbolic equilibrium at the same place as ``e`` (one coordinate, no momentum held): it
    knows where the place exists (arccos(g/(Rw²)) needs Rw² > g) and when its ω² is positive; None otherwise."""
    red = d.reduction
    if red is None or red.momenta or e.momenta or not e.exact or len(e.exact) != 1:
        return None
    x = next(iter(e.exact.values()))
    return next((r for r in red.equilibria if sp.simplify(r.position - x) == 0), None)


def _relation(relation: sp.Relational, pr: Printer) -> str:
    """b > a in LaTeX, each side as the page prints it: R w^{2} > g."""
    return f"{pr.tex(relation.lhs)} > {pr.tex(relation.rhs)}"


def _relation_text(relation: sp.Relational) -> str:
    """b > a as running text prints it: Rw² > g."""
    return f"{unicode_text(relation.lhs)} > {unicode_text(relation.rhs)}"


def _turned(relation: sp.Relational) -> sp.Relational:
    """b > a turned round, a > b: where ω² is negative (Rw² > g at the hoop's bottom)."""
    return sp.StrictGreaterThan(relation.rhs, relation.lhs, evaluate=False)


NOT_NOW = r"(\text{not at the current parameters})"


def _exists_note(r: ReducedEquilibrium, pr: Printer) -> str:
    """Beside an equilibrium that exists only for some parameters: the condition."""
    assert r.exists is not None
    return rf"\quad (\text{{exists only when }} {_relation(r.exists, pr)})"


def _absent(nm: NormalModes, found: list[Equilibrium], d: Derivation) -> list[ReducedEquilibrium]:
    """The reduction's equilibria that exist only for some parameters and not at the current ones (the hoop's
    θ = ±arccos(g/(Rw²)) while Rw² < g): the numerical search cannot find them, but they are part of the answer."""
    red = d.reduction
    if red is None or red.momenta or nm.everywhere:
        return []
    here = [r for e in found if (r := _reduced(e, d)) is not None]
    return [r for r in red.equilibria if r.exists is not None and all(r is not h for h in here)]


def _family_of(e: Equilibrium, nm: NormalModes, d: Derivation) -> dict[str, sp.Expr] | None:
    """The closed-form family of equilibria (a coordinate left free) that ``e`` was picked from, if any."""
    if not e.exact or e.momenta:
        return None
    sym = {s.name: s for s in d.table.q}
    for family in nm.families:
        free = [n for n in e.exact if n not in family]
        if not family or not free:
            continue
        zero = {sym[n]: sp.Integer(0) for n in free}
        if all(sp.simplify(family[n].xreplace(zero) - e.exact[n]) == 0 for n in family):
            return family
    return None


def _relations(family: dict[str, sp.Expr], d: Derivation) -> list[tuple[sp.Expr, sp.Expr]]:
    """A family's conditions as a textbook writes them: the coordinates on the left, the rest on the right,
    the right side positive (x₂ − x₁ = l₀, not x₁ = x₂ − l₀)."""
    sym = {s.name: s for s in d.table.q}
    q = set(d.table.q)
    out = []
    for name, value in family.items():
        gap = sp.expand(sym[name] - value)
        left = sp.Add(*[t for t in sp.Add.make_args(gap) if t.free_symbols & q])
        right = left - gap
        if right.could_extract_minus_sign() or (right == 0 and left.could_extract_minus_sign()):
            left, right = -left, -right
        out.append((left, right))
    return out


def _family_tex(family: dict[str, sp.Expr], pr: Printer, d: Derivation) -> str:
    return r",\; ".join(f"{pr.tex(a)} = {pr.tex(b)}" for a, b in _relations(family, d))


def _family_text(family: dict[str, sp.Expr], d: Derivation) -> str:
    return ", ".join(f"{unicode_text(a)} = {unicode_text(b)}" for a, b in _relations(family, d))


def _any(d: Derivation, pr: Printer) -> str:
    return r"\text{any } " + r",\; ".join(pr.tex(s) for s in d.table.q)


def _rounded(matrix: sp.Matrix) -> sp.Matrix:
    """Numbers found numerically (a steady motion's K) to the four figures the rest of the step shows."""
    return matrix.applyfunc(
        lambda x: sp.sympify(x).xreplace({f: sp.Float(f, 4) for f in sp.sympify(x).atoms(sp.Float)})
    )


_KIND = {
    STABLE: "every ω² is positive, so each mode oscillates: a stable equilibrium",
    NEUTRAL: "one ω² is zero: along that mode nothing pulls back and the system drifts at constant speed "
    "(a neutral direction), while the other modes oscillate",
    "unstable": "a negative ω² means that small displacements along that mode grow exponentially, at the rate "
    "√(−ω²): an unstable equilibrium",
}


def _points(
    points: tuple[dict[str, float], ...],
    sym: dict[str, sp.Symbol],
    pr: Printer,
    label: str,
    exact: tuple[dict[str, sp.Expr] | None, ...] = (),
) -> list[str]:
    """Points listed without modes, each coordinate in closed form where one is known (π, not 3.14159)."""
    rows = []
    for i, p in enumerate(points):
        known: dict[str, sp.Expr] = (exact[i] or {}) if i < len(exact) else {}
        rows.append(
            r",\; ".join(f"{pr.tex(sym[n])} = {pr.tex(known[n]) if n in known else _figures(v)}" for n, v in p.items())
            + label
        )
    return rows


def _singular_points(nm: NormalModes, d: Derivation, pr: Printer, vname: str = "U") -> list[str]:
    """Equilibria where the coordinates fail (the mass matrix is singular: the pole of a sphere, r = 0): each
    with the coordinates that have a value there, and the ones that have none named (φ at the pole)."""
    sym = {s.name: s for s in d.table.q}
    defaults = {s: sp.Float(p.default) for s, p in zip(d.table.params, d.system.parameters, strict=True)}
    M = d.equations.mass_matrix
    rows = []
    for i, point in enumerate(nm.singular):
        known = (nm.singular_exact[i] or {}) if i < len(nm.singular_exact) else {}
        at = {sym[n]: known.get(n, sp.Float(v)) for n, v in point.items()}
        # a coordinate whose own inertia vanishes here (m r² θ̇² at r = 0) has no value at this point
        lost = [
            n for k, n in enumerate(d.table.names)
            if abs(complex(sp.N(M[k, k].xreplace(at).xreplace(defaults)))) < 1e-12
        ]  # fmt: skip
        shown = [n for n in point if n not in lost] or list(point)
        where = r",\; ".join(
            f"{pr.tex(sym[n])} = {pr.tex(known[n]) if n in known else _figures(point[n])}" for n in shown
        )
        # the note on a row of its own, so that a phone's narrow box needs no sideways scroll
        verdict = _pole_verdict(nm, d, point, known, lost, defaults) if lost else None
        if verdict is not None:
            extremum, stable, w2 = verdict
            kept = next(n for n in d.table.names if n not in lost)
            names = r",\; ".join(pr.tex(sym[n]) for n in lost)
            said = {True: r"\text{stable}", False: r"\text{unstable}", None: ""}[stable]
            if said and w2 is not None:
                said += rf",\quad {notation.letter('frequency', d)}^2 = {pr.tex(w2)}"
            where += rf":\quad {said}" if said else ""
            # judged by the potential along the coordinate that keeps a value (θ at a pole), said in words on a
            # row of its own, so that a phone's narrow box needs no sideways scroll
            rows.append(where)
            where = rf"(\text{{a {extremum} of }} {vname} \text{{ along }} {pr.tex(sym[kept])})"
            note = rf"(\text{{the coordinates fail: }} {names} \text{{ has no value}})"
        elif lost:
            names = r",\ ".join(pr.tex(sym[n]) for n in lost)
            note = rf"(\text{{the coordinates fail: }} {names} \text{{ has no value}})"
        else:
            note = r"(\text{the coordinates fail here})"
        rows += [where, note]
    return rows


def _pole_verdict(
    nm: NormalModes,
    d: Derivation,
    point: dict[str, float],
    known: dict[str, sp.Expr],
    lost: list[str],
    defaults: dict[sp.Symbol, sp.Expr],
) -> tuple[str, bool | None, sp.Expr | None] | None:
    """Where the coordinates fail at a point (φ at a sphere's pole), the potential along the one coordinate that
    keeps a value (θ): ("minimum" or "maximum", stable or unstable, ω² = V″/M there where it has a closed form).
    Every displacement from a pole is a change of θ in the direction φ, so V″ along θ must have one sign for
    every φ; None where it has not, or where more than one coordinate keeps a value."""
    table = d.table
    kept = [n for n in table.names if n not in lost]
    if len(kept) != 1:
        return None
    sym = {s.name: s for s in table.q}
    k = table.names.index(kept[0])
    q = table.q[k]
    # V″ along the kept coordinate, at the point, for directions φ all round
    second = sp.diff(nm.potential, q, 2).xreplace({sym[kept[0]]: known.get(kept[0], sp.Float(point[kept[0]]))})
    values = []
    for angle in (0.0, 1.0, 2.5, 4.0):
        at = {sym[n]: sp.Float(angle) for n in lost}
        value = complex(sp.N(second.xreplace(at).xreplace(defaults)))
        values.append(value.real if abs(value.imag) <= 1e-12 * max(abs(value), 1e-300) else float("nan"))
    scale = max(abs(v) for v in values) if all(v == v for v in values) else 0.0
    if scale == 0 or any(abs(v) <= 1e-9 * scale for v in values):
        return None
    if all(v > 0 for v in values):
        extremum = "minimum"
    elif all(v < 0 for v in values):
        extremum = "maximum"
    else:
        return None
    # velocity terms (a spin, a magnetic field) can hold a maximum: then only the extremum is said
    stable = None if nm.damped else extremum == "minimum"
    w2 = None
    if stable and kept[0] in known:
        # ω² = V″/M along the kept coordinate, where the position is known in closed form and φ drops out
        inertia = d.equations.mass_matrix[k, k].xreplace({q: known[kept[0]]})
        found = sp.simplify(second / inertia)
        w2 = found if not found.has(*(sym[n] for n in lost)) and found.is_positive is not False else None
    return extremum, stable, w2


def _how_found(nm: NormalModes, found: list[Equilibrium]) -> str:
    """How the list was found, and how far it can be trusted (never "exactly" unless provably complete)."""
    if nm.solved:
        return "These are all the equilibria: no other configuration makes every generalized force vanish" + (
            "; where the conditions leave a coordinate free, every state that satisfies them is one."
            if nm.family
            else "."
        )
    some_exact = any(e.exact for e in found)
    where = f" (it looked at {nm.searched})" if nm.searched else ""
    if nm.angles_only:
        # the whole configuration space was searched; only roots closer together than the search can tell apart escape
        return (
            ("Closed forms are shown where they are known; " if some_exact else "")
            + ("a" if some_exact else "A")
            + " search through a full turn of every angle, at the default parameters, found "
            + (("no others." if all(e.exact for e in found) else "the rest") if some_exact else "them")
            # a caveat only where some equilibrium rests on the search alone
            + (
                ""
                if some_exact and all(e.exact for e in found)
                else " (roots lying very close together could still escape it)."
            )
        )
    if some_exact:
        return (
            "Closed forms are shown where they are known; a numerical search at the default parameters"
            f"{where} completed the list, so others may exist outside that range."
        )
    return (
        f"The equilibria were found numerically at the default parameters{where}; others may exist outside that range."
    )


def normal_mode_steps(d: Derivation, nm: NormalModes) -> list[dict[str, str]]:
    table = d.table
    pr = Printer(table.latex_names())
    if nm.failed:
        return [_step("equilibria", "Equilibria", [r"\text{not computed}"], [], nm.failed)]
    qn = [pr.tex(s) for s in table.q]
    plain = d.mechanics.T is not None and d.mechanics.U is not None and sp.expand(d.mechanics.U - nm.potential) == 0
    vname = "U" if plain else notation.rest_potential(d)[0]
    forced = any(f.xreplace(dict.fromkeys(table.qd, 0)) != 0 for f in d.mechanics.Q)
    frame = r" + \frac{\partial b}{\partial t}" if nm.moving_frame else ""
    found = [e for e in nm.equilibria if not e.momenta]
    # with no equilibrium, a condition is never written "= 0": a force free of q is "≠ 0", one that depends on q
    # is shown as it is (its sentence says it has no root)
    none = not (found or nm.singular or nm.kinks or nm.unclassified)
    q_set = set(table.q)
    rows = [
        rf"\frac{{\partial {vname}}}{{\partial {qn[k]}}}{frame}{' - Q' if forced else ''} = {pr.tex(display(g))}"
        + ("" if g == 0 else (r" \neq 0" if not (sp.sympify(g).free_symbols & q_set) else "") if none else " = 0")
        for k, g in enumerate(nm.condition)
    ]
    if not plain:
        rows.insert(0, rf"{vname} = -L\big|_{{\dot q = 0}} = {pr.tex(display(nm.potential))}")
    listed: list[str] = []
    sym_q = {s.name: s for s in table.q}
    for e in found:
        family = _family_of(e, nm, d)
        if nm.everywhere:
            row = r"\text{every configuration is an equilibrium}"
        elif family is not None:
            row = r"\text{every state with } " + _family_tex(family, pr, d)
        else:
            row = _where(e, pr, d)
            # an equilibrium that exists only for some parameters says so beside it
            if (r := _reduced(e, d)) is not None and r.exists is not None:
                row += _exists_note(r, pr)
        if row not in listed:
            listed.append(row)
    # and one that does not exist at the current parameters is still listed, with its condition
    absent = _absent(nm, found, d)
    coordinate = d.reduction.coordinate if d.reduction is not None else ""
    for r in absent:
        # whether it holds now on a row of its own, so that a phone's narrow box needs no sideways scroll
        listed += [f"{pr.tex(sym_q[coordinate])} = {pr.root(r.position)}{_exists_note(r, pr)}", NOT_NOW]
    none = none and not absent
    if none:
        listed.append(r"\text{no equilibrium}")
    rows += listed
    sym = {s.name: s for s in table.q}
    rows += _singular_points(nm, d, pr, vname)
    rows += _points(nm.kinks, sym, pr, rf"\quad (\text{{at a kink of }} {vname})")
    rows += _points(nm.unclassified, sym, pr, r"\quad (\text{coefficients change with } t)", nm.unclassified_exact)
    why = "At rest (q̇ = 0) the state stays put where the Euler–Lagrange equations give q̈ = 0. "
    if not plain:
        why += (
            f"{notation.rest_potential(d)[1].replace('U_eff', 'The effective potential U_eff')} is the potential energy less "
            "the part T₀ of the kinetic energy without velocities (a moving constraint's share). "
        )
    if nm.moving_frame:
        why += (
            "L has a term b·q̇ whose b depends on t (a moving support), so d/dt of the momentum at rest, ∂b/∂t, "
            "enters the condition as well. "
        )
    if nm.everywhere:
        why += (
            # the page's own letter for the potential (U, or U_eff where the rows above write U_eff), never a third
            f"{'U' if plain else notation.rest_potential(d)[1]} does not depend on the coordinates and nothing else "
            "acts on a body at rest, so every configuration "
            "is an equilibrium"
            + (
                "; the velocity terms (a magnetic field, a Coriolis force) act only on moving bodies and turn them."
                if nm.damped
                else "."
            )
        )
    elif nm.note:
        why += nm.note
    else:
        why += _how_found(nm, found)
    conditions: list[sp.Relational] = []
    wu = notation.text("frequency", d)
    for r in absent:
        if r.exists not in conditions:
            conditions.append(r.exists)
    for c in conditions:
        group = [r for r in absent if r.exists == c]
        places = " and ".join(f"{plain_name(coordinate)} = {unicode_text(r.position)}" for r in group)
        many = len(group) > 1
        why += (
            f" {places} {'are equilibria' if many else 'is an equilibrium'} only when {_relation_text(c)}, which "
            f"does not hold at the current parameters: {'they are' if many else 'it is'} listed with that condition, "
            "and no small oscillations are worked out about "
            + ("them" if many else "it")
            + (
                f"; where {'they exist' if many else 'it exists'}, {wu}² = {unicode_text(group[0].omega_squared)} is "
                + ("positive (stable)." if group[0].stable else "negative (unstable).")
                if group[0].stable is not None and all(r.omega_squared == group[0].omega_squared for r in group)
                else "."
            )
        )
    if nm.found > MAX_EQUILIBRIA:
        why += f" {nm.found} were found; the first {MAX_EQUILIBRIA} are shown."
    if nm.singular:
        why += (
            f" At {len(nm.singular)} of them the coordinates themselves fail, as polar coordinates do at the origin: "
            "a coordinate there has no value, and no small oscillations are worked out in these coordinates about "
            "those points. Where one coordinate keeps a value (θ at a sphere's pole), each point is judged by the "
            "potential along it, since every small displacement is a change of that coordinate: a minimum is stable, "
            "a maximum unstable."
        )
    if nm.kinks:
        why += (
            f" At {len(nm.kinks)} of them V has a kink (an absolute value turns there), so the force jumps and no "
            "quadratic approximation, hence no frequency of small oscillations, exists at those points."
        )
    if nm.common_factor:
        why += (
            " Its linearised equations change with time only through a factor common to all their coefficients; "
            "divided by it, their coefficients are constant, and the exponents and frequencies below are theirs."
        )
    if nm.unclassified:
        why += (
            " The system stays at rest there at all times, but its linearised equations change with time, so "
            "there are no constant frequencies to report."
        )
    steps = [_step("equilibria", "Equilibria", rows, list(nm.condition), why)]
    for i, e in enumerate(nm.equilibria, start=1):
        steps.append(_equilibrium_step(e, pr, d, i, nm))
        if (beats := _beats_step(e, pr, d, i)) is not None:
            steps.append(beats)
    return steps


def _beats_step(e: Equilibrium, pr: Printer, d: Derivation, number: int) -> dict[str, str] | None:
    """Beats between two modes of shapes (1, 1) and (1, −1) with exact, distinct, positive ω²: started with one
    coordinate displaced by a and the other at rest, the motion passes from one to the other and back."""
    if len(e.modes) != 2 or e.momenta:
        return None
    shapes = [_exact_shape(e, m, d) for m in e.modes]
    if any(s is None for s in shapes) or [list(s) for s in shapes if s] != [[1, 1], [1, -1]]:
        return None
    if (
        any(m.exact is None or m.omega_squared <= 0 for m in e.modes)
        or e.modes[0].omega_squared == e.modes[1].omega_squared
    ):
        return None
    w1, w2 = (sp.sqrt(m.exact) for m in e.modes)
    At, Au = notation.letter("start", d), notation.text("start", d)
    t, a = d.table.t, sp.Symbol(Au, positive=True)
    q1, q2 = (pr.tex(s) for s in d.table.q[:2])
    half_difference, half_sum = (w2 - w1) / 2, (w1 + w2) / 2
    # q = (a/2)(1, 1) cos ω₁t + (a/2)(1, −1) cos ω₂t starts at (a, 0) at rest; cos A ± cos B as products
    first = a * sp.cos(half_difference * t) * sp.cos(half_sum * t)
    second = a * sp.sin(half_difference * t) * sp.sin(half_sum * t)
    # the products are the two modes' sums (cos A ± cos B), checked rather than assumed
    sums = (a * (sp.cos(w1 * t) + sp.cos(w2 * t)) / 2, a * (sp.cos(w1 * t) - sp.cos(w2 * t)) / 2)
    if any(sp.simplify((p - q).rewrite(sp.exp)) != 0 for p, q in zip((first, second), sums, strict=True)):
        return None
    w1n, w2n = (math.sqrt(m.omega_squared) for m in e.modes)
    wu = notation.text("frequency", d)
    wt = notation.letter("frequency", d)
    sum_tex, difference_tex = rf"\tfrac{{{wt}_1 + {wt}_2}}{{2}}", rf"\tfrac{{{wt}_2 - {wt}_1}}{{2}}"
    rows = [
        rf"{wt}_1 = {pr.tex(w1)},\quad {wt}_2 = {pr.tex(w2)}",
        rf"{q1} = \tfrac{{{At}}}{{2}} \left(\cos {wt}_1 t + \cos {wt}_2 t\right) "
        rf"= {At} \cos\left({difference_tex}\, t\right) \cos\left({sum_tex}\, t\right)",
        rf"{q2} = \tfrac{{{At}}}{{2}} \left(\cos {wt}_1 t - \cos {wt}_2 t\right) "
        rf"= {At} \sin\left({difference_tex}\, t\right) \sin\left({sum_tex}\, t\right)",
    ]
    why = (
        f"Started with {plain_name(d.table.names[0])} = {Au} and everything else at rest, the motion is half of each "
        f"mode: the sum and difference cos {wu}₁t ± cos {wu}₂t, written as products, show a fast oscillation at the mean frequency ({wu}₁ + {wu}₂)/2 "
        f"inside a slow envelope at ({wu}₂ − {wu}₁)/2. The motion passes from the first coordinate to the second and "
        f"back: the first is still and the second swings with the whole amplitude {Au} after π/({wu}₂ − {wu}₁), and "
        f"the first swings fully again after 2π/({wu}₂ − {wu}₁), the beat period (at the default parameters {_figures(math.pi / (w2n - w1n))} s and "
        f"{_figures(2 * math.pi / (w2n - w1n))} s). The weaker the coupling, the closer the two frequencies and the "
        "slower the exchange."
    )
    return _step(
        f"beats:{number}", "Beats: the motion passes from one coordinate to the other", rows, [first, second], why
    )


def exponent_letter(d: Derivation) -> str:
    """The letter of the exponents of e^{σt}, λ or σ (app/engine/document/notation.py, the home of a page's letters)."""
    return notation.exponent(d)[0]


def _exponents(e: Equilibrium, d: Derivation, named: bool = True) -> str:
    """The exponents λ of e^{λt}, or σ (notation.exponent), in 1/s to four figures at the default parameters,
    each complex pair once."""
    lin = e.linear
    assert lin is not None
    shown = []
    for s in lin.exponents:
        if s.imag < -1e-12 * max(1.0, abs(s)):
            continue  # each pair once
        re = _figures(s.real) if abs(s.real) > 1e-9 * max(1.0, abs(s)) else "0"
        pair = s.imag > 1e-12 * max(1.0, abs(s))
        # a purely imaginary pair is ±2i, never 0 ± 2i
        shown.append((rf"\pm {_figures(s.imag)}i" if re == "0" else rf"{re} \pm {_figures(s.imag)}\,i") if pair else re)
    eta, r = notation.letter("displacement", d), exponent_letter(d)
    lead = rf"{eta} \propto e^{{{r} t}},\quad " if named else ""
    return rf"{lead}{r} = " + r",\; ".join(shown) + r"\,\mathrm{s}^{-1}" + AT_DEFAULTS


def _verdict(e: Equilibrium, d: Derivation) -> str:
    lin = e.linear
    Mu, Ku, wu = (notation.text(c, d) for c in ("mass_matrix", "stiffness", "frequency"))
    r = notation.exponent(d)[1]  # in a sentence, the Unicode letter
    if lin is None or not lin.moving:
        text = _KIND[e.kind].replace("ω", wu)
        return text[0].upper() + text[1:] + "."
    freq = ", ".join(_figures(f) for f in lin.frequencies)
    out = (
        "The velocity terms (G, from damping, Coriolis or magnetic forces) enter the motion near it: with "
        f"{notation.text('displacement', d)} = v e^{{{r}t}} "
        # the eigenvalues of the first-order system's block matrix [[0, I], [−M⁻¹K, −M⁻¹G]] are the roots of
        # det(σ²M + σG + K) = 0: η = v e^{σt} in M η̈ + G η̇ + K η = 0
        f"the exponents {r} are the roots of det({r}²{Mu} + {r}G + {Ku}) = 0. "
    )
    if e.kind == "unstable":
        out += "One has a positive real part, so small displacements grow: an unstable equilibrium."
    elif lin.damped and all(s.real < 0 for s in lin.exponents):
        out += "Every one has a negative real part, so small motions die away: an asymptotically stable equilibrium."
    elif e.kind == NEUTRAL:
        out += _neutral(lin, Ku, wu)
    else:
        out += "Every one is imaginary, so small motions oscillate" + (f" (frequencies {freq})" if freq else "") + "."
        if lin.gyroscopic:
            out += (
                f" {Ku} alone has a negative {wu}² (the potential is not a minimum there): the gyroscopic terms hold it, "
                "a gyroscopically stable equilibrium."
            )
    return out


_COUNT = {1: "One", 2: "Two", 3: "Three", 4: "Four", 5: "Five", 6: "Six"}


def _neutral(lin: Linear, Ku: str, wu: str) -> str:
    """A neutral equilibrium's exponents in words: how many are zero (free drifts), and the oscillations of the
    others, which come from G alone where K gives ω² = 0 in every direction (a charge in a magnetic field)."""
    scale = max([1.0, *(abs(s) for s in lin.exponents)])
    zeros = sum(1 for s in lin.exponents if abs(s) <= 1e-9 * scale)
    pairs = sorted({_figures(s.imag) for s in lin.exponents if s.imag > 1e-12 * scale})
    count = _COUNT.get(zeros, str(zeros))
    out = f"{count} {'is' if zeros == 1 else 'are'} zero ({'a free drift' if zeros == 1 else 'free drifts'})"
    if pairs:
        out += (
            ", the others are ±"
            + ", ±".join(f"{p}i" for p in pairs)
            + " (oscillations at "
            + ", ".join(pairs)
            + " rad/s)"
        )
        if all(abs(w) <= 1e-9 * scale**2 for w in lin.omega_squared):
            out += (
                f"; {Ku} gives {wu}² = 0 in every direction, so these frequencies come from the velocity terms G alone"
            )
    return out + ", and none grows: a neutral equilibrium."


def _equilibrium_step(e: Equilibrium, pr: Printer, d: Derivation, number: int, nm: NormalModes) -> dict[str, str]:
    """The modes about the ``number``-th equilibrium (key ``normal-modes:number``, or ``steady-motion:number``
    about a steady motion of a reduction)."""
    sym = {s.name: s for s in d.table.q}
    family = _family_of(e, nm, d)
    if nm.everywhere:
        where, about = _any(d, pr), "any configuration"
    elif family is not None:
        where, about = (
            r"\text{every state with } " + _family_tex(family, pr, d),
            "the equilibria " + _family_text(family, d),
        )
        free = [sym[n] for n in e.coordinates if n not in family]
        at = {sym[n]: v for n, v in family.items()}
        # M and K the same all along the family, or given where it was picked (the free coordinates at 0)
        if any((x.xreplace(at)).has(*free) for x in [*d.equations.mass_matrix, *nm.condition]):
            where += r"\quad (\text{at } " + r",\; ".join(f"{pr.tex(s)} = 0" for s in free) + ")"
            about += " (at " + ", ".join(f"{plain_name(s.name)} = 0" for s in free) + ")"
    else:
        where = _where(e, pr, d)
        about = ", ".join(
            f"{plain_name(n)} = {unicode_text(e.exact[n]) if e.exact and n in e.exact else _figures(v)}"
            for n, v in e.position.items()
        )
    if len(e.coordinates) == 1 and len(e.modes) == 1:
        return _one_coordinate_step(e, pr, d, number, where, about)
    Mt, Kt, wt = (notation.letter(c, d) for c in ("mass_matrix", "stiffness", "frequency"))
    Mu, Ku, wu = (notation.text(c, d) for c in ("mass_matrix", "stiffness", "frequency"))
    eu, au = (notation.text(c, d) for c in ("displacement", "amplitude"))
    order_text = ", ".join(plain_name(n) for n in e.coordinates)
    amp = notation.letter("amplitude", d)
    order = ", ".join(pr.tex(sym[n]) for n in e.coordinates)
    rows = [rf"{Mt} = {pr.tex(_rounded(e.mass))},\quad {Kt} = {pr.tex(_rounded(e.stiffness))}"]
    named = _named_radicand(e, pr, d)
    if named is not None:
        rows.append(named[2])
    # the order of the amplitudes in every mode's column, said once
    rows.append(rf"\text{{amplitudes of }} ({order})\text{{:}}")
    for i, m in enumerate(e.modes, start=1):
        # ω² in 1/s² whatever the coordinates; four figures at the default parameters beside the closed form
        unit = r"\,\mathrm{s}^{-2}" if m.omega_squared != 0 else ""
        closed = _with_radicand(m.exact, named[0], named[1], pr) if named is not None and m.exact is not None else None
        value = (
            (closed or pr.tex(m.exact)) + r" \approx " + _figures(m.omega_squared) + unit
            if m.exact is not None and not m.exact.is_number
            else (pr.tex(m.exact) if m.exact is not None else _figures(m.omega_squared)) + unit
        )
        exact_shape = _exact_shape(e, m, d)
        # the mode's amplitudes as a column vector, a_k = (1, −1)ᵀ, in the coordinates' order stated above
        column = r"\\".join(
            pr.tex(x) if exact_shape else _figures(a) for a, x in zip(m.shape, exact_shape or m.shape, strict=True)
        )
        rows.append(rf"{wt}_{{{i}}}^2 = {value},\quad {amp}_{{{i}}} = \begin{{pmatrix}}{column}\end{{pmatrix}}")
    moving = e.linear is not None and e.linear.moving
    if moving:
        rows.append(_exponents(e, d))
    if e.momenta:
        key = f"steady-motion:{number}"
        title = f"Small oscillations about the steady motion at {plain_name(e.coordinates[0])} = {_figures(e.position[e.coordinates[0]])}"
        why = (
            "With the conserved momenta held at the values shown, the reduced coordinate sits at a minimum or maximum of "
            f"U_eff: the body moves steadily (a circular or conical orbit), and {wu}² = U_eff''/"
            f"{notation.inertia(d).unicode}. "
        )
    else:
        key = f"normal-modes:{number}"
        title = "Normal modes about " + about
        # the method is said once, about the first equilibrium; the others say only what differs (their verdict)
        why = (
            (
                f"Near the equilibrium {Mu} {eu}̈ + {Ku} {eu} = 0, with {eu} the small displacement from it, {Mu} the "
                f"mass matrix and {Ku} the Hessian of the potential there; {eu} = {au} cos {wu}t solves it when "
                f"({Ku} − {wu}² {Mu}) {au} = 0, so each {wu}² is an eigenvalue of {Ku} relative to {Mu} and {au} its "
                f"shape, the column of the coordinates' amplitudes in the order shown ({order_text}), its largest "
                "entry 1 (numbers at the default parameters)"
                + (", the shapes of the motion without its velocity terms. " if moving else ". ")
            )
            if number == next((i for i, x in enumerate(nm.equilibria, start=1) if not x.momenta), number)
            else f"As about the first equilibrium, with this equilibrium's {Mu} and {Ku}. "
        )
    if e.linear is not None and e.linear.definite < 0:
        why += (
            "The mass matrix is negative definite here (L = U − T, or a negative mass): the equations are the same as "
            f"for −L, so {wu}² and the verdict are unchanged. "
        )
    elif e.linear is not None and e.linear.definite == 0:
        why += "The mass matrix is indefinite here (the kinetic energy is not positive for every velocity). "
    if named is not None:
        why += f"{notation.radicand(d)[1]} is the quantity under the square root of {wu}², written once on a line of its own. "
    why += _verdict(e, d)
    return _step(
        key, title, [where, *rows], [e.mass.tolist(), e.stiffness.tolist(), [m.omega_squared for m in e.modes]], why
    )


def _closed(exact: sp.Expr | None, number: float, unit: str, pr: Printer) -> str:
    """A closed form with its value at the default parameters beside it (said so), or the number alone."""
    if exact is not None and not exact.is_number:
        return rf"{pr.tex(exact)} \approx {_figures(number)}{unit}{AT_DEFAULTS}"
    return (pr.tex(exact) if exact is not None else _figures(number)) + unit


def coordinate_unit(d: Derivation, name: str) -> str:
    """A coordinate's unit as a heading prints it: rad for an angle, m for a length, none when unknown."""
    q = next(s for s in d.table.q if s.name == name)
    dims = system_dimensions(d).get(q)
    if dims is None:
        return ""
    return "rad" if not dims else unit_text(dims)


def momentum_unit(d: Derivation, momentum: str) -> str:
    """The unit of the momentum p_q conjugate to q, in LaTeX after a thin space; empty when q's unit is unknown."""
    name = momentum.removeprefix("p_")
    q = next((s for s in d.table.q if s.name == name), None)
    dims = system_dimensions(d).get(q) if q is not None else None
    if dims is None:
        return ""
    # p = ∂L/∂q̇ has the units of L (kg·m²/s²) times s over q's: kg·m²/s for an angle, kg·m/s for a length
    return unit_latex(add_dims({"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-1)}, dims, Fraction(-1)))


def _damped_rows(e: Equilibrium, pr: Printer, d: Derivation) -> list[str]:
    """The auxiliary equation about a damped equilibrium of one coordinate, its roots as a formula, and (where it
    oscillates) the critical damping and the energy's decay, each followed by its number at the defaults."""
    name = e.coordinates[0]
    found = damped(d, e.exact[name]) if e.exact and name in e.exact else None
    if found is None:
        return []
    eta, r, w = notation.letter("displacement", d), exponent_letter(d), notation.letter("frequency", d)
    values = defaults(d.system, d.table)
    beta_value = float(sp.N(found.beta.xreplace(values)))
    w0_value = float(sp.N(found.omega0_squared.xreplace(values)))
    if w0_value < 0:
        # a negative linearised stiffness is no squared frequency: with κ = −ω₀² > 0 (g/R at the top), the
        # equation is η̈ + 2β η̇ − κ η = 0, η ∝ e^{σt} gives σ² + 2β σ − κ = 0, so σ = −β ± √(β² + κ): one root
        # is positive, the rate at which a small displacement grows
        kappa = -found.omega0_squared
        k = pr.tex(kappa)
        k = rf"\left({k}\right)" if isinstance(kappa, sp.Add) else k
        growth = -beta_value + math.sqrt(beta_value**2 - w0_value)
        return [
            rf"\ddot{{{eta}}} + 2\beta\,\dot{{{eta}}} - {k}\,{eta} = 0,\quad \beta = {pr.tex(found.beta)}",
            rf"{eta} \propto e^{{{r} t}}:\quad {r}^2 + 2\beta {r} - {k} = 0,\quad {r} = -\beta \pm \sqrt{{\beta^2 + {k}}}",
            rf"\beta \approx {_figures(beta_value)}\,\mathrm{{s}}^{{-1}},\quad {k} \approx {_figures(-w0_value)}"
            + PER_SECOND_SQUARED
            + AT_DEFAULTS,
            # the positive root: a small displacement grows like e^{σ₊t}
            rf"\text{{growth rate }} {r}_+ = -\beta + \sqrt{{\beta^2 + {k}}} \approx {_figures(growth)}\,\mathrm{{s}}^{{-1}}"
            + AT_DEFAULTS,
        ]
    rows = [
        # η̈ + 2β η̇ + ω₀² η = 0, with β and ω₀² from the engine's linearised equation of motion
        rf"\ddot{{{eta}}} + 2\beta\,\dot{{{eta}}} + {w}_0^2\,{eta} = 0,\quad \beta = {pr.tex(found.beta)},\quad "
        rf"{w}_0^2 = {pr.tex(found.omega0_squared)}",
        # η ∝ e^{σt}: σ² + 2β σ + ω₀² = 0, so σ = −β ± √(β² − ω₀²)
        rf"{eta} \propto e^{{{r} t}}:\quad {r}^2 + 2\beta {r} + {w}_0^2 = 0,\quad {r} = -\beta \pm \sqrt{{\beta^2 - {w}_0^2}}",
        rf"\beta \approx {_figures(beta_value)}\,\mathrm{{s}}^{{-1}},\quad {w}_0^2 \approx {_figures(w0_value)}"
        + PER_SECOND_SQUARED
        + AT_DEFAULTS,
    ]
    if found.critical is not None and w0_value > 0:
        # β = ω₀: the two roots meet, the boundary between oscillating and creeping back
        p, value = found.critical
        dims = parse_unit(next((q.unit for q in d.system.parameters if q.name == p.name), ""))
        shown = unit_latex(dims) if dims else ""
        rows.append(
            rf"\beta = {w}_0:\quad {pr.tex(p)}_\text{{c}} = {pr.tex(value)} \approx "
            rf"{_figures(float(sp.N(value.xreplace(values))))}{shown}" + AT_DEFAULTS
        )
    if 0 < beta_value**2 < w0_value:
        # light damping: the amplitude decays as e^{−βt}, so the energy, quadratic in it, decays as e^{−2βt}, but
        # only averaged over a swing (within one, it falls fastest where θ̇ is largest) and only for β ≪ ω₀
        rows.append(
            rf"\langle E \rangle \propto e^{{-2\beta t}},\quad 2\beta = {pr.tex(2 * found.beta)}"
            rf"\quad (\text{{averaged over a swing, for }} \beta \ll {w}_0)"
        )
    return rows


def _rate_words(rate: sp.Expr | None, w2: float, pr: Printer) -> str:
    """The rate √(−ω²) at which a displacement runs away, in running text: in closed form, √(3g/(2l)), where one
    is known, else its value in s⁻¹."""
    return pr.text(rate) if rate is not None else f"{_figures(math.sqrt(-w2))} s⁻¹"


def _one_coordinate_step(
    e: Equilibrium, pr: Printer, d: Derivation, number: int, where: str, about: str
) -> dict[str, str]:
    """About an equilibrium (or a steady motion) of one coordinate: ω², or the rate at which a displacement runs
    away, or the exponents where velocity terms act. One coordinate has no shape and no matrices to print."""
    wt, wu, eu = notation.letter("frequency", d), notation.text("frequency", d), notation.text("displacement", d)
    mode = e.modes[0]
    w2 = mode.omega_squared
    name = e.coordinates[0]
    exact = mode.exact
    red = d.reduction
    eliminated = ""
    if e.momenta and exact is not None and red is not None and red.coordinate == name:
        if red.omega_squared_steady is not None:
            # about a steady motion, ω² in its coordinate r₀ with the momentum eliminated by U_eff′(r₀) = 0, as the
            # steady motions' step prints it (3g cos a/r₀ in a cone), not the root put back into U_eff″/m_eff
            r = next(s for s in d.table.q if s.name == name)
            exact = trig_cancelled(red.omega_squared_steady.xreplace({r: sp.Symbol(name + "0", real=True)}))
            r0, momentum = unicode_text(sp.Symbol(name + "0")), ", ".join(unicode_text(P) for P in red.momenta)
            eliminated = (
                f" {wu}² is written in {r0}, the steady motion's {plain_name(name)}, with {momentum} eliminated by "
                f"U_eff′({r0}) = 0."
            )
    moving = e.linear is not None and e.linear.moving
    rows = [where]
    # the reduction's verdict in symbols: where the place exists, and when ω² is positive (g > Rw² at the
    # spinning hoop's bottom), for a verdict the numbers at the defaults alone would state as general
    reduced = _reduced(e, d)
    conditional = reduced.stable_when if reduced is not None and reduced.stable is None else None
    if moving:
        auxiliary = _damped_rows(e, pr, d)
        # after the auxiliary equation, which says η ∝ e^{σt}, the roots' numbers alone
        rows += [*auxiliary, _exponents(e, d, named=not auxiliary)]
        lin = e.linear
        assert lin is not None
        grows = any(s.real > 1e-12 for s in lin.exponents)
        what = "Small motions about"
        r = notation.exponent(d)[1]  # in a sentence, the Unicode letter
        why = (
            f"Linearised about {about}, a small displacement is a sum of exponentials in time, one for each root "
            f"{r} of the auxiliary equation, which holds the velocity term (the damping): the real part of {r} is a "
            "rate of growth or decay (in s⁻¹), its imaginary part an angular frequency. "
            + (
                f"One {r} is positive, {r}₊ ≈ {_figures(max(x.real for x in lin.exponents))} s⁻¹: a small displacement "
                "grows exponentially at that rate instead of oscillating, an unstable equilibrium."
                if grows
                else f"Every {r} has a negative real part: a small motion dies away, an asymptotically stable equilibrium."
            )
        )
        if grows:
            what = "No oscillation about"
    elif w2 > 0:
        rows.append(f"{wt}^2 = " + _closed(exact, w2, PER_SECOND_SQUARED, pr))
        what = "Small oscillations about"
        why = (
            f"Linearised about {about}, the small displacement {eu} from it obeys {eu}̈ + {wu}² {eu} = 0: it "
            f"oscillates at the angular frequency {wu}, a stable equilibrium"
            + (" at the current parameters." if conditional is not None else ".")
        )
    elif w2 < 0:
        # the rate √(−ω²) printed over the whole radicand, √(3g/(2l)), not SymPy's √6 √(g/l)/2
        rate = sp.Pow(-exact, sp.S.Half, evaluate=False) if exact is not None else None
        shown = pr.tex(exact) if exact is not None else _figures(w2) + PER_SECOND_SQUARED
        # a sign that depends on the parameters is the sign at the current ones, said in the equation itself
        # (braced, so that a phone's line never breaks between "<" and "0")
        negative = r"{\;<\;0}\quad \text{at the current parameters}" if conditional is not None else "< 0"
        rows.append(rf"{wt}^2 = {shown} {negative}\quad \text{{(no oscillation: it runs away)}}")
        rows.append(r"\text{rate } \sqrt{-" + wt + "^2} = " + _closed(rate, math.sqrt(-w2), r"\,\mathrm{s}^{-1}", pr))
        what = "No oscillation about"
        why = (
            f"Linearised about {about}, the small displacement {eu} from it obeys {eu}̈ = |{wu}²| {eu}: it grows "
            f"exponentially at the rate {_rate_words(rate, w2, pr)} instead of oscillating, so the equilibrium is "
            "unstable" + (" at the current parameters." if conditional is not None else ".")
        )
    else:
        rows.append(rf"{wt}^2 = 0")
        what = "No restoring force about"
        why = f"Linearised about {about}, nothing pulls a small displacement back: it drifts at constant speed."
    if not moving and conditional is not None:
        # ω² = (g − Rw²)/R: stable when g > Rw², unstable when Rw² > g, whatever the defaults are
        rows.append(
            rf"\text{{stable when }} {_relation(conditional, pr)},\quad \text{{unstable when }} "
            rf"{_relation(_turned(conditional), pr)}"
        )
        why += (
            f" {wu}² changes sign with the parameters: it is positive, a stable equilibrium, when "
            f"{_relation_text(conditional)}, and negative, an unstable one, when {_relation_text(_turned(conditional))}."
        )
    if not moving and reduced is not None and reduced.exists is not None:
        # arccos(g/(Rw²)) is a place only when Rw² > g; there ω² has the sign the reduction proved
        there = (
            "" if reduced.stable is None else rf",\quad \text{{and there }} {wt}^2 {'>' if reduced.stable else '<'} 0"
        )
        rows.append(rf"\text{{exists only when }} {_relation(reduced.exists, pr)}{there}")
        why += f" This equilibrium exists only when {_relation_text(reduced.exists)}" + (
            f", and wherever it exists {wu}² is positive: it is stable wherever it exists."
            if reduced.stable is True
            else f", and wherever it exists {wu}² is negative: it is unstable wherever it exists."
            if reduced.stable is False
            else "."
        )
    if e.linear is not None and e.linear.definite < 0:
        why += (
            " The inertia is negative here (L = U − T, or a negative mass): the equations are the same as for −L, "
            f"so {wu}² and the verdict are unchanged."
        )
    if e.momenta:
        unit = coordinate_unit(d, name)
        at = f"{plain_name(name)} = {_figures(e.position[name])}" + (f" {unit}" if unit else "")
        title = f"Small oscillations about the steady motion at {at}"
        why = (
            "With the conserved momenta held at the values shown, the reduced coordinate sits at a minimum or maximum "
            f"of U_eff: the body moves steadily (a circular or conical orbit), and {wu}² = U_eff″/"
            f"{notation.inertia(d).unicode}"
            + (
                " is positive: a small displacement oscillates about it, a stable steady motion."
                if w2 > 0
                else " is negative: a small displacement runs away, an unstable steady motion."
                if w2 < 0
                else "."
            )
            + eliminated
        )
        key = f"steady-motion:{number}"
    else:
        title, key = f"{what} {about}", f"normal-modes:{number}"
        # the equilibrium is part of the first equation's sentence ("about θ = 0: ω² = g/R"), never a lone row
        # that reads as an equation of its own; its "=" unspaced, so the rows still align at the equation's
        rows = [rf"\text{{about }} {where.replace(' = ', '=')}:\quad {rows[1]}", *rows[2:]]
    return _step(key, title, rows, [e.mass.tolist(), e.stiffness.tolist(), [w2]], why)


def normal_modes_json(nm: NormalModes, pr: Printer) -> list[dict[str, Any]]:
    return [
        {
            "equilibrium": dict(e.position),
            # with its running-text form, for the marks that name it (a separatrix that just reaches θ = π)
            "exact": {n: {**pr.pair(x), "unicode": pr.text(x)} for n, x in e.exact.items()} if e.exact else None,
            "momenta": dict(e.momenta),
            "stable": e.stable,
            "kind": e.kind,
            "coordinates": list(e.coordinates),
            # every configuration is an equilibrium (V ≡ 0 and nothing acts at rest): at rest nothing moves
            "everywhere": nm.everywhere,
            # the full linearization's exponents s (velocity terms included), as [Re s, Im s]
            "exponents": [[s.real, s.imag] for s in e.linear.exponents] if e.linear else [],
            "frequencies": list(e.linear.frequencies) if e.linear else [],
            "gyroscopic": bool(e.linear and e.linear.gyroscopic),
            # with velocity terms: each oscillation's exponent and complex shape (amplitude, phase in radians)
            "complex_modes": [
                {
                    "exponent": [s.real, s.imag],
                    "amplitude": {q: abs(a) for q, a in zip(e.coordinates, shape, strict=True)},
                    "phase": {q: math.atan2(a.imag, a.real) for q, a in zip(e.coordinates, shape, strict=True)},
                }
                for s, shape in (e.linear.complex_modes if e.linear else ())
            ],
            "modes": [
                {
                    "omega_squared": m.omega_squared,
                    "shape": dict(zip(e.coordinates, m.shape, strict=True)),
                    "sympy": sp.sstr(m.exact) if m.exact is not None else None,
                    "latex": pr.tex(m.exact) if m.exact is not None else None,
                }
                for m in e.modes
            ],
        }
        for e in nm.equilibria
    ]


def limits_step(d: Derivation, pr: Printer, limits: tuple[tuple[str, float], ...]) -> dict[str, str] | None:
    """Each acceleration beside its limit as a parameter goes to a value (the statement's comparison, the
    massive pulley's z̈ → (m₁ − m₂) g/(m₁ + m₂) as M → 0), each with its value at the defaults where it is a
    constant; None where the accelerations are not in closed form or no named parameter is the system's."""
    params = {s.name: s for s in d.table.params}
    chosen = [(params[name], value) for name, value in limits if name in params]
    if not chosen or not d.equations.closed_form:
        return None
    values = defaults(d.system, d.table)
    moving = {*d.table.q, *d.table.qd, *d.table.qdd, d.table.t}
    rows, data = [], []
    for k, acceleration in enumerate(d.equations.accelerations):
        name = d.table.names[k]
        qdd = pr.tex(d.table.qdd[k])
        unit = coordinate_unit(d, name)
        # a number only where the acceleration is a constant of the motion (a constant force, as here)
        per = (rf"\,\mathrm{{{unit}}}" if unit and unit != "rad" else "") + PER_SECOND_SQUARED

        def at_defaults(expr: sp.Expr, unit: str = per) -> str:
            if expr.free_symbols & moving:
                return ""
            return rf" \approx {_figures(float(sp.N(expr.xreplace(values))))}{unit}"

        number = at_defaults(acceleration)
        rows.append(rf"{qdd} = {pr.tex(acceleration)}{number}{AT_DEFAULTS if number else ''}")
        for symbol, value in chosen:
            # the limit, not the value put in: a parameter in a denominator may vanish there
            limit = sp.factor_terms(sp.limit(acceleration, symbol, value))
            shown = sp.Float(value) if not float(value).is_integer() else sp.Integer(int(value))
            rows.append(rf"\lim_{{{pr.tex(symbol)} \to {pr.tex(shown)}}} {qdd} = {pr.tex(limit)}{at_defaults(limit)}")
            data.append([acceleration, limit])
    names = ", ".join(f"{pr.text(symbol)} → {pr.text(sp.nsimplify(value))}" for symbol, value in chosen)
    return _step(
        "limits",
        f"The acceleration and its limit as {names}" if len(d.table.q) == 1 else f"The accelerations as {names}",
        rows,
        data,
        "Each acceleration beside its limit, the comparison the problem asks for.",
    )
