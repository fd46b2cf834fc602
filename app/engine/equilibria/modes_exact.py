"""Closed forms for the equilibria step: the equilibria solved by SymPy, and omega^2 at an exact equilibrium.

Each is bounded by its own time budget and returns nothing (rather than
waiting) when SymPy cannot answer in time; the numerical search in
``app.engine.equilibria.roots`` and the numbers in ``app.engine.equilibria.stability`` stand
without them.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from app.engine.algebra.budget import document_memo, memoized, within_budget
from app.engine.display.forms import roots_compacted, settle
from app.engine.equations.mechanics import positive_names
from app.engine.parser.symbols import SymbolTable
from app.limits import CANCEL_WORK, EIGEN_WORK
from app.limits import EQUILIBRIA_SOLVE_WORK as SOLVE_WORK
from app.scenes.types import System

MAX_SOLVE_OPS = 400  # larger conditions go straight to the numeric search
MAX_EXACT_OPS = 80  # closed forms of omega^2 longer than this are given as numbers only


def positive(system: System, table: SymbolTable) -> dict[sp.Symbol, sp.Symbol]:
    """Stand-ins carrying the declared signs (positive parameters, nonnegative distances)."""
    names = positive_names(system)
    nonnegative = {p.name for p in system.parameters if p.min is not None and p.min == 0}
    out = {s: sp.Symbol(s.name, nonnegative=True) for s in table.params if s.name in nonnegative}
    out.update({s: sp.Symbol(s.name, positive=True) for s in table.params if s.name in names})
    out.update({s: sp.Symbol(s.name, nonnegative=True) for s in table.q if s.name in names})
    return out


def polynomial(g_exprs: list[sp.Expr], q: list[sp.Symbol]) -> bool:
    """Every condition is a ratio of polynomials in the coordinates: SymPy's solve then finds every root."""
    for e in g_exprs:
        num, den = sp.fraction(sp.together(e))
        if not (num.is_polynomial(*q) and den.is_polynomial(*q)):
            return False
    return True


def solve(
    g_exprs: list[sp.Expr], q: list[sp.Symbol], system: System, table: SymbolTable
) -> list[dict[sp.Symbol, sp.Expr]] | None:
    """Closed-form equilibria (free coordinates left out), or None if SymPy cannot tell in time."""
    if all(e == 0 for e in g_exprs):
        return [{}]
    if sp.count_ops(g_exprs) > MAX_SOLVE_OPS:
        return None
    assume = positive(system, table)
    back = {v: k for k, v in assume.items()}
    unknowns = [assume.get(s, s) for s in q]
    found = within_budget(
        # unchecked and unsimplified (much faster); each root is checked numerically by the caller
        lambda: sp.solve(
            [e.xreplace(assume) for e in g_exprs if e != 0], unknowns, dict=True, check=False, simplify=False
        ),
        None,
        SOLVE_WORK,
    )
    if found is None:
        return None
    return [{k.xreplace(back): without_atan(v.xreplace(back)) for k, v in sol.items()} for sol in found]


def without_atan(value: sp.Expr) -> sp.Expr:
    """SymPy's half-angle roots 2 atan(√a) written as a textbook does, acos((1 − a)/(1 + a)).

    For u ≥ 0, tan(φ/2) = u gives cos φ = (1 − u²)/(1 + u²) with φ = 2 atan u in [0, π), where acos is the
    inverse: the same angle.  A principal square root is never negative; where it is not real, the root is
    not real either and is dropped by the caller.  So the bead on a turning hoop sits at acos(g/(Rω²)), and
    sin² + cos² of it collapses in M and K (cos(acos c) = c, sin(acos c) = √(1 − c²))."""

    def half_angle(e: sp.Expr) -> bool:
        # u = √a, or c √a/√b (c > 0): a principal root over another is never negative where it is real either
        # (i√|a|/(i√|b|) = √(a/b)); the spun hoop's root is 2 atan(√(Rω² − g)/√(g + Rω²))
        if not isinstance(e, sp.atan):
            return False
        factors = sp.Mul.make_args(e.args[0])
        up = [f for f in factors if isinstance(f, sp.Pow) and f.exp == sp.Rational(1, 2)]
        down = [f for f in factors if isinstance(f, sp.Pow) and f.exp == -sp.Rational(1, 2)]
        rest = [f for f in factors if f not in up and f not in down]
        return len(up) == 1 and len(down) <= 1 and all(f.is_number and f.is_positive for f in rest)

    def acos_half(e: sp.Expr) -> sp.Expr:
        # u² with the roots squared away: c² a/b
        u2 = sp.Mul(*(f.base ** (2 * f.exp) if isinstance(f, sp.Pow) else f**2 for f in sp.Mul.make_args(e.args[0])))
        return sp.acos(sp.factor(sp.cancel(sp.together((1 - u2) / (1 + u2))))) / 2

    return value.replace(half_angle, acos_half) if value.has(sp.atan) else value


def cheap(expr: sp.Expr) -> sp.Expr:
    """A quick normal form for entries of M and K at an equilibrium (no full simplification); once per
    document for each entry (M is the same at a double pendulum's (0, 0) and (π, π), and m₂l₁l₂ recurs)."""
    memo = document_memo()
    key = ("cheap", expr)
    if memo is not None and key in memo:
        return memo[key]
    found = within_budget(lambda: sp.factor_terms(sp.cancel(expr)), None, CANCEL_WORK)
    if found is None:
        return expr  # past its bound: not remembered (the next try may have more)
    if memo is not None:
        memo[key] = found
    return found


def _neat(expr: sp.Expr) -> sp.Expr:
    if any(not e.exp.is_integer for e in expr.atoms(sp.Pow)):
        return sp.factor_terms(expr)
    return sp.factor(expr)


def _roots(M: sp.Matrix, K: sp.Matrix) -> list[sp.Expr]:
    n = M.shape[0]
    if M.is_diagonal() and K.is_diagonal():
        return [sp.cancel(K[i, i] / M[i, i]) for i in range(n)]
    if n == 2:
        # det(K - l M) = a l^2 + b l + c = 0
        a = M.det()
        b = -(K[0, 0] * M[1, 1] + K[1, 1] * M[0, 0] - K[0, 1] * M[1, 0] - K[1, 0] * M[0, 1])
        c = K.det()
        # the same discriminant at pairs of equilibria (K → −K: a double pendulum's (0, 0) and (π, π)), factored
        # once: b² written with b's sign chosen, as SymPy leaves (−x − y)² and (x + y)² apart
        discriminant = (-b if b.could_extract_minus_sign() else b) ** 2 - 4 * a * c
        root = sp.sqrt(memoized("discriminant", discriminant, lambda: sp.factor(sp.expand(discriminant))))
        # a rational result (the square root came out) is put over one factored denominator
        return [_neat((-b - root) / (2 * a)), _neat((-b + root) / (2 * a))]
    lam = sp.Dummy("lambda")
    # with parameters in the coefficients, Cardano's and Ferrari's formulas run far past MAX_EXACT_OPS (and
    # past EIGEN_WORK at every equilibrium of a triple pendulum): only roots from factors of degree ≤ 2, and
    # none when there is no such factor, known before the symbolic determinant is expanded (numbers alone keep
    # the general formulas, whose results may be short)
    if (M.free_symbols | K.free_symbols) and _irreducible_at_a_point(M, K, lam):
        return []
    poly = sp.Poly(sp.expand((K - lam * M).det(method="berkowitz")), lam)
    general = not any(c.free_symbols for c in poly.all_coeffs())
    roots = sp.roots(poly, multiple=True, cubics=general, quartics=general)
    if len(roots) != M.shape[0]:
        return []
    return [sp.factor_terms(r) for r in roots]


def _irreducible_at_a_point(M: sp.Matrix, K: sp.Matrix, lam: sp.Dummy) -> bool:
    """det(K − λM) has no factor of lower degree in λ, shown at one rational point of the parameters.

    A factorisation A(λ)·B(λ) over the parameters survives setting them to numbers that keep the degree in λ
    (the leading coefficient, det M, nonzero there); so if the determinant of the matrices with numbers put
    in is irreducible over the rationals with its full degree, the symbolic one is too.  This costs a
    determinant of numbers, where expanding the symbolic one costs most of the time of a chain's modes.
    False: not shown (the roots are then looked for in the symbolic determinant)."""
    symbols = sorted((M.free_symbols | K.free_symbols), key=str)
    point = {s: sp.Rational(7 + 3 * i, 11 + 2 * i) for i, s in enumerate(symbols)}
    try:
        poly = sp.Poly(sp.expand((K.xreplace(point) - lam * M.xreplace(point)).det(method="berkowitz")), lam)
    except sp.PolynomialError:
        return False
    if poly.degree() != M.shape[0] or not poly.get_domain().is_QQ and not poly.get_domain().is_ZZ:
        return False
    return bool(poly.is_irreducible)


def eigenvalues(M: sp.Matrix, K: sp.Matrix, assume: Mapping[sp.Symbol, sp.Symbol]) -> list[sp.Expr]:
    """Closed forms of the roots of det(K - lambda M) = 0 (under the declared signs), when small and in time."""
    back = {v: k for k, v in assume.items()}

    def work() -> list[sp.Expr]:
        Ma, Ka = M.xreplace(dict(assume)), K.xreplace(dict(assume))
        # the roots as a textbook prints them: √a √b as one root, shared factors out of sums (the declared
        # signs are read where the symbols still carry them: SymPy would split √(ab) again under them)
        return [roots_compacted(r.xreplace(back), assume) for r in _roots(Ma, Ka)]

    found: list[sp.Expr] = within_budget(work, [], EIGEN_WORK)
    # each root is already in its neat form (factored, or its common factors out around the square root):
    # the document prints it as it stands (a search for a shorter one would expand products of square roots)
    return [settle(c) for c in found if sp.count_ops(c) <= MAX_EXACT_OPS]
