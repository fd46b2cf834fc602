"""The checker's jobs in the worker pool: a step's problem built once, answers judged against it.

A step's *problem* (app/engine/tutor/check_problem.py) comes in two sizes:

* the truth alone (``catalogue=False``): the engine's expression and its values at the sample points, all a
  right answer needs (``verdict``: correct or equivalent, decided numerically, before any symbolic work);
* with its catalogue of mistakes: every mistake generated from the system, evaluated at the same points, the
  costly part (a few seconds for the double pendulum's accelerations on an idle machine), which a wrong
  answer's diagnosis needs.

Each is built once per system and step, in the pool, and sent to later jobs as the pickle it was returned
as; a worker keeps the problems it has unpickled, by the key the web process gives them, so an answer's job
costs its own judging only; and the verdicts it gave, by problem and built answer, so an answer a class types
in many spellings (``m*g*l``, ``g*m*l``) costs its judging once and its reading each time.  A scene's catalogue is also kept on disk, keyed by the engine's and scenes'
source, so a restarted server builds none of them again.
"""

from __future__ import annotations

import pickle
from collections import OrderedDict
from collections.abc import Callable
from typing import Any

from app.engine.derivation.derive import Derivation
from app.engine.errors import DerivationError
from app.engine.parser.parse import Parsed
from app.engine.parser.user_system import UserSystem
from app.engine.tutor.check import (
    CheckError,
    Problem,
    cancelling_terms,
    follow_up_answer,
    follow_up_mistake,
    follow_up_of,
    judge_of,
    parse_answer,
    problem,
    verdict_of,
)
from app.service.chapter import derivations
from app.service.runtime.cache import cache_dir, write_atomically
from app.service.runtime.encoding import dumps
from app.service.users.user_checks import InvalidSystem
from app.service.users.user_jobs import derive_checked, guarded

# the problems a worker has unpickled, by key: every step of a class's scene fits
MAX_WORKER_PROBLEMS = 64
# the verdicts a worker remembers, by problem and built answer (a few kB each; a worker retires after
# app.service.runtime.worker.MAX_TASKS jobs in any case)
MAX_WORKER_VERDICTS = 1024
WRONG = b""  # the first verdict's answer for a wrong answer: its diagnosis needs the catalogue


def pickled(value: Any) -> bytes:
    return pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL)


def refusal(exc: CheckError) -> InvalidSystem:
    """A refused answer (or step, or coordinate), located at its field."""
    return InvalidSystem(str(exc), (exc.field,), exc.part, exc.start, exc.end, exc.readings)


def in_system(exc: DerivationError) -> InvalidSystem:
    """A refusal of the declared system, located under ``system``."""
    loc = exc.loc or ()
    kind = type(exc) if isinstance(exc, InvalidSystem) else InvalidSystem
    return kind(
        f"system.{exc}" if loc else f"system: {exc}",
        ("system", *loc),
        exc.part,
        getattr(exc, "start", None),
        getattr(exc, "end", None),
        getattr(exc, "readings", ()),
    )


def _judged(work: Callable[[], Any]) -> Any:
    try:
        return work()
    except CheckError as exc:
        raise refusal(exc) from None


# ---- building a step's problem ----------------------------------------------------------------


def catalogue_path(scene_id: str, step: str, coordinate: str | None) -> Any:
    """Where a scene step's problem with its catalogue is kept (keyed as the scenes' derivations are)."""
    fingerprint = derivations.PROCESS_SCENES.documents.fingerprint
    return cache_dir() / "check-problems" / f"{scene_id}-{step}-{coordinate or '_'}-{fingerprint}.pickle"


def kept_catalogue(scene_id: str, step: str, coordinate: str | None) -> tuple[Problem, bytes] | None:
    """A scene step's problem with its catalogue and its pickle, as built before by this version, or None."""
    try:
        blob = catalogue_path(scene_id, step, coordinate).read_bytes()
        return pickle.loads(blob), blob
    except Exception:  # noqa: BLE001 — absent, or written by another version of SymPy: built again
        return None


def scene_problem(scene_id: str, step: str, coordinate: str | None, catalogue: bool = True) -> Problem:
    """A scene step's problem (the catalogue from the disk when it was built before, else built and kept)."""
    d = derivations.derivation(scene_id)
    if not catalogue:
        return problem(d, step, coordinate, mistakes=False)
    kept = kept_catalogue(scene_id, step, coordinate)
    if kept is not None:
        return kept[0]
    found = problem(d, step, coordinate)
    write_atomically(catalogue_path(scene_id, step, coordinate), pickled(found))
    return found


def warm_all() -> None:
    """Every scene step's catalogue, built and kept on disk: at set-up and image build (app.service.warm)."""
    from app.engine.tutor.check import exercises
    from app.scenes import SCENES

    for scene_id in SCENES:
        for step, coordinate in exercises(derivations.derivation(scene_id)):
            scene_problem(scene_id, step, coordinate)


def scene_problem_job(scene_id: str, step: str, coordinate: str | None) -> bytes:
    """Worker job: a scene step's problem with its catalogue, as a pickle."""
    return guarded(lambda: _judged(lambda: scene_problem(scene_id, step, coordinate)), pickled)


def system(user: UserSystem) -> Derivation:
    """A user system's derivation (once per worker); a refusal located under ``system``."""
    try:
        return derive_checked(user)
    except (InvalidSystem, DerivationError) as exc:
        raise in_system(exc) from None


def system_problem_job(user: UserSystem, step: str, coordinate: str | None, catalogue: bool) -> bytes:
    """Worker job: a user system's step problem (derived once per worker), with its catalogue or without, as a
    pickle."""
    return guarded(lambda: _judged(lambda: problem(system(user), step, coordinate, mistakes=catalogue)), pickled)


# ---- judging an answer --------------------------------------------------------------------------

_problems: OrderedDict[str, Problem] = OrderedDict()


def loaded(key: str, blob: bytes) -> Problem:
    """The problem sent as ``blob``, unpickled once per worker (by the web process's ``key`` for it)."""
    found = _problems.get(key)
    if found is None:
        found = _problems[key] = pickle.loads(blob)
        while len(_problems) > MAX_WORKER_PROBLEMS:
            _problems.popitem(last=False)
    else:
        _problems.move_to_end(key)
    return found


_verdicts: OrderedDict[tuple, bytes] = OrderedDict()


def remembered(key: tuple, judging: Callable[[], bytes]) -> bytes:
    """The encoded verdict under ``key`` (a problem's key, the job's kind and the built answer), judged once
    per worker.

    A verdict is a function of the problem and the answer as built (``app.engine.tutor.check.judge_of``), never of
    how it was typed: ``m*g*l`` and ``g*m*l``, or an answer and the same answer ``+ 0*k``, are one SymPy
    expression (equal and of one hash), so a class typing one answer in many spellings is judged once.  A
    refusal is never kept (each text is read, and refused in its own words, by its own job)."""
    found = _verdicts.get(key)
    if found is None:
        found = _verdicts[key] = judging()
        while len(_verdicts) > MAX_WORKER_VERDICTS:
            _verdicts.popitem(last=False)
    else:
        _verdicts.move_to_end(key)
    return found


def verdict_job(key: str, blob: bytes, answer: Parsed) -> bytes:
    """Worker job: the verdict on a right answer, from the truth alone; ``WRONG`` for a wrong one."""

    def run() -> bytes:
        pb = loaded(key, blob)
        built = parse_answer(pb, answer)

        def judging() -> bytes:
            found = verdict_of(pb, built)
            return WRONG if found is None else dumps(found)

        return remembered((key, "verdict", built), judging)

    return guarded(lambda: _judged(run), bytes)


def check_job(key: str, blob: bytes, answer: Parsed | str, follow_up: str | None = None) -> bytes:
    """Worker job: judge an answer (or an answer to a mistake's follow-up question, read here when it is text)
    against a step's problem with its catalogue."""

    def run() -> bytes:
        pb = loaded(key, blob)
        if follow_up is None:
            built = parse_answer(pb, answer)
            # two typed terms that cancel are gone from the built answer: they are part of what is judged
            cancelling = cancelling_terms(pb, answer)
            return remembered((key, "judge", built, cancelling), lambda: dumps(judge_of(pb, built, cancelling)))
        mistake = follow_up_mistake(pb, follow_up)
        built = follow_up_answer(pb, mistake, answer)
        return remembered((key, "follow-up", follow_up, built), lambda: dumps(follow_up_of(pb, mistake, built)))

    return guarded(lambda: _judged(run), bytes)
