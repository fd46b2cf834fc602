"""Generated source for one system: right-hand sides and observables, from the engine's expressions.

Three scalar functions, all ``f(t, y, k, out)`` (y a state, k the parameters):

    rhs      y = (q, q_dot)  ->  (q_dot, q_ddot)    q_ddot = M(q, t)^-1 f(q, q_dot, t)
    ham      z = (q, p)      ->  (q_dot, p_dot)     q_dot = M^-1 (p - b),  p_dot = dL/dq + Q
    momenta  y = (q, q_dot)  ->  p                  p = dL/dq_dot

``browser_source`` prints the same q_ddot as the body of a JavaScript function
``(t, y, k, out)`` for the page's live preview (static/js/preview.js).

where b = p at q_dot = 0 (L is quadratic in the velocities, so p = M q_dot + b),
and p_dot = dL/dq (at the q_dot belonging to p) + Q is Hamilton's
p_dot = -dH/dq + Q written with the Lagrangian.  q_ddot uses the engine's solved
accelerations when they are compact, otherwise M and f with a numeric solve.
One vectorised function evaluates observables (energy, h, conserved
quantities, det M, constraint forces) on all samples at once.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import sympy as sp

from app.engine.algebra.kinks import away_from_kinks
from app.engine.derivation.derive import Derivation
from app.engine.equations.lagrange import Equations
from app.numerics.codegen import (
    ArrayPrinter,
    Block,
    BrowserPrinter,
    ScalarPrinter,
    function_source,
    ldl_solve,
    matrix_entries,
    unpack,
)


@dataclass(frozen=True)
class Names:
    """Safe names for the engine's symbols in generated code."""

    rename: dict[sp.Symbol, sp.Symbol]
    q: list[str]
    v: list[str]
    p: list[str]
    k: list[str]

    @classmethod
    def of(cls, d: Derivation) -> Names:
        table = d.table
        n = len(table.names)
        q = [f"q{i}" for i in range(n)]
        v = [f"v{i}" for i in range(n)]
        k = [f"k{i}" for i in range(len(table.params))]
        rename = {table.t: sp.Symbol("t", real=True)}
        rename.update({s: sp.Symbol(name, real=True) for s, name in zip(table.q, q, strict=True)})
        rename.update({s: sp.Symbol(name, real=True) for s, name in zip(table.qd, v, strict=True)})
        rename.update({s: sp.Symbol(name, real=True) for s, name in zip(table.params, k, strict=True)})
        return cls(rename, q, v, [f"p{i}" for i in range(n)], k)

    def __call__(self, expr: sp.Expr) -> sp.Expr:
        return sp.sympify(expr).xreplace(self.rename)


def _compact(eqs: Equations) -> bool:
    """Use the solved accelerations when the engine kept a closed form and it is not much larger than M and f."""
    if not eqs.closed_form:
        return False
    return sp.count_ops(list(eqs.accelerations)) <= 3 * (sp.count_ops(eqs.mass_matrix) + sp.count_ops(eqs.forcing)) + 60


def _rhs_block(d: Derivation, names: Names, block: Block, printer) -> Block:
    """out = (q_dot, q_ddot) from y = (q, q_dot), k and t, as straight-line code."""
    eqs = d.equations
    n = len(names.q)
    for vector, group, offset in (("y", names.q, 0), ("y", names.v, n), ("k", names.k, 0)):
        for i, name in enumerate(group):
            block.set(name, f"{vector}[{i + offset}]")
    outs = [f"out[{n + i}]" for i in range(n)]
    for i, v in enumerate(names.v):
        block.set(f"out[{i}]", v)
    if _compact(eqs):
        block.assign(outs, [names(a) for a in eqs.accelerations], printer, "a_")
    else:
        # M q_ddot = f, solved numerically
        M = eqs.mass_matrix.applyfunc(names)
        entries, exprs = matrix_entries(M, "_")
        forcing = [f"_f{i}" for i in range(n)]
        block.assign(entries + forcing, [*exprs, *(names(x) for x in eqs.forcing)], printer, "a_")
        ldl_solve(block, M, forcing, [f"_x{i}" for i in range(n)], "_", printer)
        for i, out in enumerate(outs):
            block.set(out, f"_x{i}")
    return block


def rhs_source(d: Derivation, names: Names) -> str:
    return function_source("rhs", "t, y, k, out", _rhs_block(d, names, Block(), ScalarPrinter()))


def browser_source(d: Derivation, names: Names) -> str:
    """The body of the JavaScript function ``(t, y, k, out)`` computing the same (q_dot, q_ddot) as ``rhs``.

    Printed from the engine's expressions with the renamed symbols, like the Python source: no
    name or text from a declaration reaches it, only q0.., v0.., k0.., t, numbers and Math calls.
    """
    return "\n".join(_rhs_block(d, names, Block(javascript=True), BrowserPrinter()).lines)


def jacobian_source(d: Derivation, names: Names) -> str | None:
    """``jac(t, y, k, out)``: out[i*2n + j] = dF_i/dy_j, for the implicit methods; None when q_ddot is not compact."""
    eqs = d.equations
    if not _compact(eqs):
        return None
    n = len(names.q)
    ys = [sp.Symbol(x, real=True) for x in (*names.q, *names.v)]
    rows = [ys[n + i] for i in range(n)] + [names(a) for a in eqs.accelerations]
    block = Block()
    block.raw(*unpack("y", names.q), *unpack("y", names.v, n), *unpack("k", names.k))
    targets, exprs = [], []
    for i, row in enumerate(rows):
        for j, y in enumerate(ys):
            # dF_i/dy_j, differentiated term by term (no simplification).  A piecewise-smooth F
            # (Abs, sign) has a derivative with DiracDelta at its kinks; away from them, where every
            # step of an implicit method's Newton iteration lands almost surely, the delta is 0.
            derivative = away_from_kinks(sp.diff(row, y))
            if derivative != 0:
                targets.append(f"out[{i * 2 * n + j}]")
                exprs.append(derivative)
    block.raw(f"for _i in range({4 * n * n}):", "    out[_i] = 0.0")
    if exprs:
        block.assign(targets, exprs, ScalarPrinter(), "j_")
    return function_source("jac", "t, y, k, out", block)


def hamilton_source(d: Derivation, names: Names) -> str:
    eqs, mech = d.equations, d.mechanics
    n = len(names.q)
    block = Block()
    block.raw(*unpack("z", names.q), *unpack("z", names.p, n), *unpack("k", names.k))
    zero_v = {sp.Symbol(v, real=True): sp.Integer(0) for v in names.v}
    M = eqs.mass_matrix.applyfunc(names)
    entries, exprs = matrix_entries(M, "_")
    # b = p at q_dot = 0, so that p = M q_dot + b
    offsets = [names(p).xreplace(zero_v) for p in eqs.momenta]
    block.assign(entries + [f"_b{i}" for i in range(n)], [*exprs, *offsets], ScalarPrinter(), "h_")
    block.raw(*(f"_r{i} = p{i} - _b{i}" for i in range(n)))
    # q_dot = M^-1 (p - b)
    ldl_solve(block, M, [f"_r{i}" for i in range(n)], names.v, "_")
    # p_dot = dL/dq + Q at that q_dot
    p_dot = [names(g + Q) for g, Q in zip(eqs.dL_dq, mech.Q, strict=True)]
    block.assign([f"out[{n + i}]" for i in range(n)], p_dot, ScalarPrinter(), "g_")
    block.raw(*(f"out[{i}] = {v}" for i, v in enumerate(names.v)))
    return function_source("ham", "t, z, k, out", block)


def momenta_source(d: Derivation, names: Names) -> str:
    n = len(names.q)
    block = Block()
    block.raw(*unpack("y", names.q), *unpack("y", names.v, n), *unpack("k", names.k))
    block.assign([f"out[{i}]" for i in range(n)], [names(p) for p in d.equations.momenta], ScalarPrinter(), "m_")
    return function_source("momenta", "t, y, k, out", block)


def observables_source(names: Names, exprs: Sequence[sp.Expr]) -> str:
    """``observe(t, Q, V, k)``: each expression on arrays of samples (Q, V of shape (n, N))."""
    block = Block()
    block.raw(*unpack("Q", names.q), *unpack("V", names.v), *unpack("k", names.k))
    targets = [f"_o{i}" for i in range(len(exprs))]
    block.assign(targets, [names(e) for e in exprs], ArrayPrinter(), "o_")
    listed = "".join(f"{x}, " for x in targets)
    block.raw(f"return [numpy.broadcast_to(numpy.asarray(x, dtype=float), numpy.shape(t)).copy() for x in ({listed})]")
    return function_source("observe", "t, Q, V, k", block)
