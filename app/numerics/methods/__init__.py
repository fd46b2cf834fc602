"""The method registry: the one home of the integrators' names.

``base`` holds the rules, each other module one family of methods.  A method
is a ``Method`` subclass with a ``name`` and class attributes describing it
(family, order, compiled, implicit, summary); importing the family modules
defines them, and ``METHODS`` lists every concrete one in definition order.
Everything that names methods reads them from here: the request schema's
literal and the pages' menus (``CHOICES``), ``auto``'s picks (the roles below),
the error reference, the work-precision comparison.  Adding a method is
adding its class.
"""

from __future__ import annotations

from app.numerics.errors import SimulationError
from app.numerics.methods import explicit, implicit, scipy_ivp, symplectic
from app.numerics.methods.base import Method, Problem, Trajectory
from app.numerics.system import NumericSystem


def _concrete(cls: type[Method]) -> list[type[Method]]:
    found = []
    for sub in cls.__subclasses__():
        if sub.__dict__.get("name"):
            found.append(sub)
        found.extend(_concrete(sub))
    return found


FAMILIES = (explicit, implicit, symplectic, scipy_ivp)  # menu order: compiled first, then scipy's
METHODS: dict[str, Method] = {
    cls.name: cls() for family in FAMILIES for cls in _concrete(Method) if cls.__module__ == family.__name__
}
AUTO = "auto"
CHOICES: tuple[str, ...] = (AUTO, *METHODS)  # what a request may ask for
# each choice as a reader reads it (the menus, the run's details); the API's values stay the names
LABELS: dict[str, str] = {AUTO: "automatic choice", **{n: m.label or n for n, m in METHODS.items()}}

# Roles: the methods auto, the error estimate and the server's start-up give a job to.
NONSTIFF = "Vern8"  # auto's default; it watches for stiffness on the way (why this pair: choose.py)
STIFF = "Radau-compiled"  # auto's pick for a stiff start, and where a run that meets stiffness is redone
REFERENCE = NONSTIFF  # the tighter run behind an adaptive run's error estimate
FALLBACK = "DOP853"  # answers while the compiled code is not ready: no compiler needed
FALLBACK_STIFF = "Radau"  # ... and for a stiff problem (scipy's Radau IIA: the same scheme, a Python step loop)


def method(name: str) -> Method:
    """The registered method of that name; a SimulationError naming the choices otherwise."""
    if name not in METHODS:
        raise SimulationError(f"unknown method {name[:40]!r}; choose {AUTO} or one of {', '.join(METHODS)}", "method")
    return METHODS[name]


def symplectic_for(system: NumericSystem) -> Method | None:
    """The symplectic method for a system: the highest order that applies (Gauss-Legendre, order 6, wherever
    it does).  On the pendulum over 10⁴ periods it gave a 20× smaller error than Yoshida-4, a flat energy,
    and a faster run (0.22 s against 0.30 s): its larger steps more than pay for the implicit stages.  None when
    none applies (p = ∂L/∂q̇ not linear in q̇ and H not separable)."""
    usable = [m for m in METHODS.values() if m.family == "symplectic" and m.applicable(system) is None]
    return min(usable, key=lambda m: (-m.order, m.implicit)) if usable else None


__all__ = [
    "LABELS",
    "AUTO",
    "CHOICES",
    "FALLBACK",
    "FALLBACK_STIFF",
    "METHODS",
    "NONSTIFF",
    "REFERENCE",
    "STIFF",
    "Method",
    "Problem",
    "Trajectory",
    "method",
    "symplectic_for",
]
