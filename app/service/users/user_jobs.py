"""The worker pool's jobs on a user system: build it in SymPy, derive, simulate, export.

Each job takes the checked system (``app.engine.parser.user_system.UserSystem``), builds
each expression the web process read (``UserSystem.parsed``) in SymPy once, without
reading its text again (docs/parsing.md), derives the system with the engine under
one time budget and returns the JSON document as bytes.  A failure on user
input comes back as a located refusal, never as a server error.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from cachetools import LRUCache

from app.engine.algebra.budget import OutOfTime, clock_limit
from app.engine.derivation.derive import Derivation, derive
from app.engine.document.contract import printed_document
from app.engine.document.model import Document, FirstStage
from app.engine.errors import DerivationError
from app.engine.parser.parse import ExpressionError, build
from app.engine.parser.symbols import SymbolTable
from app.engine.parser.user_system import UserSystem
from app.errors import OverCapacity
from app.scenes.types import System
from app.service.runtime import progress
from app.service.runtime.encoding import dumps
from app.service.users.user_checks import (
    InvalidSystem,
    TooCostly,
    _refuse,
    check_system,
    located,
    simulation_loc,
    spec_key,
)
from app.settings import settings

log = logging.getLogger(__name__)


def engine_seconds() -> float:
    """The engine's own budget for one derivation, inside the worker's hard limit: over it, a refusal naming it."""
    return settings().derive_seconds * 2 / 3


def build_system(user: UserSystem) -> System:
    """The engine's declaration of a checked user system, each expression built in SymPy once (gate 3) from
    what the check read, locating any refusal.  A system that was not checked (no ``parsed``) is checked here."""
    parsed = user.parsed if user.parsed is not None else check_system(user)
    namespace = SymbolTable(user.coordinates, user.parameter_names).namespace()
    positional = {k: v for k, v in namespace.items() if not k.endswith("_dot")}
    built = {}
    for loc, _, velocities in user.expressions():
        try:
            built[loc] = build(parsed[loc], namespace if velocities else positional)
        except ExpressionError as exc:
            raise _refuse(loc, exc) from None
    if (nowhere := user.never_real(built)) is not None:  # an energy that is real nowhere
        raise _refuse(*nowhere)  # type: ignore[arg-type]
    return user.system(built)


@contextmanager
def engine_budget(user: UserSystem) -> Iterator[None]:
    """The one clock of the engine's work on a user system, below the worker's hard limit.

    The engine's own bounds count work, never time (app/engine/algebra/work.py), so what it computes does not depend
    on the machine's load; this clock only stops a job that a loaded machine makes too slow, and its
    firing is a refusal that names the limit (never a poorer document, never a killed worker).
    """
    seconds = engine_seconds()
    try:
        with clock_limit(seconds):
            yield
    except OutOfTime:
        where = user.form
        raise TooCostly(
            f"{where}: the equations of motion of this system take longer to derive than the {seconds:g} s "
            "allowed (a limit of this server's engine, not a mistake in the system)",
            (where,),
        ) from None


# a small cache per worker: simulating after deriving is common
_derivations: LRUCache[UserSystem, Derivation] = LRUCache(maxsize=8)


def derive_checked(user: UserSystem) -> Derivation:
    """Derive a checked system, once per worker."""
    found = _derivations.get(user)
    if found is not None:
        return found
    where = user.form
    try:
        with engine_budget(user):
            d = derive(build_system(user))
    except DerivationError as exc:  # a singular mass matrix and the like: the form's field is at fault
        if isinstance(exc, InvalidSystem):
            raise
        raise located(exc, (where,), f"{where}: {exc}") from None
    _derivations[user] = d
    return d


def encoded(document: Document | FirstStage) -> bytes:
    """A printed document as the JSON the API sends (its model's JSON: the same bytes as the dict it replaced)."""
    return dumps(document.as_json())


def guarded(job: Callable[[], Any], encode: Callable[[Any], bytes] = dumps) -> bytes:
    """Run a job; an engine failure on user input is a refusal, never a server error.  Its result is sent
    as JSON, or as ``encode`` makes it (a step's problem: a pickle, for later jobs)."""
    try:
        return encode(job())
    except (InvalidSystem, OverCapacity, MemoryError, RecursionError):
        raise
    except DerivationError as exc:
        raise located(exc, ()) from None
    except Exception:  # a SymPy or numerics failure on an odd but allowed input
        log.exception("user system failed")
        # the details are for the log; the student gets a sentence without the engine's internal names
        raise InvalidSystem(
            "the engine could not handle this system (a limit of the engine, not a mistake in what you wrote); "
            "try writing it another way, for example without Abs or with simpler expressions"
        ) from None


def in_this_worker() -> dict[str, Any]:
    """What a job runs with in a worker process, which has no app: gates of its own (a worker runs one job at
    a time, in line, compiling first) and the process's compiled systems (``PROCESS_SCENES``, which lives as
    long as the worker), given to the service functions as ``gates`` and ``compiled``."""
    from app.service.chapter.derivations import PROCESS_SCENES
    from app.service.runtime.gates import Gates

    return {"gates": Gates(), "compiled": PROCESS_SCENES.compiled}


def derive_job(user: UserSystem) -> bytes:
    """Worker job: the derivation JSON of a user system (as for a scene), telling the page which part it is on
    (app/service/runtime/progress.py, under the same key as the derivation's cache)."""

    def run() -> Document:
        with progress.reported(spec_key(user)), engine_budget(user):
            return printed_document(derive_checked(user))

    return guarded(run, encoded)


def simulate_job(user: UserSystem, request: Any) -> bytes:
    """Worker job: the simulation JSON of a user system (as for a scene)."""
    from app.numerics.errors import SimulationError
    from app.service.simulations.simulation import simulate_derivation

    def run() -> dict[str, Any]:
        d = derive_checked(user)
        try:
            return simulate_derivation(d, request, **in_this_worker())
        except SimulationError as exc:
            raise located(exc, simulation_loc(user, exc.part)) from None

    return guarded(run)


def export_job(user: UserSystem, fmt: str, initial: dict[str, float], t_end: float | None, document: bytes) -> bytes:
    """Worker job: a user system as a notebook, script or LaTeX document (JSON-wrapped).

    ``document`` is the system's derivation JSON (from ``derive_job``, as the cache holds it), so only printing
    is left to do."""
    from app.numerics.errors import SimulationError
    from app.service.export.code import ExportError
    from app.service.export.exporting import system_export

    def run() -> dict[str, str]:
        d = derive_checked(user)
        try:
            return system_export(d, Document.model_validate_json(document), fmt, initial, t_end)
        except SimulationError as exc:
            raise located(exc, simulation_loc(user, exc.part)) from None
        except ExportError as exc:
            raise InvalidSystem(f"this system cannot be exported: {exc}") from None

    return guarded(run)


def derived_job(user: UserSystem, compute: Callable[..., dict[str, Any]], options: dict[str, Any]) -> bytes:
    """``compute(derivation, **options)`` on a user system in a pool worker (parameter values are the declared
    ones, the derivation's defaults, unless ``options`` gives others): a refusal names the part of the
    declaration it is about."""
    from app.numerics.errors import SimulationError

    def run() -> dict[str, Any]:
        d = derive_checked(user)
        try:
            return compute(d, **in_this_worker(), **options)
        except SimulationError as exc:
            raise located(exc, simulation_loc(user, exc.part)) from None

    return guarded(run)


def action_job(user: UserSystem, options: dict[str, Any]) -> bytes:
    """Worker job: the action of a user system (app.service.simulations.action; parameter values from its declaration
    unless given)."""
    from app.service.simulations.action import action_of_derivation

    return derived_job(user, action_of_derivation, options)


def relax_job(user: UserSystem, options: dict[str, Any]) -> bytes:
    """Worker job: the relaxed path of a user system (app.service.simulations.action)."""
    from app.service.simulations.action import relax_of_derivation

    return derived_job(user, relax_of_derivation, options)


def poincare_job(user: UserSystem, options: dict[str, Any]) -> bytes:
    """Worker job: the Poincaré section of a user system (app.service.simulations.poincare)."""
    from app.service.simulations.poincare import section_of_derivation

    return derived_job(user, section_of_derivation, options)


def modes_job(user: UserSystem) -> bytes:
    """Worker job: predicted against measured normal-mode frequencies of a user system (app.service.simulations.modes), from
    its derivation's own normal modes (the member its document prints)."""
    from app.service.simulations.modes import measure

    def run() -> list[dict[str, Any]]:
        return measure(derive_checked(user), **in_this_worker())

    return guarded(run)
