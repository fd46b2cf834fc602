"""Check a student's step: the scenes' and users' systems, through the user-system worker pool.

An answer is text a user typed, so checking it is user-driven SymPy work and
runs where /api/derive's does: the web process reads it once, in pure Python
(``app.engine.check.check_answer``: the step's name rules and the parser's first
two gates), refusing bad text at once; what it read (a ``Parsed``) goes to one
job in the worker pool, which builds it in SymPy without reading the text again
and judges it, under the hard time limit and the same fair share per session
(one job at a time), with identical requests answered from a cache.

* A scene's problem (the engine's expression for the step and the mistaken
  variants) is built once per process from the scene's cached derivation, in a
  thread, and sent to the worker with the answer: the worker does no derivation.
* Asking for a scene's steps (its practice page opening) queues that scene's problems to be built, one at a
  time in one background thread, in the steps' order: a student's first check of a step (the double
  pendulum's equation of θ₁ takes seconds to build, its catalogue of mistakes with it) then finds its problem
  ready, or waits for the build under way rather than starting a second one.
* A user system is derived in the worker (its per-worker cache makes repeated
  checks of one system cheap), then judged there; its problems, with the
  catalogue of mistakes generated from its derivation (app/engine/diagnose.py),
  are kept per worker too, so a class typing answers to one system generates
  them once.
* An answer to a named mistake's follow-up question (``follow_up``: the
  mistake's key) is judged against that question's truth, by the same engine.
  Its names are the question's: a scene's problem tells them in the web process;
  a declared system's only once derived, so that answer is read in the worker
  (once, too).

Refusals carry the field at fault: ``answer``, ``step`` or ``coordinate``, or
``system.…`` for the declared system of ``POST /api/check``.
"""

from __future__ import annotations

import asyncio
import queue
import threading
from collections import OrderedDict
from collections.abc import Callable, Mapping
from typing import Any

from app.engine.answer_sides import read_answer
from app.engine.check import (
    STEPS,
    CheckError,
    Problem,
    check_answer,
    follow_up_mistake,
    judge,
    judge_follow_up,
    name_kinds,
    problem,
)
from app.engine.derive import Derivation
from app.engine.errors import DerivationError
from app.engine.exercises import exercise_json
from app.engine.parse import Parsed
from app.engine.user_system import UserSystem
from app.service import derivations
from app.service.encoding import dumps
from app.service.typesetting import Typesetter
from app.service.user_checks import InvalidSystem, checked, spec_key
from app.service.user_jobs import derive_checked, guarded
from app.service.user_systems import ResultCache, UserSystems
from app.settings import Settings, settings

MAX_ANSWER_CACHE = 4096
MAX_WORKER_PROBLEMS = 64


def refusal(exc: CheckError) -> InvalidSystem:
    return InvalidSystem(str(exc), (exc.field,), exc.part, exc.start, exc.end, exc.readings)


def _in_system(exc: DerivationError) -> InvalidSystem:
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


# ---- in the worker --------------------------------------------------------------------------


def _judge(pb: Problem, answer: Parsed | str, follow_up: str | None) -> dict[str, Any]:
    return judge(pb, answer) if follow_up is None else judge_follow_up(pb, follow_up, answer)


def scene_check_job(pb: Problem, answer: Parsed, follow_up: str | None = None) -> bytes:
    """Worker job: judge an answer (or an answer to a mistake's follow-up question), as the web process read it,
    against a scene's problem."""
    return guarded(lambda: _judged(lambda: _judge(pb, answer, follow_up)))


# a worker's problems of user systems, with their catalogues of mistakes: generated once per system and step
_problems: OrderedDict[tuple, Problem] = OrderedDict()


def _user_problem(user: UserSystem, d: Derivation, step: str, coordinate: str | None) -> Problem:
    key = (user, step, coordinate)
    found = _problems.get(key)
    if found is None:
        found = _problems[key] = problem(d, step, coordinate)
        while len(_problems) > MAX_WORKER_PROBLEMS:
            _problems.popitem(last=False)
    else:
        _problems.move_to_end(key)
    return found


def _system(user: UserSystem) -> Derivation:
    try:
        return derive_checked(user)
    except (InvalidSystem, DerivationError) as exc:
        raise _in_system(exc) from None


def system_check_job(
    user: UserSystem, step: str, coordinate: str | None, answer: Parsed | str, follow_up: str | None = None
) -> bytes:
    """Worker job: derive a user system (cached per worker), then judge the answer (as the web process read it;
    a follow-up's answer as typed, read here)."""

    def run() -> dict[str, Any]:
        d = _system(user)
        return _judged(lambda: _judge(_user_problem(user, d, step, coordinate), answer, follow_up))

    return guarded(run)


def system_practice_job(user: UserSystem) -> bytes:
    """Worker job: the exercises of a user system (each step's prompt and the engine's answer)."""
    return guarded(lambda: exercise_json(_system(user)))


# ---- in the web process ---------------------------------------------------------------------


def declared(data: Mapping[str, Any]) -> UserSystem:
    """The checked user system of a request's ``system`` field; a refusal is located under ``system``."""
    try:
        return checked(data)
    except InvalidSystem as exc:
        raise _in_system(exc) from None


class Checking:
    """Scene problems and exercises (cached per process), answers through the worker pool."""

    def __init__(self, users: UserSystems, config: Settings | None = None) -> None:
        self.check_seconds = (config or settings()).check_seconds
        # the jobs share the user systems' pool, fair share and request sharing
        self.users = users
        self._problems: dict[tuple[str, str, str | None], Problem] = {}
        self._building: dict[tuple[str, str, str | None], threading.Event] = {}
        self._prepared: set[str] = set()
        self._queue: queue.SimpleQueue[tuple[str, str, str | None]] = queue.SimpleQueue()
        self._builder: threading.Thread | None = None
        self._exercises: dict[str, bytes] = {}
        self._lock = threading.Lock()
        self.answers = ResultCache(entries=MAX_ANSWER_CACHE, total_bytes=16 * 2**20)
        self.practice = ResultCache(entries=64)
        self.typesetter = Typesetter(users, self.check_seconds)  # answers typeset as they are typed

    def scene_problem(self, scene_id: str, step: str, coordinate: str | None) -> Problem:
        """The problem of a scene's step (in a thread: SymPy on the engine's own expressions)."""
        d = derivations.derivation(scene_id)  # UnknownScene for an unknown id
        key = (scene_id, step, coordinate if coordinate in d.table.names else None)
        while True:
            with self._lock:
                found = self._problems.get(key)
                building = self._building.get(key)
                mine = found is None and building is None
                if mine:
                    building = self._building[key] = threading.Event()
            if found is not None:
                return found
            assert building is not None
            if not mine:
                # another thread (the background one, or another student's check) builds it: wait for that build
                building.wait()
                continue
            try:
                found = problem(d, step, coordinate)
            except CheckError as exc:
                raise refusal(exc) from None
            finally:
                with self._lock:
                    if found is not None:
                        self._problems[key] = found
                    del self._building[key]
                building.set()
            return found

    def prepare(self, scene_id: str, exercises: list[tuple[str, str | None]]) -> None:
        """Queue the problems of a scene's steps to be built in the background (once per scene), in order."""
        with self._lock:
            if scene_id in self._prepared:
                return
            self._prepared.add(scene_id)
            for step, coordinate in exercises:
                self._queue.put((scene_id, step, coordinate))
            if self._builder is None:
                self._builder = threading.Thread(target=self._build_queued, name="check-problems", daemon=True)
                self._builder.start()

    def _build_queued(self) -> None:
        while True:
            scene_id, step, coordinate = self._queue.get()
            try:
                self.scene_problem(scene_id, step, coordinate)
            except Exception:  # noqa: BLE001 — a step that cannot be built is refused when it is checked
                pass

    def scene_exercises(self, scene_id: str) -> bytes:
        """The exercises of a scene as JSON (in a thread)."""
        if scene_id not in self._exercises:
            document = {"id": scene_id, **exercise_json(derivations.derivation(scene_id))}
            self._exercises[scene_id] = dumps(document)
            # the student will check these steps next: their problems are built meanwhile
            self.prepare(scene_id, [(e["step"], e["coordinate"]) for e in document["exercises"]])
        return self._exercises[scene_id]

    async def check_scene(
        self,
        scene_id: str,
        step: str,
        coordinate: str | None,
        answer: str,
        client: str,
        address: str,
        follow_up: str | None = None,
    ) -> bytes:
        pb = await asyncio.to_thread(self.scene_problem, scene_id, step, coordinate)
        kind = step
        if follow_up is not None:
            try:
                fu = follow_up_mistake(pb, follow_up).follow_up
            except CheckError as exc:
                raise refusal(exc) from None
            assert fu is not None
            kind = fu.kind
        try:
            # an equation typed lhs = rhs (an acceleration q_ddot = rhs) is read as the step takes it
            if follow_up is None:
                parsed = read_answer(answer, step, pb.coordinate, pb.kinds)[0]
            else:
                parsed = check_answer(answer, kind, pb.kinds)
        except CheckError as exc:
            raise refusal(exc) from None
        key = spec_key("scene", scene_id, step, pb.coordinate, answer.strip(), follow_up)
        return await self.users.run_job(
            self.answers, key, client, address, self.check_seconds, scene_check_job, pb, parsed, follow_up
        )

    async def check_system(
        self,
        user: UserSystem,
        step: str,
        coordinate: str | None,
        answer: str,
        client: str,
        address: str,
        follow_up: str | None = None,
    ) -> bytes:
        if step not in STEPS:
            raise InvalidSystem(f"step: unknown step {step[:40]!r}; the steps are: {', '.join(STEPS)}", ("step",))
        # every coordinate's momentum may turn out conserved: the worker holds what was read to the conserved
        # ones (app.engine.check_answers.parse_answer)
        kinds = name_kinds(user.coordinates, user.parameter_names, tuple(f"p_{q}" for q in user.coordinates))
        read: Parsed | str = answer
        if follow_up is None:
            # (a follow-up's names are the question's: the worker reads it against the mistake)
            try:
                read = read_answer(answer, step, coordinate, kinds)[0]
            except CheckError as exc:
                raise refusal(exc) from None
        key = spec_key(user, step, coordinate, answer.strip(), follow_up)
        return await self.users.run_job(
            self.answers,
            key,
            client,
            address,
            self.check_seconds,
            system_check_job,
            user,
            step,
            coordinate,
            read,
            follow_up,
        )

    async def system_exercises(self, user: UserSystem, client: str, address: str) -> bytes:
        key = spec_key(user, "practice")
        return await self.users.run_job(
            self.practice, key, client, address, self.check_seconds * 3, system_practice_job, user
        )
