"""SymPy source for exported notebooks and scripts, under the code generator's rule.

The code reads like the system: its variables are the system's own names
(``theta1``, ``theta1_dot``, ``theta1_ddot``, ``l1``, ``m2``), each accepted again
by ``check_name`` (letters and digits) before it is written.  A name that would
clash with Python (a keyword, a builtin), with the script's own names (``sp``,
``t``, ``L``, ``q``, …) or with another of the system's names is written with a
trailing underscore (``print_``), and the file says so in a comment.  The declared
names are also the *names* of the SymPy symbols (string literals, so printed
results read ``theta``).  Expressions are the engine's validated SymPy objects,
renamed and printed by a SymPy printer; no text a user typed is pasted into code.
"""

from __future__ import annotations

import builtins
import keyword
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import sympy as sp
from sympy.printing.pycode import SymPyPrinter

from app.engine.derivation.derive import Derivation
from app.engine.parser.parse import ExpressionError, check_name, parse_expression
from app.errors import Refused
from app.scenes.types import Event


class ExportError(Refused):
    """A derivation that cannot be exported safely (an unexpected name or function)."""


class SourcePrinter(SymPyPrinter):
    """Prints SymPy-building source: ``sp.sin(q0)``, ``sp.Rational(1, 2)``, ``sp.pi``.

    Strict: a function it has no rule for raises instead of being pasted by name.
    """

    def __init__(self) -> None:
        super().__init__({"fully_qualified_modules": True, "strict": True})

    def _module_format(self, fqn: str, register: bool = True) -> str:
        # every SymPy function by its short name under the ``sp`` alias
        return "sp." + fqn.rsplit(".", 1)[-1]

    def _print_Rational(self, expr: sp.Rational) -> str:
        # exact: Python's 1/2 would be the float 0.5
        return f"sp.Rational({expr.p}, {expr.q})"

    def _print_Half(self, expr: sp.Rational) -> str:
        return self._print_Rational(expr)

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_Pi(self, expr: sp.Expr) -> str:
        return "sp.pi"

    def _print_Exp1(self, expr: sp.Expr) -> str:
        return "sp.E"

    def _print_ImaginaryUnit(self, expr: sp.Expr) -> str:
        raise ExportError("the derivation contains the imaginary unit, which a real system should not")


def checked_name(name: str, what: str) -> str:
    """A declared name, accepted again before it is written into a file (letters and digits only)."""
    try:
        return check_name(name, what)
    except ExpressionError as exc:
        raise ExportError(str(exc)) from None


# Every name the exported script and notebook define or import themselves: a system's name equal to one of
# these (or to a Python keyword or builtin) is written with a trailing underscore.
RESERVED = frozenset(
    """sp np json solve_ivp nbformat t q v a k L Q p EL M f acc dt T U h E r masses velocities show same check
    show_engine LATEX sol names end y0 t_end k_values accelerations rhs events time y e k_ vk pk qk ak Qk ri mi vi
    x tries mine engine name value expr point diff values plt fig ax random matplotlib numpy sympy scipy IPython
    Math display symbols rng i t_samples energy n E_t ti yi top bottom T_engine L_engine EL_engine acc_engine
    p_engine h_engine E_engine""".split()
)


def _free(name: str, used: set[str]) -> str:
    """name, or name with trailing underscores until it clashes with nothing."""
    out = name
    while (
        out in used
        or out in RESERVED
        or keyword.iskeyword(out)
        or keyword.issoftkeyword(out)
        or hasattr(builtins, out)
        or out.startswith(("g", "event"))
        and out.removeprefix("g").removeprefix("event").isdigit()
    ):
        out += "_"
    used.add(out)
    return out


@dataclass(frozen=True)
class Naming:
    """The code names of one derivation's symbols (the system's own, renamed only on a clash), and a printer."""

    coordinates: tuple[str, ...]
    parameters: tuple[str, ...]
    renamed: dict[sp.Symbol, sp.Symbol]
    code_names: dict[str, str] = field(default_factory=dict)  # declared name -> name in the code

    @classmethod
    def of(cls, d: Derivation) -> Naming:
        table = d.table
        coordinates = tuple(checked_name(n, "coordinate") for n in table.names)
        parameters = tuple(checked_name(n, "parameter") for n in table.parameter_names)
        renamed: dict[sp.Symbol, sp.Symbol] = {table.t: sp.Symbol("t", real=True)}
        used: set[str] = set()
        code_names: dict[str, str] = {}
        for name, q, qd, qdd in zip(coordinates, table.q, table.qd, table.qdd, strict=True):
            for declared, symbol in ((name, q), (f"{name}_dot", qd), (f"{name}_ddot", qdd)):
                code_names[declared] = _free(declared, used)
                renamed[symbol] = sp.Symbol(code_names[declared], real=True)
        for name, k in zip(parameters, table.params, strict=True):
            code_names[name] = _free(name, used)
            renamed[k] = sp.Symbol(code_names[name], real=True)
        return cls(coordinates, parameters, renamed, code_names)

    @property
    def n(self) -> int:
        return len(self.coordinates)

    def code(self, expr: sp.Expr) -> str:
        """An engine expression as SymPy source in the code names."""
        expr = sp.sympify(expr).xreplace(self.renamed)
        unknown = expr.free_symbols - set(self.renamed.values())
        if unknown:
            raise ExportError(f"the expression has symbols the system does not declare: {sorted(map(str, unknown))}")
        try:
            return SourcePrinter().doprint(expr)
        except ExportError:
            raise
        except Exception as exc:  # sympy's strict printer refusing a function it cannot print
            raise ExportError(f"an expression cannot be written as SymPy code ({type(exc).__name__})") from None

    def code_list(self, exprs: Iterable[sp.Expr]) -> str:
        return "[" + ", ".join(self.code(e) for e in exprs) + "]"

    def symbol_lines(self) -> list[str]:
        """Lines declaring t and every name as a real SymPy symbol named as declared (a comment lists renamings)."""
        lines = ['t = sp.Symbol("t", real=True)']
        clashes = [f"{declared} as {code}" for declared, code in self.code_names.items() if declared != code]
        if clashes:
            lines.append(
                "# written with a trailing underscore, since the plain name is Python's or this file's own: "
                + ", ".join(clashes)
            )
        c = self.code_names
        for suffix in ("", "_dot", "_ddot"):
            for name in self.coordinates:
                lines.append(f"{c[name + suffix]} = sp.Symbol({name + suffix!r}, real=True)")
        for name in self.parameters:
            lines.append(f"{c[name]} = sp.Symbol({name!r}, real=True)")
        lines.append(f"q = [{', '.join(c[n] for n in self.coordinates)}]  # coordinates")
        lines.append(f"v = [{', '.join(c[n + '_dot'] for n in self.coordinates)}]  # their velocities")
        lines.append(f"a = [{', '.join(c[n + '_ddot'] for n in self.coordinates)}]  # their accelerations")
        lines.append(f"k = [{', '.join(c[n] for n in self.parameters)}]  # parameters")
        return lines


# The total time derivative along a motion, d/dt f = ∂f/∂t + Σ_k (∂f/∂q_k) q̇_k + (∂f/∂q̇_k) q̈_k,
# the engine's own rule (app.engine.parser.symbols), written out for the reader.
DT_LINES = [
    "def dt(f):",
    '    """The total time derivative of f(t, q, v) along a motion: chain rule through every coordinate."""',
    "    return sp.diff(f, t) + sum(sp.diff(f, qk) * vk + sp.diff(f, vk) * ak for qk, vk, ak in zip(q, v, a))",
]

EULER_LAGRANGE_LINES = [
    "# p_k = ∂L/∂q̇_k, and the Euler–Lagrange equations d/dt p_k − ∂L/∂q_k − Q_k = 0",
    "p = [sp.diff(L, vk) for vk in v]",
    "EL = [dt(pk) - sp.diff(L, qk) - Qk for pk, qk, Qk in zip(p, q, Q)]",
]

ACCELERATION_LINES = [
    "# The equations are linear in the accelerations: M q̈ = f, M_jk = ∂EL_j/∂q̈_k, f = −EL at q̈ = 0",
    "M = sp.Matrix([[sp.diff(e, ak) for ak in a] for e in EL])",
    "f = -sp.Matrix(EL).xreplace({ak: 0 for ak in a})",
    "acc = list(M.LUsolve(f))",
]


def number(value: float) -> str:
    return repr(float(value))


def simulation_lines(naming: Naming, values: Sequence[float], y0: Sequence[float], t_end: float) -> list[str]:
    """Lines that integrate q̈ = acc from y0 to t_end with DOP853 (``sol`` holds the run)."""
    names = ", ".join(naming.parameters)
    return [
        f"k_values = [{', '.join(number(x) for x in values)}]  # {names or 'no parameters'}",
        f"y0 = [{', '.join(number(x) for x in y0)}]  # q, then q_dot",
        f"t_end = {number(t_end)}",
        "accelerations = sp.lambdify((t, q, v, k), acc, modules='math', cse=True, dummify=True)",
        "",
        "",
        "def rhs(time, y):",
        '    """y = (q, q_dot) -> (q_dot, q_ddot)."""',
        f"    return [*y[{naming.n}:], *accelerations(time, y[:{naming.n}], y[{naming.n}:], k_values)]",
        "",
        "",
    ]


def event_lines(naming: Naming, d: Derivation, events: Sequence[Event]) -> list[str]:
    """Lines defining ``events`` for solve_ivp: each a terminal event where its g falls through zero."""
    lines: list[str] = []
    names = []
    n = naming.n
    for i, event in enumerate(events):
        try:
            g = parse_expression(event.expression, d.table.namespace())
        except ExpressionError as exc:
            raise ExportError(f"event {event.name!r}: {exc}") from None
        lines += [
            f"# Where the set-up ends ({event.name}): the run stops the first time g{i} falls below zero",
            f"g{i} = sp.lambdify((t, q, v, k), {naming.code(g)}, modules='math', dummify=True)",
            "",
            "",
            f"def event{i}(time, y):",
            f"    return g{i}(time, y[:{n}], y[{n}:], k_values)",
            "",
            "",
            f"event{i}.terminal, event{i}.direction = True, -1",
        ]
        names.append(f"event{i}")
    return [*lines, f"events = [{', '.join(names)}]"]
