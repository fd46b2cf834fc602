"""The symbol convention shared by the engine, the API and the numerics.

A coordinate ``q`` is the plain real symbol ``q``; its velocity is ``q_dot``
and its acceleration ``q_ddot``; time is ``t``; parameters go by their names.
Working with plain symbols (not functions of time) keeps every derivative a
partial derivative, and the total time derivative is written out explicitly:

    d/dt f(t, q, q_dot) = df/dt + sum_k (df/dq_k) q_dot_k + (df/dq_dot_k) q_ddot_k
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from app.engine.display.names import latex
from app.engine.errors import DerivationError
from app.engine.parser.parse import check_name

# the time, one symbol everywhere (a coordinate's group of symbols holds it beside the coordinates)
TIME = sp.Symbol("t", real=True)


@dataclass(frozen=True)
class SymbolTable:
    """Real symbols for the coordinates, their rates, parameters and time."""

    names: tuple[str, ...]
    parameter_names: tuple[str, ...]

    def __post_init__(self) -> None:
        seen: set[str] = set()
        for name in (*self.names, *self.parameter_names):
            check_name(name, "coordinate" if name in self.names else "parameter")
            if name in seen:
                raise DerivationError(f"the name {name!r} is declared twice")
            seen.add(name)
        if not self.names:
            raise DerivationError("at least one generalized coordinate is needed")

    @property
    def t(self) -> sp.Symbol:
        return TIME

    @property
    def q(self) -> tuple[sp.Symbol, ...]:
        return tuple(sp.Symbol(n, real=True) for n in self.names)

    @property
    def qd(self) -> tuple[sp.Symbol, ...]:
        return tuple(sp.Symbol(f"{n}_dot", real=True) for n in self.names)

    @property
    def qdd(self) -> tuple[sp.Symbol, ...]:
        return tuple(sp.Symbol(f"{n}_ddot", real=True) for n in self.names)

    @property
    def params(self) -> tuple[sp.Symbol, ...]:
        return tuple(sp.Symbol(n, real=True) for n in self.parameter_names)

    def namespace(self) -> dict[str, sp.Symbol]:
        """Every name an expression may use, mapped to its symbol."""
        table = {s.name: s for s in (*self.q, *self.qd, *self.params, self.t)}
        return table

    def latex_names(self) -> dict[sp.Symbol, str]:
        """How each symbol prints: velocities with a dot, accelerations with two."""
        table: dict[sp.Symbol, str] = {}
        for name, q, qd, qdd in zip(self.names, self.q, self.qd, self.qdd, strict=True):
            table[q] = latex(name)
            table[qd] = latex(f"{name}_dot")
            table[qdd] = latex(f"{name}_ddot")
        for name, p in zip(self.parameter_names, self.params, strict=True):
            table[p] = latex(name)
        return table

    def dt(self, expr: sp.Expr) -> sp.Expr:
        """Total time derivative along a motion q(t)."""
        # d/dt f = df/dt + sum_k df/dq_k * q_dot_k + df/dq_dot_k * q_ddot_k
        total = sp.diff(expr, self.t)
        for q, qd, qdd in zip(self.q, self.qd, self.qdd, strict=True):
            total += sp.diff(expr, q) * qd + sp.diff(expr, qd) * qdd
        return total
