"""Systems users type in: check, derive and simulate them inside the worker pool.

A request arrives as plain data (the web layer validated its shape):

    {"coordinates": [...], "parameters": [{"name", "value", "unit", "min", "max"}, ...],
     "lagrangian": ... | "kinetic": ..., "potential": ... | "particles": [...], "potential": ...,
     "forces": {coordinate: Q}, "nonnegative": [...]}

``check_system`` refuses bad names and bad expressions in pure Python (no
SymPy), each refusal carrying the location of the offending field
(``["particles", 0, "position", 1]``) and the character span of the offending
part.  The jobs ``derive_job`` and ``simulate_job`` run in a worker process:
they check again, build every expression in SymPy, derive the system with the
engine and return the JSON document as bytes.  The event loop only checks,
looks up caches and awaits.
"""

from __future__ import annotations

import asyncio
import hashlib
import json
import logging
import math
import threading
from collections import OrderedDict
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from app.engine.budget import BudgetExceeded, time_limit
from app.engine.contract import derivation_json
from app.engine.derive import Derivation, derive
from app.engine.errors import DerivationError, excerpt
from app.engine.parse import MAX_TERMS, ExpressionError, Size, check_name, expression_size, parse_expression
from app.engine.symbols import SymbolTable
from app.scenes.types import Parameter, Particle, System
from app.service import fairness as fair
from app.service import worker
from app.service.encoding import dumps
from app.settings import settings

MAX_COORDINATES = 6
MAX_PARAMETERS = 24
MAX_PARTICLES = 8
DERIVE_SECONDS = settings().derive_seconds
SIMULATE_SECONDS = settings().simulate_seconds
# the engine's own budget for one derivation, inside the worker's hard limit: over it, a refusal naming it
ENGINE_SECONDS = DERIVE_SECONDS * 2 / 3

log = logging.getLogger(__name__)


class InvalidSystem(DerivationError):
    """A user system refused; ``loc`` is the path of the offending field in the request."""

    def __init__(self, message: str, loc: tuple = (), part: str = "", start: int | None = None, end: int | None = None):
        super().__init__(message, part)
        self.loc = tuple(loc)
        self.start = start
        self.end = end

    def __reduce__(self):
        return (type(self), (str(self), self.loc, self.part, self.start, self.end))

    def as_json(self) -> dict[str, Any]:
        return {
            "detail": str(self)[:500],
            "part": self.part[:80],
            "loc": ["body", *(excerpt(x) for x in self.loc)],
            "start": self.start,
            "end": self.end,
        }


def _where(loc: tuple) -> str:
    head, *rest = loc
    text = str(head)
    for x in rest:
        text += f"[{x}]" if isinstance(x, int) else f".{excerpt(x)}"
    return text


def _refuse(loc: tuple, exc: ExpressionError) -> InvalidSystem:
    return InvalidSystem(f"{_where(loc)}: {exc}", loc, exc.part, getattr(exc, "start", None), getattr(exc, "end", None))


def form_of(spec: dict[str, Any]) -> str:
    """Which of the three forms the system is given in (the field a derivation error points at)."""
    if spec.get("particles"):
        return "particles"
    return "lagrangian" if spec.get("lagrangian") is not None else "kinetic"


def expressions(spec: dict[str, Any]) -> Iterator[tuple[tuple, str, bool]]:
    """Every expression of a system: (location, text, whether velocities may appear)."""
    for i, particle in enumerate(spec.get("particles") or ()):
        yield ("particles", i, "mass"), particle["mass"], False
        for j, component in enumerate(particle["position"]):
            yield ("particles", i, "position", j), component, False
    for key, velocities in (("lagrangian", True), ("kinetic", True), ("potential", False)):
        if spec.get(key) is not None:
            yield (key,), spec[key], velocities
    for name, text in (spec.get("forces") or {}).items():
        yield ("forces", name), text, True


def _names(spec: dict[str, Any]) -> tuple[list[str], list[str]]:
    coordinates = list(spec.get("coordinates") or ())
    parameters = [p["name"] for p in spec.get("parameters") or ()]
    return coordinates, parameters


def check_system(spec: dict[str, Any]) -> None:
    """Refuse a system whose names or expressions are not allowed (pure Python, no SymPy)."""
    coordinates, parameters = _names(spec)
    if not 1 <= len(coordinates) <= MAX_COORDINATES:
        raise InvalidSystem(f"give between 1 and {MAX_COORDINATES} coordinates", ("coordinates",))
    if len(parameters) > MAX_PARAMETERS:
        raise InvalidSystem(f"at most {MAX_PARAMETERS} parameters are allowed", ("parameters",))
    if len(spec.get("particles") or ()) > MAX_PARTICLES:
        raise InvalidSystem(f"at most {MAX_PARTICLES} particles are allowed", ("particles",))
    seen: set[str] = set()
    named = [(("coordinates", i), n, "coordinate") for i, n in enumerate(coordinates)]
    named += [(("parameters", i, "name"), n, "parameter") for i, n in enumerate(parameters)]
    for loc, name, what in named:
        try:
            check_name(name, what)
        except ExpressionError as exc:
            raise _refuse(loc, exc) from None
        if name in seen:
            raise InvalidSystem(f"{_where(loc)}: the name {name!r} is declared twice", loc, name)
        seen.add(name)
    for i, p in enumerate(spec.get("parameters") or ()):
        low, high, value = p.get("min"), p.get("max"), p.get("value", 1.0)
        if low is not None and high is not None and low > high:
            loc = ("parameters", i, "min")
            raise InvalidSystem(f"{_where(loc)}: min {low:g} is larger than max {high:g}", loc)
        if (low is not None and value < low) or (high is not None and value > high):
            loc = ("parameters", i, "value")
            span = f"{'-inf' if low is None else f'{low:g}'} to {'inf' if high is None else f'{high:g}'}"
            raise InvalidSystem(f"{_where(loc)}: {value:g} is outside the allowed range, {span}", loc)

    forms = [bool(spec.get("particles")), spec.get("kinetic") is not None, spec.get("lagrangian") is not None]
    if sum(forms) != 1:
        raise InvalidSystem(
            "give exactly one of: particles (with a potential), kinetic and potential, or lagrangian", ()
        )
    if spec.get("lagrangian") is not None and spec.get("potential") is not None:
        raise InvalidSystem("potential: a Lagrangian already contains the potential; give L alone", ("potential",))
    if spec.get("lagrangian") is None and spec.get("potential") is None:
        raise InvalidSystem(
            "potential: a potential U is needed with particles or with T (write 0 if none)", ("potential",)
        )
    for name in spec.get("forces") or {}:
        if name not in coordinates:
            raise InvalidSystem(f"forces: {name[:40]!r} is not a coordinate", ("forces", name), name[:40])
    for i, name in enumerate(spec.get("nonnegative") or ()):
        if name not in coordinates:
            raise InvalidSystem(f"nonnegative[{i}]: {name[:40]!r} is not a coordinate", ("nonnegative", i), name[:40])

    base = set(coordinates) | set(parameters) | {"t"}
    with_velocities = base | {f"{q}_dot" for q in coordinates}
    sizes = {}
    for loc, text, velocities in expressions(spec):
        try:
            sizes[loc] = expression_size(text, with_velocities if velocities else base)
        except ExpressionError as exc:
            raise _refuse(loc, exc) from None
    _check_kinetic_size(spec, sizes)


def _check_kinetic_size(spec: dict[str, Any], sizes: dict[tuple, Size]) -> None:
    """Refuse particles whose kinetic energy would expand past MAX_TERMS terms (before SymPy builds it).

    A position of n terms of degree d has a velocity of at most n*d terms (each
    monomial differentiates into one term per factor); its square has at most
    v(v + 1)/2 terms, times the terms of the mass; T sums those over particles and axes.
    """
    total = 0
    for i, particle in enumerate(spec.get("particles") or ()):
        mass = sizes[("particles", i, "mass")].terms
        for j in range(len(particle["position"])):
            size = sizes[("particles", i, "position", j)]
            velocity = size.terms * max(1, math.ceil(size.degree))
            total += mass * velocity * (velocity + 1) // 2
        if total > MAX_TERMS:
            loc = ("particles", i, "position")
            raise InvalidSystem(
                f"{_where(loc)}: the kinetic energy of these particles would expand into more than {MAX_TERMS} "
                "terms; use fewer or simpler positions (or give T and U directly)",
                loc,
            )


def to_system(spec: dict[str, Any]) -> System:
    """The engine's declaration of a checked request."""
    particles = []
    for p in spec.get("particles") or ():
        position = tuple(p["position"]) + ("0",) * (3 - len(p["position"]))
        particles.append(Particle(p["mass"], position, p.get("label") or ""))
    return System(
        coordinates=tuple(spec["coordinates"]),
        parameters=tuple(
            Parameter(p["name"], float(p.get("value", 1.0)), p.get("unit") or "", p.get("min"), p.get("max"))
            for p in spec.get("parameters") or ()
        ),
        particles=tuple(particles),
        kinetic=spec.get("kinetic"),
        potential=spec.get("potential"),
        lagrangian=spec.get("lagrangian"),
        forces=dict(spec.get("forces") or {}),
        nonnegative=tuple(spec.get("nonnegative") or ()),
    )


# ---- in the worker --------------------------------------------------------------------------


def build_system(spec: dict[str, Any]) -> System:
    """Check a request and build each expression in SymPy (gate 3), locating any refusal."""
    check_system(spec)
    coordinates, parameters = _names(spec)
    namespace = SymbolTable(tuple(coordinates), tuple(parameters)).namespace()
    positional = {k: v for k, v in namespace.items() if not k.endswith("_dot")}
    for loc, text, velocities in expressions(spec):
        try:
            parse_expression(text, namespace if velocities else positional)
        except ExpressionError as exc:
            raise _refuse(loc, exc) from None
    return to_system(spec)


@contextmanager
def engine_budget(spec: dict[str, Any]) -> Iterator[None]:
    """One time budget for the engine's work on a user system, below the worker's hard limit.

    Every expand, substitution, solve and display step inside shares it (the
    engine's own smaller budgets nest within it); running out is a refusal that
    names the limit, not a killed worker.
    """
    try:
        with time_limit(ENGINE_SECONDS):
            yield
    except BudgetExceeded:
        where = form_of(spec)
        raise InvalidSystem(
            f"{where}: deriving this system takes longer than the {ENGINE_SECONDS:g} s allowed; "
            "write it with fewer terms, lower powers or fewer nested functions",
            (where,),
        ) from None


_derivations: OrderedDict[str, Derivation] = OrderedDict()


def _derive(spec: dict[str, Any]) -> Derivation:
    """Derive a checked system (a small cache per worker: simulating after deriving is common)."""
    key = spec_key(spec)
    if key in _derivations:
        _derivations.move_to_end(key)
        return _derivations[key]
    where = form_of(spec)
    try:
        with engine_budget(spec):
            system = build_system(spec)
            d = derive(system)
    except DerivationError as exc:  # a singular mass matrix and the like: the form's field is at fault
        if isinstance(exc, InvalidSystem):
            raise
        raise InvalidSystem(f"{where}: {exc}", (where,), exc.part) from None
    _derivations[key] = d
    while len(_derivations) > 8:
        _derivations.popitem(last=False)
    return d


def _guarded(job: Callable[[], Any]) -> bytes:
    """Run a job; an engine failure on user input is a refusal, never a server error."""
    try:
        return dumps(job())
    except (InvalidSystem, MemoryError, RecursionError):
        raise
    except DerivationError as exc:
        raise InvalidSystem(str(exc), (), exc.part) from None
    except Exception:  # a SymPy or numerics failure on an odd but allowed input
        log.exception("user system failed")
        # the details are for the log; the student gets a sentence without the engine's internal names
        raise InvalidSystem(
            "the engine could not handle this system (a limit of the engine, not a mistake in what you wrote); "
            "try writing it another way, for example without Abs or with simpler expressions"
        ) from None


def derive_job(spec: dict[str, Any]) -> bytes:
    """Worker job: the derivation JSON of a user system (as for a scene)."""

    def run() -> dict[str, Any]:
        with engine_budget(spec):
            return derivation_json(_derive(spec))

    return _guarded(run)


def simulate_job(spec: dict[str, Any], request: Any) -> bytes:
    """Worker job: the simulation JSON of a user system (as for a scene)."""
    from app.numerics.errors import SimulationError
    from app.service.simulation import simulate_derivation

    def run() -> dict[str, Any]:
        d = _derive(spec)
        try:
            return simulate_derivation(d, request)
        except SimulationError as exc:
            raise InvalidSystem(str(exc), simulation_loc(spec, exc.part), exc.part) from None

    return _guarded(run)


def export_job(
    spec: dict[str, Any], fmt: str, initial: dict[str, float], t_end: float | None, document: bytes
) -> bytes:
    """Worker job: a user system as a notebook, script or LaTeX document (JSON-wrapped).

    ``document`` is the system's derivation JSON (from ``derive_job``), so only printing is left to do."""
    from app.numerics.errors import SimulationError
    from app.service.export.code import ExportError
    from app.service.exporting import system_export

    def run() -> dict[str, str]:
        d = _derive(spec)
        try:
            return system_export(d, json.loads(document), fmt, initial, t_end)
        except SimulationError as exc:
            raise InvalidSystem(str(exc), simulation_loc(spec, exc.part), exc.part) from None
        except ExportError as exc:
            raise InvalidSystem(f"this system cannot be exported: {exc}") from None

    return _guarded(run)


def simulation_loc(spec: dict[str, Any], part: str) -> tuple:
    """Where in a simulate request the numerics' complaint points ("parameters.k" is that parameter's value)."""
    head, _, name = part.partition(".")
    if head == "parameters":
        names = [p["name"] for p in spec.get("parameters") or ()]
        return ("parameters", names.index(name), "value") if name in names else ("parameters",)
    if head == "initial":
        return ("initial", name) if name else ("initial",)
    return (head,) if head else ()


# ---- in the web process ---------------------------------------------------------------------


def spec_key(spec: dict[str, Any], *extra: Any) -> str:
    text = json.dumps([spec, *extra], sort_keys=True, separators=(",", ":"), default=str)
    return hashlib.sha256(text.encode()).hexdigest()


class ResultCache:
    """A small LRU of finished documents (bytes), bounded in entries and in total size."""

    def __init__(self, entries: int = 256, total_bytes: int = 64 * 2**20):
        self.entries = entries
        self.total_bytes = total_bytes
        self._items: OrderedDict[str, bytes] = OrderedDict()
        self._size = 0
        self._lock = threading.Lock()

    def get(self, key: str) -> bytes | None:
        with self._lock:
            value = self._items.get(key)
            if value is not None:
                self._items.move_to_end(key)
            return value

    def put(self, key: str, value: bytes) -> None:
        with self._lock:
            if key in self._items or len(value) > self.total_bytes // 4:
                return
            self._items[key] = value
            self._size += len(value)
            while len(self._items) > self.entries or self._size > self.total_bytes:
                _, dropped = self._items.popitem(last=False)
                self._size -= len(dropped)


class UserSystems:
    """Derive and simulate user systems: caches, fairness, then the worker pool."""

    def __init__(self, pool: worker.WorkerPool | None = None, gate: fair.Fairness | None = None):
        self._pool = pool
        self._gate = gate
        self.derivations = ResultCache()
        self.simulations = ResultCache(entries=64)
        self.exports = ResultCache(entries=64)
        self._running: dict[tuple[int, str], asyncio.Future] = {}
        self._queued: dict[tuple[int, str], fair.Ticket] = {}  # the ticket of each running slot
        self._waiters: dict[tuple[int, str], int] = {}

    @property
    def pool(self) -> worker.WorkerPool:
        if self._pool is None:
            self._pool = worker.pool()
        return self._pool

    @property
    def gate(self) -> fair.Fairness:
        if self._gate is None:
            self._gate = fair.Fairness(capacity=4 * self.pool.workers, workers=self.pool.workers)
        return self._gate

    async def _run(self, cache: ResultCache, key: str, client: str, address: str, timeout: float, job, *args) -> bytes:
        """A cached answer, else the same request already running, else a new job (one fair-share ticket)."""
        cached = cache.get(key)
        if cached is not None:
            return cached
        # a classroom opening one shared link asks for the same system at once: one job serves them all
        slot = (id(asyncio.get_running_loop()), key)
        running = self._running.get(slot)
        if running is None:
            ticket = self.gate.admit(client, address)
            running = asyncio.ensure_future(self._job(cache, key, ticket, timeout, job, args))
            self._running[slot] = running
            self._queued[slot] = ticket
            running.add_done_callback(lambda done: self._finished(slot, done))
        # a client that goes away does not stop the job the others wait for; the last one to go, while it queues, does
        self._waiters[slot] = self._waiters.get(slot, 0) + 1
        try:
            return await asyncio.shield(running)
        except asyncio.CancelledError:
            queued = self._queued.get(slot)
            if self._waiters.get(slot) == 1 and queued is not None and not queued.running:
                running.cancel()
            raise
        finally:
            if slot in self._waiters:
                self._waiters[slot] -= 1

    async def run_job(self, cache: ResultCache, key: str, client: str, address: str, timeout: float, job, *args) -> bytes:
        """Another kind of job on user text (checking a student's answer): same cache, sharing, fair share and pool."""
        return await self._run(cache, key, client, address, timeout, job, *args)

    def _finished(self, slot: tuple[int, str], done: asyncio.Future) -> None:
        self._running.pop(slot, None)
        self._queued.pop(slot, None)
        self._waiters.pop(slot, None)
        if not done.cancelled():
            done.exception()  # retrieved here too, in case every waiter went away

    async def _job(self, cache: ResultCache, key: str, ticket: fair.Ticket, timeout: float, job, args) -> bytes:
        def submit() -> Any:
            try:
                future = self.pool.submit(job, *args, timeout=timeout)
            except BaseException:
                ticket.release("failed")
                raise
            # the slot is freed when the job really ends; a job out of time or memory counts against its client
            future.add_done_callback(lambda done: ticket.release(worker.ending(done)))
            return future

        await self.gate.turn(ticket)  # a fair turn for a worker, within the queue deadline
        # in a thread: the first job starts the forkserver (importing the engine), which takes seconds
        future = await asyncio.to_thread(submit)
        result = await self.pool.run_async(future, timeout)
        cache.put(key, result)
        return result

    async def derive(self, spec: dict[str, Any], client: str, address: str) -> bytes:
        check_system(spec)
        return await self._run(self.derivations, spec_key(spec), client, address, DERIVE_SECONDS, derive_job, spec)

    async def simulate(self, spec: dict[str, Any], request: Any, client: str, address: str) -> bytes:
        check_system(spec)
        key = spec_key(spec, request.model_dump(mode="json"))
        return await self._run(self.simulations, key, client, address, SIMULATE_SECONDS, simulate_job, spec, request)

    async def export(
        self, spec: dict[str, Any], fmt: str, initial: dict[str, float], t_end: float | None, client: str, address: str
    ) -> bytes:
        """``{"content", "filename", "media_type"}`` as JSON bytes, made in the pool under the derive limit."""
        check_system(spec)
        key = spec_key(spec, "export", fmt, initial, t_end)
        cached = self.exports.get(key)
        if cached is not None:
            return cached
        # the derivation the page already asked for (cached), or a derive job first: the export only prints
        document = await self.derive(spec, client, address)
        return await self._run(
            self.exports, key, client, address, DERIVE_SECONDS, export_job, spec, fmt, initial, t_end, document
        )


service = UserSystems()
