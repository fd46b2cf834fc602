"""The plan of one simulation: which method runs, which runs the error reference, and why.

Deciding comes before running, so whoever runs the plan can look at the
concrete methods: ``auto`` resolved (``choose``), the scipy fallback taken
while the compiled code is not ready, the reference named.  Whoever runs it
can tell from them where it should run (a server keeps scipy's Python step
loops apart, whatever was asked for: ``auto`` choosing a scipy method is one).

Only a run that cannot go on as planned changes method after planning:
``Plan.handed_over`` is the plan ``auto``'s explicit method continues with when
it meets stiffness (Radau IIA), ``Plan.instead_of_symplectic`` the one its
symplectic pick continues with past its step limit.

A plan travels to a worker process by ``portable`` (everything but the system,
methods by name) and ``rebuilt`` there on that process's own copy of the system.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, fields, replace
from typing import Any

import numpy as np

from app.numerics import jit
from app.numerics.choose import Analysis, analyse, choose
from app.numerics.errors import SimulationError
from app.numerics.estimate import reference_name
from app.numerics.methods import AUTO, FALLBACK, FALLBACK_STIFF, METHODS, NONSTIFF, STIFF, Method, method
from app.numerics.methods.symplectic import FixedStep
from app.numerics.system import NumericSystem


@dataclass(frozen=True)
class Plan:
    system: NumericSystem
    k: np.ndarray
    y0: np.ndarray
    t_end: float
    samples: int
    rtol: float
    atol: float
    requested: str  # what was asked for: "auto" or a method's name
    method: Method  # what runs
    reason: str  # why, in a sentence or two
    analysis: Analysis
    path: str  # "compiled", "scipy" (a scipy method asked for or chosen), "scipy-fallback"
    reference: Method | None  # the error estimate's reference run, None without an estimate
    stiff: bool = False  # estimated as a stiff problem (the reference keeps atol); True after a hand-over
    wait_for_compile: bool = True  # False (a server): a hand-over takes scipy's Radau while the kernel compiles

    @property
    def name(self) -> str:
        return self.method.name

    @property
    def watch_stiffness(self) -> bool:
        """``auto``'s explicit default stops when it meets stiffness, to be redone with Radau."""
        return self.requested == AUTO and self.method.name == NONSTIFF

    def handed_over(self, t: float) -> Plan:
        """The plan after ``auto``'s explicit run met stiffness at ``t``: the whole run redone with the
        implicit method, estimated as a stiff problem (its reference is the stiff method, tighter)."""
        stiff = METHODS[STIFF]
        if not self.wait_for_compile and not jit.ready(stiff.kernel_module):
            stiff = METHODS[FALLBACK_STIFF]  # the kernel is still compiling (about a minute from an empty cache)
        reason = (
            f"{self.reason}; but {self.name} detected stiffness at t = {t:.4g} s (step size held at its "
            f"stability limit), so the run was redone with the implicit {stiff.name} method"
        )
        reference = METHODS[reference_name(stiff=True, compiled=stiff.compiled)] if self.reference is not None else None
        # the path says what ran: scipy's Radau steps in Python, never "compiled"
        path = "compiled" if stiff.compiled else "scipy"
        return replace(self, method=stiff, reason=reason, reference=reference, stiff=True, path=path)

    def instead_of_symplectic(self, why: str) -> Plan:
        """The plan after ``auto``'s symplectic pick could not finish (its step limit): Verner's adaptive
        pair instead, which watches for stiffness, rather than a refusal."""
        reason = f"{self.reason}; but {self.name} {why}, so auto ran {NONSTIFF} instead (adaptive step)"
        reference = _reference(METHODS[NONSTIFF], self.stiff, compiled=True) if self.reference is not None else None
        return replace(self, method=METHODS[NONSTIFF], reason=reason, reference=reference, path="compiled")

    def portable(self) -> dict[str, Any]:
        """Everything but the system, the methods by name: what a worker process needs to run this plan."""
        out = {f.name: getattr(self, f.name) for f in fields(self) if f.name != "system"}
        out["method"] = self.method.name
        out["reference"] = self.reference.name if self.reference is not None else None
        return out

    @classmethod
    def rebuilt(cls, system: NumericSystem, portable: dict[str, Any]) -> Plan:
        """The plan ``portable`` describes, on this process's copy of its system."""
        reference = portable["reference"]
        return cls(
            system=system,
            **{**portable, "method": METHODS[portable["method"]], "reference": reference and METHODS[reference]},
        )


def plan(
    system: NumericSystem,
    k: np.ndarray,
    y0: np.ndarray,
    t_end: float,
    samples: int,
    requested: str,
    rtol: float,
    atol: float,
    estimate: bool = True,
    wait_for_compile: bool = True,
    ready: Callable[[Method, NumericSystem], bool] | None = None,
) -> Plan:
    """Analyse the start, resolve ``auto``, check the method applies, and fall back to scipy while compiling.

    With ``wait_for_compile=False`` (a server), ``auto`` picking a compiled method whose code (or
    whose reference's code) is not ready yet in this process runs scipy's DOP853 on the generated
    scalar right-hand side instead, run and reference; asking for a method by name always runs it.
    ``ready(method, system)``: whether that code is ready (by default the method's own ``ready``, what this
    process has compiled; a server's gates may give another, app/service/runtime/gates.py)."""
    is_ready = ready or (lambda m, s: m.ready(s))
    analysis = analyse(system, k, y0, t_end, rtol, atol)  # one atol for every component
    if requested == AUTO:
        name, reason = choose(system, analysis)
    else:
        name, reason = method(requested).name, "requested"
    chosen = METHODS[name]
    why_not = chosen.applicable(system)
    if why_not:
        raise SimulationError(f"method {name} cannot integrate this system: {why_not}", "method")
    path = "compiled" if chosen.compiled else "scipy"
    reference = _reference(chosen, analysis.stiff, compiled=True) if estimate else None
    if (
        requested == AUTO
        and chosen.compiled
        and not wait_for_compile
        and not (is_ready(chosen, system) and (reference is None or is_ready(reference, system)))
    ):
        # the same kind of method as the pick: an explicit pair on a stiff problem would crawl
        fallback = FALLBACK_STIFF if analysis.stiff else FALLBACK
        reason = (
            f"scipy's {fallback} (Python step loop) answered, because the compiled code that auto picks here is "
            f"still being compiled in the background; once it is ready auto runs {name}: {reason}"
        )
        chosen, path = METHODS[fallback], "scipy-fallback"
        reference = _reference(chosen, analysis.stiff, compiled=False) if estimate else None
    return Plan(
        system,
        k,
        y0,
        t_end,
        samples,
        rtol,
        atol,
        requested,
        chosen,
        reason,
        analysis,
        path,
        reference,
        analysis.stiff,
        wait_for_compile,
    )


def _reference(chosen: Method, stiff: bool, compiled: bool) -> Method:
    # a fixed-step method is its own reference (with half the step); an adaptive one a tighter run
    return chosen if isinstance(chosen, FixedStep) else METHODS[reference_name(stiff, compiled)]
