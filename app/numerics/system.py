"""A derivation as numeric functions, with the structural facts the method choice needs."""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from functools import cached_property
from types import ModuleType
from typing import TYPE_CHECKING

import numpy as np
import sympy as sp

from app.engine.derivation.derive import Derivation
from app.numerics import jit
from app.numerics.generate import Names, browser_source, hamilton_source, jacobian_source, momenta_source, rhs_source

if TYPE_CHECKING:
    from app.numerics.bound import Bound


@dataclass
class NumericSystem:
    """Right-hand sides of one system: Python callables at once, numba ones on first use."""

    derivation: Derivation
    coordinates: tuple[str, ...]
    parameter_names: tuple[str, ...]
    sources: dict[str, str]
    python: dict
    separable: bool  # q_ddot depends on q alone and M is constant: H = 1/2 v.M.v + U(q)
    autonomous: bool  # no explicit t in the equations
    energy_name: str | None  # "E" or "h" when the engine says that quantity is conserved
    conserved: tuple[str, ...]
    key: str
    periodic: tuple[bool, ...] = ()  # coordinates that are angles: F(q + 2 pi e_i) = F(q)
    # p = M q_dot + b with M free of q_dot, so q_dot(q, p) = M⁻¹(p − b) and ``ham`` is generated; False when
    # ∂²L/∂q̇² depends on the velocities (a relativistic particle): no (q, p) form for the symplectic methods
    legendre_linear: bool = True
    _compiled: ModuleType | None = field(default=None, repr=False)
    _compiled_jacobian: ModuleType | None = field(default=None, repr=False)
    _lock: threading.Lock = field(default_factory=threading.Lock, repr=False)
    _bound: dict = field(default_factory=dict, repr=False)

    @property
    def n(self) -> int:
        return len(self.coordinates)

    @cached_property
    def browser(self) -> str:
        """The body of a JavaScript (t, y, k, out) computing rhs, for the page's live preview (printed on first use)."""
        return browser_source(self.derivation, Names.of(self.derivation))

    @cached_property
    def compiled_key(self) -> str:
        return jit.source_key(jit.compiled_source(self._compiled_sources()))

    def _compiled_sources(self) -> dict[str, str]:
        # no ham when the Legendre map p = ∂L/∂q̇ is not linear in q̇ (``legendre_linear``)
        return {k: self.sources[k] for k in ("rhs", "ham") if k in self.sources}

    def is_compiled(self) -> bool:
        """True when ``compiled()`` would return at once (no numba compile or cache load)."""
        return jit.ready(self.compiled_key)

    def compiled(self) -> ModuleType:
        """The numba module with ``rhs`` and ``ham`` (compiled or loaded from the disk cache once)."""
        with self._lock:
            if self._compiled is None:
                self._compiled = jit.compiled_functions(self._compiled_sources())
            return self._compiled

    @property
    def has_jacobian(self) -> bool:
        """True when the engine's Jacobian dF/dy is generated (q_ddot compact enough to differentiate)."""
        return "jac" in self.sources

    @cached_property
    def jacobian_key(self) -> str:
        return jit.source_key(jit.compiled_source({"jac": self.sources["jac"]})) if self.has_jacobian else ""

    def is_jacobian_compiled(self) -> bool:
        """True when ``compiled_jacobian()`` would return at once (or there is no Jacobian to compile)."""
        return not self.has_jacobian or jit.ready(self.jacobian_key)

    def compiled_jacobian(self) -> ModuleType | None:
        """The numba module with ``jac`` (a module of its own: only the implicit methods need it, and the
        Jacobian's source is several times the right-hand side's); None when no Jacobian is generated."""
        if not self.has_jacobian:
            return None
        with self._lock:
            if self._compiled_jacobian is None:
                self._compiled_jacobian = jit.compiled_functions({"jac": self.sources["jac"]})
            return self._compiled_jacobian

    def bound(self, name: str) -> Bound:
        """``rhs``, ``ham`` or ``jac`` compiled, ready to hand to a kernel (the address looked up once per system)."""
        with self._lock:
            found = self._bound.get(name)
        if found is None:
            from app.numerics.bound import Bound
            from app.numerics.kernels.common import RHS_SIG

            module = self.compiled_jacobian() if name == "jac" else self.compiled()
            if module is None:
                raise KeyError(f"no generated {name} for this system")
            found = Bound(getattr(module, name), RHS_SIG)
            with self._lock:
                self._bound[name] = found
        return found

    # The Python twins get lists of floats: plain float arithmetic is faster than numpy scalars, and a
    # division by zero raises ZeroDivisionError instead of warning and returning inf.
    def f(self, t: float, y: np.ndarray, k: np.ndarray) -> np.ndarray:
        out = np.empty(2 * self.n)
        if self._compiled is not None:
            # the numba twin once loaded: a long expression costs it about 1 us instead of 10-100 us
            self.bound("rhs")(float(t), np.ascontiguousarray(y, dtype=float), np.ascontiguousarray(k, dtype=float), out)
            return out
        self.python["rhs"](float(t), np.asarray(y, dtype=float).tolist(), np.asarray(k, dtype=float).tolist(), out)
        return out

    def jacobian(self, t: float, y: np.ndarray, k: np.ndarray) -> np.ndarray | None:
        """dF/dy from the engine's expressions, or None when not generated."""
        if "jac" not in self.python:
            return None
        m = 2 * self.n
        out = np.empty(m * m)
        self.python["jac"](float(t), np.asarray(y, dtype=float).tolist(), np.asarray(k, dtype=float).tolist(), out)
        return out.reshape(m, m)

    def momenta(self, t: float, y: np.ndarray, k: np.ndarray) -> np.ndarray:
        out = np.empty(self.n)
        self.python["momenta"](float(t), np.asarray(y, dtype=float).tolist(), np.asarray(k, dtype=float).tolist(), out)
        return out


def _mass_and_forcing(eqs):
    """The entries of M and f, whose symbols are those of M⁻¹f."""
    return (*eqs.mass_matrix, *eqs.forcing)


def _free(expr, symbols) -> bool:
    return not sp.sympify(expr).has(*symbols)


def generated_sources(d: Derivation) -> dict[str, str]:
    """The generated scalar functions of a derivation, by name (rhs, ham, momenta, and jac when compact)."""
    names = Names.of(d)
    sources = {"rhs": rhs_source(d, names), "momenta": momenta_source(d, names)}
    if not d.equations.velocity_dependent:
        # q_dot = M⁻¹(p − b) needs M free of q_dot
        sources["ham"] = hamilton_source(d, names)
    jac = jacobian_source(d, names)
    if jac is not None:
        sources["jac"] = jac
    return sources


def numeric_system(d: Derivation, sources: dict[str, str] | None = None) -> NumericSystem:
    """Generate (never simplify) the numeric functions of a derivation; ``sources`` when already generated
    (``generated_sources`` of the same derivation, e.g. from a disk cache)."""
    table, eqs, en = d.table, d.equations, d.energetics
    sources = dict(sources) if sources is not None else generated_sources(d)
    mass_constant = all(_free(x, (*table.q, *table.qd, table.t)) for x in eqs.mass_matrix)
    forced = any(Q != 0 for Q in d.mechanics.Q)
    separable = (
        mass_constant
        and not forced
        and (
            all(_free(a, (*table.qd, table.t)) for a in eqs.accelerations)
            if eqs.closed_form  # M⁻¹f: free of q_dot and t when M (constant here) and f are
            else all(_free(x, (*table.qd, table.t)) for x in eqs.forcing)
        )
        and all(_free(p.xreplace(dict.fromkeys(table.qd, 0)), (*table.q, table.t)) for p in eqs.momenta)
    )
    autonomous = all(
        _free(a, (table.t,)) for a in (eqs.accelerations if eqs.closed_form else (*_mass_and_forcing(eqs),))
    )
    conserved = tuple(c.name for c in en.conserved)
    energy_name = next((c.name for c in en.conserved if c.name in ("E", "h")), None)
    system = NumericSystem(
        derivation=d,
        coordinates=tuple(table.names),
        parameter_names=tuple(table.parameter_names),
        sources=sources,
        python=jit.python_functions(sources),
        separable=separable,
        autonomous=autonomous,
        energy_name=energy_name,
        conserved=conserved,
        key=jit.source_key("".join(sources.values())),
        legendre_linear="ham" in sources,
    )
    system.periodic = tuple(_is_angle(system, i) for i in range(system.n))
    return system


def _is_angle(system: NumericSystem, i: int) -> bool:
    """True when the equations repeat after q_i -> q_i + 2 pi (checked at random states and parameters)."""
    rng = np.random.default_rng(7)
    for _ in range(4):
        y = rng.uniform(0.2, 1.3, 2 * system.n)
        k = rng.uniform(0.5, 2.0, len(system.parameter_names))
        t = float(rng.uniform(0.0, 1.0))
        shifted = y.copy()
        shifted[i] += 2 * np.pi
        try:
            a, b = system.f(t, y, k), system.f(t, shifted, k)
        # TypeError: a fractional power of a negative number is complex in Python (|q̇| > c of a relativistic L)
        except (ArithmeticError, ValueError, TypeError):
            return False
        if not np.allclose(a, b, rtol=1e-9, atol=1e-12):
            return False
    return True
