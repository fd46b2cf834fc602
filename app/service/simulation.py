"""Simulations of scenes and of user systems: validation, compiled-system cache, the JSON result.

``simulate_derivation`` is the one entry point: the scene route calls it with
a scene's derivation, the user-system worker with a user's.  It checks the
request against the system's declared ranges, builds (once per system and
process) the numeric functions, runs ``app.numerics.simulate`` and returns the
documented JSON:

    {"t", "state": {q, q_dot}, "energy", "hamiltonian", "conserved": {name: [...]},
     "constraint_forces": {name: [...]}, "stats": {...}}
"""

from __future__ import annotations

import hashlib
import json
import math
import threading
import time
from collections import OrderedDict
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import AbstractContextManager, ExitStack, contextmanager
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from app.engine.derive import Derivation
from app.errors import OverCapacity
from app.limits import DEFAULT_T_END, GIVE_WAY_SECONDS
from app.numerics import limits, methods
from app.numerics.errors import SimulationError
from app.numerics.events import EventFunction, compile_events
from app.numerics.methods import AUTO, METHODS, NONSTIFF
from app.numerics.methods.scipy_ivp import scipy_integrate
from app.numerics.observables import Observables, build, summarize
from app.numerics.plan import Plan, plan
from app.numerics.simulate import Outcome, run
from app.numerics.start import why_not_at_start
from app.numerics.system import NumericSystem, generated_sources, numeric_system
from app.scenes import SCENES, Scene
from app.service.cache import JsonCache, source_fingerprint
from app.service.trust import judge
from app.settings import container_cpus, settings

SLOTS = max(2, container_cpus())
HEAVY_SPAN = 10  # times the scene's t_end (or the default 10 s)
HEAVY_RTOL = 1e-9


class Offload(Protocol):
    """Runs ``job(*args)`` in a worker process and returns its result (``WorkerPool.run``)."""

    def __call__(self, job: Callable[..., Any], /, *args: Any, timeout: float) -> Any: ...


class SimulationInput(Protocol):
    """What a request carries (``app.web.schemas_simulate.SimulateRequest`` has these fields)."""

    parameters: Mapping[str, float]
    initial: Mapping[str, float]
    t_end: float | None
    method: str
    rtol: float | None
    atol: float | None
    samples: int | None
    precision: str  # "full" or "display" (absent means full)


class _Compiled:
    """Numeric systems per scene id (or per generated source for user systems), per process.

    One lock per key: a request for one scene never waits while another scene's system is built
    (by the warm-up thread or another request); two requests for the same scene build it once."""

    def __init__(self, size: int = 32):
        self.size = size
        self.items: OrderedDict[str, tuple[NumericSystem, Observables]] = OrderedDict()
        self.lock = threading.Lock()  # guards ``items`` and ``_building``, held only briefly
        self._building: dict[str, threading.Lock] = {}
        self.build_seconds: dict[str, float] = {}

    def _cached(self, key: str) -> tuple[NumericSystem, Observables] | None:
        with self.lock:
            if key in self.items:
                self.items.move_to_end(key)
                return self.items[key]
            return None

    def get(
        self, key: str | None, d: Derivation, forces: Sequence[dict[str, Any]]
    ) -> tuple[NumericSystem, Observables]:
        # a user system's key is its declaration (and its constraint forces), known before any code
        # generation: a warm system is found here without printing a line of its source again
        scene = key is not None
        found_key = key if key is not None else system_key(d, forces)
        found = self._cached(found_key)
        if found is not None:
            return found
        with self.lock:
            building = self._building.setdefault(found_key, threading.Lock())
        with building:
            return self._cached(found_key) or self._build(found_key, d, forces, scene)

    def _build(
        self, key: str, d: Derivation, forces: Sequence[dict[str, Any]], scene: bool
    ) -> tuple[NumericSystem, Observables]:
        start = time.perf_counter()
        # a scene's generated sources come from the disk cache (keyed by the engine's, scenes' and
        # numerics' source), so a new worker skips the code generation
        sources = _SOURCES.get(key, lambda: generated_sources(d)) if scene else None
        system = numeric_system(d, sources)
        entry = (system, build(system, forces))
        with self.lock:
            self.build_seconds[key] = time.perf_counter() - start
            self.items[key] = entry
            while len(self.items) > self.size:
                self.items.popitem(last=False)
        return entry


def system_key(d: Derivation, forces: Sequence[dict[str, Any]]) -> str:
    """A user system's cache key: a digest of its declaration (the parsed System) and its constraint forces."""
    text = repr(d.system) + json.dumps(list(forces), sort_keys=True, default=str)
    return "system:" + hashlib.sha256(text.encode()).hexdigest()


_EVENTS: dict[str, list[EventFunction]] = {}  # per scene id: its terminal events, compiled once per process


def _events(scene: Scene | None, system: NumericSystem) -> list[EventFunction]:
    if scene is None or not scene.events:
        return []
    if scene.id not in _EVENTS:
        _EVENTS[scene.id] = compile_events(system, scene.events)
    return _EVENTS[scene.id]


_SOURCES = JsonCache("generated-sources", source_fingerprint("engine", "scenes", "numerics"))
COMPILED = _Compiled()


def _check_number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SimulationError(f"{where} must be a finite number", where)
    if abs(value) > limits.VALUE_MAX:
        raise SimulationError(f"{where} = {value:g} is beyond the allowed magnitude {limits.VALUE_MAX:g}", where)
    return float(value)


def _in_range(value: float, low: float | None, high: float | None) -> bool:
    return (low is None or value >= low) and (high is None or value <= high)


def parameter_vector(d: Derivation, given: Mapping[str, float]) -> np.ndarray:
    declared = {p.name: p for p in d.system.parameters}
    unknown = sorted(set(given) - set(declared))
    if unknown:
        raise SimulationError(
            f"unknown parameter {unknown[0][:40]!r}; this system has {', '.join(declared) or 'no parameters'}",
            "parameters",
        )
    values = []
    for name, p in declared.items():
        value = _check_number(given.get(name, p.default), f"parameters.{name}")
        if not _in_range(value, p.min, p.max):
            raise SimulationError(
                f"parameters.{name} = {value:g} is outside its allowed range [{p.min}, {p.max}] {p.unit}".rstrip(),
                f"parameters.{name}",
            )
        values.append(value)
    return np.array(values, dtype=float)


def initial_state(d: Derivation, given: Mapping[str, float], defaults: Mapping[str, float]) -> np.ndarray:
    names = list(d.table.names)
    allowed = names + [f"{q}_dot" for q in names]
    unknown = sorted(set(given) - set(allowed))
    if unknown:
        raise SimulationError(f"unknown initial value {unknown[0][:40]!r}; allowed: {', '.join(allowed)}", "initial")
    y0 = np.array([_check_number(given.get(n, defaults.get(n, 0.0)), f"initial.{n}") for n in allowed])
    for q in d.system.nonnegative:
        if y0[names.index(q)] < 0:
            raise SimulationError(f"initial.{q} must be >= 0 ({q} is a distance)", f"initial.{q}")
    return y0


def _setting(value: Any, default: float, low: float, high: float, where: str) -> float:
    value = default if value is None else _check_number(value, where)
    if not low <= value <= high:
        raise SimulationError(f"{where} = {value:g} is outside the allowed range [{low:g}, {high:g}]", where)
    return value


# Significant digits of the series in a "display" document: a plot or a readout needs far fewer
# than the 17 of a double, and short numbers make the response about half the size.
DISPLAY_DIGITS = 7


# 10^d as the double nearest it (from its decimal literal), d = -400 .. 399: DECADES[d + 400]
DECADES = np.array([float(f"1e{d}") for d in range(-400, 400)])
# 10^s for s = 0 .. 399 as the rounding has always computed it (exact up to 10^22; inf beyond 10^308)
with np.errstate(over="ignore"):
    POWERS = 10.0 ** np.arange(0.0, 400.0)
LOG10_2 = 0.30102999566398120


def display_rounded(values: np.ndarray, digits: int = DISPLAY_DIGITS) -> np.ndarray:
    """Each finite x rounded to ``digits`` significant digits (0, NaN and Infinity unchanged).

    With e = floor(log10 |x|), x = round(x 10^s) 10^-s for s = digits - 1 - e.  The power of ten is
    applied as an exact multiplier or divisor (10^|s| is exact up to 10^22), so for 1e-16 <= |x| < 1e22
    the result is the double nearest the rounded decimal; beyond, it may be one unit in the last place
    off it.  Either way it prints with at most ``digits`` digits."""
    out = np.array(values, dtype=float)
    finite = np.isfinite(out) & (out != 0.0)
    every = bool(finite.all())
    x = out if every else out[finite]
    size = np.abs(x)
    # e without a logarithm: |x| = m 2^b with m in [1/2, 1) puts log10 |x| in [(b - 1) log10 2, b log10 2),
    # so e is d = floor((b - 1) log10 2) or d + 1, the latter when |x| >= 10^(d+1)
    # (log10 and 10.0**s were two thirds of this function's time: 94 against 31 us per 1000 values)
    _, b = np.frexp(size)
    e = np.floor((b - 1) * LOG10_2).astype(np.int64)
    e += size >= DECADES[e + 401]
    shift = (digits - 1) - e
    power = POWERS[np.abs(shift)]
    if shift.min(initial=0) >= 0:  # every |x| below 10^digits: the usual case, one branch
        rounded = np.round(x * power) / power
    else:
        with np.errstate(over="ignore", invalid="ignore"):  # each branch is kept only where it applies
            rounded = np.where(shift >= 0, np.round(x * power) / power, np.round(x / power) * power)
    if every:
        return rounded
    out[finite] = rounded
    return out


def _series(values: np.ndarray, precision: str = "full") -> np.ndarray:
    """A series as the document carries it: a float array (orjson writes NaN and Infinity as null)."""
    values = np.ascontiguousarray(values, dtype=float)
    return display_rounded(values) if precision == "display" else values


@contextmanager
def _slot(gate: threading.BoundedSemaphore, message: str) -> Iterator[None]:
    """Hold one of a gate's slots, or refuse as busy: under a flood a request fails fast (the
    ``scene_queue_seconds`` setting) rather than holding a server thread while it waits."""
    if not gate.acquire(timeout=min(settings().scene_queue_seconds, limits.WALL_SECONDS)):
        raise OverCapacity(message, 1)
    try:
        yield
    finally:
        gate.release()


class Gates:
    """How many simulations run at once in one process: ``slots`` in all, at most half of them heavy.

    The app builds its own (``app.service.services``) and gives it to the routes, with ``offload``:
    the ``run`` of a worker process of its own for the scenes' runs that step in Python (scipy's
    loops hold the GIL for their whole run; there they cannot delay the event loop, ``/healthz``
    included, and they never wait behind a user's derivation).  One such run at a time per web
    process (``python_loop``), so that worker is free whenever a run is sent to it.

    ``answer_while_compiling`` (a server that compiles its kernels in the background): an ``auto``
    request whose compiled method is not ready yet is answered by scipy instead of waiting on numba.
    A worker process or a script uses ``GATES``, which runs everything in line and compiles first."""

    def __init__(
        self, slots: int = SLOTS, offload: Offload | None = None, answer_while_compiling: bool = False
    ) -> None:
        self.offload = offload
        self.answer_while_compiling = answer_while_compiling
        self.slots = threading.BoundedSemaphore(slots)
        self.heavy = threading.BoundedSemaphore(max(1, slots // 2))
        # scipy's integrators loop in Python and hold the GIL for their whole run: one at a
        # time per process, so they cannot starve the compiled runs and pages served beside them.
        self.python = threading.BoundedSemaphore(1)

    def any(self) -> AbstractContextManager[None]:
        """Hold one slot, or refuse as busy."""
        return _slot(self.slots, "too many simulations are running at once; try again in a few seconds")

    def heavy_run(self) -> AbstractContextManager[None]:
        """Hold one of the heavy runs' slots, or refuse as busy."""
        return _slot(
            self.heavy, "too many long or high-accuracy simulations are running; try again shortly, or ask for less"
        )

    def python_loop(self) -> AbstractContextManager[None]:
        """Hold the one slot for a Python step loop, or refuse as busy."""
        return _slot(
            self.python,
            "another scipy (Python step loop) run is in progress here; try again in a few seconds, "
            "or ask for a compiled method",
        )


GATES = Gates()  # this process's, where no app gives its own (a worker, a script)


def simulate_derivation(
    derivation: Derivation,
    request: SimulationInput,
    *,
    constraint_forces: Sequence[dict[str, Any]] = (),
    scene_id: str | None = None,
    gates: Gates = GATES,
) -> dict[str, Any]:
    """Simulate a derived system as the request asks; a refusal raises SimulationError, a full server OverCapacity."""
    scene: Scene | None = SCENES.get(scene_id) if scene_id else None
    k = parameter_vector(derivation, request.parameters or {})
    y0 = initial_state(derivation, request.initial or {}, scene.initial if scene else {})
    t_end = _setting(request.t_end, scene.t_end if scene else DEFAULT_T_END, 1e-9, limits.T_END_MAX, "t_end")
    rtol = _setting(request.rtol, limits.RTOL_DEFAULT, limits.RTOL_MIN, limits.RTOL_MAX, "rtol")
    atol = _setting(request.atol, limits.ATOL_DEFAULT, limits.ATOL_MIN, limits.ATOL_MAX, "atol")
    samples = int(_setting(request.samples, limits.SAMPLES_DEFAULT, limits.SAMPLES_MIN, limits.SAMPLES_MAX, "samples"))
    method = request.method or AUTO
    precision = getattr(request, "precision", None) or "full"
    if method != AUTO:
        methods.method(method)  # an unknown name is refused before any work

    system, observables = COMPILED.get(scene_id, derivation, constraint_forces)
    try:
        start = system.f(0.0, y0, k)
    except (ArithmeticError, ValueError):
        start = np.array([math.nan])
    if not np.all(np.isfinite(start)):
        raise SimulationError(why_not_at_start(derivation, y0, k), "initial")  # the cause, named
    # the plan resolves auto (and the fallback while compiling) first, so the throttle sees what will run
    planned = plan(system, k, y0, t_end, samples, method, rtol, atol, wait_for_compile=not gates.answer_while_compiling)
    # a run far beyond the scene's span or near the tolerance floor is heavy: those take at most half
    # of the slots, so a flood of them leaves the others to the light runs students send
    heavy = t_end > HEAVY_SPAN * (scene.t_end if scene else DEFAULT_T_END) or rtol < HEAVY_RTOL
    elsewhere = None
    if scene_id is not None and gates.offload is not None:
        offload = gates.offload

        def elsewhere(python_plan: Plan, wall_seconds: float) -> Outcome:
            # a Python step loop holds the GIL of the process it runs in: in the scenes' worker, not
            # beside the event loop; the worker may first start and load the scene (from the disk
            # caches), hence the margin
            return offload(
                run_scene_plan, scene_id, python_plan.portable(), wall_seconds,
                timeout=wall_seconds + settings().simulate_seconds,
            )  # fmt: skip

    with ExitStack() as held:
        if planned.python_loop:
            held.enter_context(gates.python_loop())
        elif heavy:
            held.enter_context(gates.heavy_run())
        held.enter_context(gates.any())
        outcome = run(
            planned, python_loop=gates.python_loop, events=_events(scene, system), elsewhere=elsewhere,
            # the series while the error estimate's reference run finishes beside
            alongside=lambda trajectory: observe(system, observables, trajectory, k, rtol, precision),
        )  # fmt: skip
    return document(system, observables, outcome, k, rtol, precision)


@dataclass
class Observed:
    """What a document carries of a finished trajectory besides its stats: the series (rounded as asked),
    their drifts (``summarize``'s figures and warnings) and whether every series is finite."""

    series: dict[str, Any]
    summary: dict[str, Any]
    finite: bool


def observe(
    system: NumericSystem, observables: Observables, trajectory, k: np.ndarray, rtol: float, precision: str
) -> Observed:
    """The state, energy, h, conserved quantities and constraint forces along a trajectory, and their drifts."""
    tr = trajectory
    n = system.n
    values = observables.evaluate(tr.t, tr.y, k)
    state: dict[str, np.ndarray] = {}
    for i, q in enumerate(system.coordinates):
        state[q] = _series(tr.y[:, i], precision)
        state[f"{q}_dot"] = _series(tr.y[:, n + i], precision)
    # quantities whose change since t = 0 is plotted keep every digit (rounded, the change is a staircase)
    conserved = {c: _series(values[f"conserved:{c}"]) for c in system.conserved}
    forces = {f["name"]: _series(values[f"force:{i}"], precision) for i, f in enumerate(observables.forces)}
    series = {
        "t": _series(tr.t),
        "state": state,
        "energy": _series(values["energy"]),
        "hamiltonian": _series(values["hamiltonian"]),
        "conserved": conserved,
        "constraint_forces": forces,
    }
    finite = all(np.isfinite(one).all() for one in (*state.values(), *conserved.values()))
    return Observed(series, summarize(observables, tr.t, values, rtol), finite)


def document(
    system: NumericSystem, observables: Observables, outcome, k: np.ndarray, rtol: float, precision: str = "full"
) -> dict[str, Any]:
    """The result document; ``precision="display"`` rounds the state and forces (never ``stats``, E, h or the
    conserved momenta, whose changes are plotted) to DISPLAY_DIGITS."""
    tr = outcome.trajectory
    # the series, made while the reference ran (see simulate_derivation) unless the run went elsewhere
    observed = outcome.alongside
    if observed is None:
        observed = observe(system, observables, tr, k, rtol, precision)
    summary = dict(observed.summary)
    warnings = [*outcome.warnings, *summary.pop("warnings")]
    est = outcome.estimate
    stats = {
        "method": outcome.method,
        "reason": outcome.reason,
        "path": outcome.path,
        "steps": tr.steps,
        "rhs_evaluations": tr.rhs_evaluations,
        "wall_time_s": tr.wall_time_s,
        "error_estimate": est.value if est and math.isfinite(est.value) else None,
        "error_estimate_by_coordinate": est.by_coordinate if est else {},
        "error_reference": est.reference if est else None,
        **summary,
        "complete": tr.complete,
        "t_end_reached": tr.t_reached,
        "step_size": tr.step_size,
        "stiffness": outcome.analysis.as_dict(),
        "compile_time_s": outcome.compile_seconds,
        "notes": tr.notes,
        "warnings": warnings,
        # the terminal event that ended the run (its name, time and what it means), or null
        "event": outcome.event.as_json() if outcome.event is not None else None,
    }
    if not observed.finite:
        warnings.append("some values are not finite (the motion reached a singular point); they are null")
    return {
        **observed.series,
        "stats": _finite(stats),
        "trust": _finite(judge(stats["error_estimate"], stats["error_estimate_by_coordinate"], system.coordinates, tr.y)),
        # the same right-hand side as JavaScript: the page integrates a preview while an input moves
        "preview": {
            "rhs": system.browser,
            "coordinates": list(system.coordinates),
            "parameters": list(system.parameter_names),
        },
    }


def _finite(value: Any) -> Any:
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_finite(v) for v in value]
    return value


class _InFlight:
    """Simulations running in this process: the warm-up thread gives way to them between its steps."""

    def __init__(self) -> None:
        self._count = 0
        self._changed = threading.Condition()

    @contextmanager
    def serving(self) -> Iterator[None]:
        with self._changed:
            self._count += 1
        try:
            yield
        finally:
            with self._changed:
                self._count -= 1
                self._changed.notify_all()

    def wait_quiet(self, timeout: float) -> bool:
        """Wait until no simulation runs, at most ``timeout`` seconds; True when quiet."""
        with self._changed:
            return self._changed.wait_for(lambda: self._count == 0, timeout)


IN_FLIGHT = _InFlight()


def warm_all(give_way: Callable[[], object] = lambda: None) -> dict[str, float]:
    """Compile (or load from numba's disk cache) every kernel and every scene's right-hand sides.

    Run in the background at start-up and at image build (``python -m app.service.simulation``).
    Order: scipy.integrate (the fallback); then scene by scene (in the chapter's order), its
    derivation and numeric system, then ``auto``'s compiled default (``NONSTIFF``: what it picks most
    often, and the error reference) on it; then the other compiled kernels.  A method is used the
    moment it is ready.  ``give_way`` runs between steps (the server's: wait while requests are being
    served).  Returns the seconds spent per item."""
    from app.service.derivations import derivation, derivation_document

    spent: dict[str, float] = {}
    # scipy first: it answers while the kernels load, and once imported here (under its lock) no kernel
    # module that reads scipy's tables can be importing it half-way beside a request's fallback
    start = time.perf_counter()
    scipy_integrate()
    spent["scipy.integrate"] = time.perf_counter() - start
    first = METHODS[NONSTIFF]
    systems = []
    for scene_id in SCENES:
        give_way()
        start = time.perf_counter()
        forces = derivation_document(scene_id).get("constraint_forces") or []
        system = COMPILED.get(scene_id, derivation(scene_id), forces)[0]
        systems.append(system)
        spent["numeric systems"] = spent.get("numeric systems", 0.0) + time.perf_counter() - start
        give_way()
        start = time.perf_counter()
        if first.applicable(system) is None:
            first.prepare(system)
        spent[first.name] = spent.get(first.name, 0.0) + time.perf_counter() - start
    for method in (m for m in METHODS.values() if m.compiled and m is not first):
        start = time.perf_counter()
        for system in systems:
            give_way()
            if method.applicable(system) is None:
                method.prepare(system)
        spent[method.name] = time.perf_counter() - start
    return spent


def start_warming() -> threading.Thread:
    """The server's start: answer at once (scipy while compiling), load and compile in the background.

    The thread gives way to the requests being served (``IN_FLIGHT``) between its steps, so that a
    first request shares the processor with at most one step of it (one scene's system or one kernel);
    the app's ``Gates`` answer from scipy meanwhile (``answer_while_compiling``, app/service/services.py)."""
    thread = threading.Thread(
        target=warm_all, args=(lambda: IN_FLIGHT.wait_quiet(GIVE_WAY_SECONDS),), name="warm-up", daemon=True
    )
    thread.start()
    return thread


def load_scenes() -> int:
    """A worker process's job at start-up: load every scene's numeric system (from the disk caches)."""
    from app.service.derivations import derivation, derivation_document

    for scene_id in SCENES:
        forces = derivation_document(scene_id).get("constraint_forces") or []
        COMPILED.get(scene_id, derivation(scene_id), forces)
    return len(SCENES)


def run_scene_plan(scene_id: str, portable: dict[str, Any], wall_seconds: float) -> Outcome:
    """A worker process's job: run a scene's plan (``Plan.portable``) on this process's copy of its system."""
    from app.service.derivations import derivation, derivation_document

    forces = derivation_document(scene_id).get("constraint_forces") or []
    system, _ = COMPILED.get(scene_id, derivation(scene_id), forces)
    return run(Plan.rebuilt(system, portable), wall_seconds, events=_events(SCENES[scene_id], system))


def simulate_scene(scene_id: str, request: SimulationInput, gates: Gates = GATES) -> dict[str, Any]:
    from app.service.derivations import derivation, derivation_document, scene

    scene(scene_id)
    with IN_FLIGHT.serving():  # the warm-up thread waits meanwhile
        forces = derivation_document(scene_id).get("constraint_forces") or []
        return simulate_derivation(
            derivation(scene_id), request, constraint_forces=forces, scene_id=scene_id, gates=gates
        )


if __name__ == "__main__":
    for name, seconds in warm_all().items():
        print(f"{name}: {seconds:.2f} s")
