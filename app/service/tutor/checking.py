"""Check a student's step: the scenes' and users' systems, through the user-system worker pool.

An answer is text a user typed, so checking it is user-driven SymPy work and
runs where /api/derive's does: the web process reads it once, in pure Python
(``app.engine.tutor.check.check_answer``: the step's name rules and the parser's first
two gates), refusing bad text at once; what it read (a ``Parsed``) goes to a
job in the worker pool (app/service/tutor/check_jobs.py), which builds it in SymPy
without reading the text again and judges it, under the hard time limit and the
same fair share per session (one job at a time), with identical requests
answered from a cache.

The verdict comes first, and cheaply: a right answer (correct, or equivalent) is
decided from the truth's values at the sample points alone, so it never waits for
the catalogue of mistakes; only a wrong answer's diagnosis needs the catalogue.

* A scene's truth (the engine's expression for the step) is taken from the scene's
  cached derivation in a thread of the web process (what an answer may name comes
  from it too); its catalogue of mistakes is built in the worker pool, once per
  step, and kept on disk (a restarted server loads it). Asking for a scene's steps
  (its practice page opening) queues its catalogues to be built in the pool, one
  at a time, in the steps' order, so that a student's first wrong answer finds its
  catalogue ready. A check that needs a catalogue still being built waits for it
  at most a derivation's limit, then says the server is busy (the build goes on).
* A user system's problems (the truth alone, then with its catalogue) are each
  built by a pool job that derives the system (cached per worker) and kept here,
  as the pickles the jobs returned, so a class typing answers to one system builds
  them once.
* Every job is sent the problem it judges against as that pickle; a worker
  unpickles each problem once.
* An answer to a named mistake's follow-up question (``follow_up``: the
  mistake's key) is judged against that question's truth, by the same engine.
  Its names are the question's: a scene's problem tells them in the web process;
  a declared system's only once derived, so that answer is read in the worker
  (once, too).
* A check that runs into the hard limit is answered "the server is busy", with
  what to do (its answer is kept on the page: press Check again); nothing of it
  is cached.

Refusals carry the field at fault: ``answer``, ``step`` or ``coordinate``, or
``system.…`` for the declared system of ``POST /api/check``.
"""

from __future__ import annotations

import asyncio
import itertools
import pickle
import queue
import threading
from collections.abc import Mapping
from concurrent.futures import Future
from typing import Any

from app.engine.parser.parse import Parsed
from app.engine.parser.user_system import UserSystem
from app.engine.tutor.answer_sides import read_answer
from app.engine.tutor.check import STEPS, CheckError, Problem, check_answer, follow_up_mistake, name_kinds
from app.engine.tutor.exercises import exercise_json
from app.errors import OverCapacity, WorkerFailed
from app.limits import BUSY_RETRY_SECONDS, CATALOGUE_SECONDS
from app.service.chapter import derivations
from app.service.runtime.encoding import dumps
from app.service.tutor.check_jobs import (
    WRONG,
    check_job,
    in_system,
    kept_catalogue,
    pickled,
    refusal,
    scene_problem,
    scene_problem_job,
    system,
    system_problem_job,
    verdict_job,
)
from app.service.tutor.typesetting import Typesetter
from app.service.users.user_checks import InvalidSystem, checked, spec_key
from app.service.users.user_jobs import guarded
from app.service.users.user_systems import ResultCache, UserSystems
from app.settings import Settings, settings

MAX_ANSWER_CACHE = 4096
MAX_SYSTEM_PROBLEMS = 256  # user systems' problems kept (pickles of tens of kB each)
# what a student reads when a check runs into the hard limit: what happened, and what to do
BUSY = "the server is busy and this check took too long; your answer is kept: press Check again"

SceneKey = tuple[str, str, "str | None"]


def system_practice_job(user: UserSystem) -> bytes:
    """Worker job: the exercises of a user system (each step's prompt and the engine's answer)."""
    return guarded(lambda: exercise_json(system(user)))


def declared(data: Mapping[str, Any]) -> UserSystem:
    """The checked user system of a request's ``system`` field; a refusal is located under ``system``."""
    try:
        return checked(data)
    except InvalidSystem as exc:
        raise in_system(exc) from None


def _busy() -> OverCapacity:
    return OverCapacity(BUSY, BUSY_RETRY_SECONDS, whole_server=True)


class Checking:
    """Scene problems and exercises (cached per process), answers through the worker pool."""

    def __init__(self, users: UserSystems, config: Settings | None = None) -> None:
        config = config or settings()
        self.check_seconds = config.check_seconds
        self.derive_seconds = config.derive_seconds
        # the jobs share the user systems' pool, fair share and request sharing
        self.users = users
        self._truths: dict[SceneKey, tuple[Problem, bytes]] = {}  # a scene step's truth, and its pickle
        self._catalogued: dict[SceneKey, tuple[Problem, bytes]] = {}  # with its catalogue of mistakes
        self._builds: dict[SceneKey, Future] = {}  # catalogues being built in the pool
        self._prepared: set[str] = set()
        self._queue: queue.PriorityQueue[tuple[int, int, SceneKey]] = queue.PriorityQueue()
        self._order = itertools.count()
        self._builder: threading.Thread | None = None
        self._exercises: dict[str, bytes] = {}
        self._lock = threading.Lock()
        self.answers = ResultCache(entries=MAX_ANSWER_CACHE, total_bytes=16 * 2**20)
        self.problems = ResultCache(entries=MAX_SYSTEM_PROBLEMS, total_bytes=64 * 2**20)  # user systems'
        self.practice = ResultCache(entries=64)
        self.typesetter = Typesetter(users, self.check_seconds)  # answers typeset as they are typed

    # ---- a scene's problems ---------------------------------------------------------------------

    def scene_truth(self, scene_id: str, step: str, coordinate: str | None) -> tuple[Problem, bytes]:
        """A scene step's problem without its catalogue, and its pickle (in a thread: the derivation's own
        expression evaluated at the sample points)."""
        d = derivations.derivation(scene_id)  # UnknownScene for an unknown id
        # (a position's component is named in the coordinate field too: x2, the block's x)
        key = (scene_id, step, coordinate if coordinate in d.table.names or step == "position" else None)
        found = self._truths.get(key)
        if found is None:
            try:
                pb = scene_problem(scene_id, step, coordinate, catalogue=False)
            except CheckError as exc:
                raise refusal(exc) from None
            found = self._truths[key] = (pb, pickled(pb))
        return found

    def catalogue_build(self, key: SceneKey, ahead: bool = False) -> Future:
        """The build of a scene step's catalogue, as a future of the problem and its pickle: done, under way, or
        queued here (a check's first, before the steps a practice page queued ``ahead``)."""
        with self._lock:
            done = self._catalogued.get(key)
            building = self._builds.get(key)
            if done is None and (building is None or not ahead):
                # a check's wait goes before the steps queued ahead (the builder skips a key already built)
                if building is None:
                    building = self._builds[key] = Future()
                self._queue.put((1 if ahead else 0, next(self._order), key))
                if self._builder is None:
                    self._builder = threading.Thread(target=self._build_queued, name="check-catalogues", daemon=True)
                    self._builder.start()
        if done is not None:
            ready: Future = Future()
            ready.set_result(done)
            return ready
        assert building is not None
        return building

    def prepare(self, scene_id: str, exercises: list[tuple[str, str | None]]) -> None:
        """Queue the catalogues of a scene's steps to be built (once per scene), in order."""
        with self._lock:
            if scene_id in self._prepared:
                return
            self._prepared.add(scene_id)
        for step, coordinate in exercises:
            self.catalogue_build((scene_id, step, coordinate), ahead=True)

    def _build_queued(self) -> None:
        """Build the queued catalogues in the pool one at a time: the other workers stay free for answers."""
        while True:
            _, _, key = self._queue.get()
            with self._lock:
                building = self._builds.get(key)
            if building is None or building.done():
                continue
            found = failure = None
            try:
                # built before (by this version, here or at set-up): from the disk, else in the pool
                found = kept_catalogue(*key)
                if found is None:
                    blob = self.users.pool.run(scene_problem_job, *key, timeout=CATALOGUE_SECONDS)
                    found = (pickle.loads(blob), blob)
            except BaseException as exc:  # noqa: BLE001 — told to whoever waits; the next check queues it again
                failure = exc
            with self._lock:
                if found is not None:
                    self._catalogued[key] = found
                self._builds.pop(key, None)
            if found is not None:
                building.set_result(found)
            else:
                building.set_exception(failure or RuntimeError("not built"))

    def scene_exercises(self, scene_id: str) -> bytes:
        """The exercises of a scene as JSON (in a thread)."""
        if scene_id not in self._exercises:
            document = {"id": scene_id, **exercise_json(derivations.derivation(scene_id))}
            self._exercises[scene_id] = dumps(document)
            # the student will check these steps next: their catalogues are built meanwhile
            self.prepare(scene_id, [(e["step"], e["coordinate"]) for e in document["exercises"]])
        return self._exercises[scene_id]

    async def _catalogued_scene(self, key: SceneKey) -> tuple[Problem, bytes]:
        """A scene step's problem with its catalogue, waiting for its build at most a derivation's limit (building
        a step's problem is derivation work, as for a typed system's)."""
        found = self._catalogued.get(key)
        if found is not None:
            return found
        building = self.catalogue_build(key)
        try:
            return await asyncio.wait_for(asyncio.shield(asyncio.wrap_future(building)), self.derive_seconds)
        except TimeoutError:
            raise _busy() from None
        except WorkerFailed as exc:
            if exc.kind == "timeout":
                raise _busy() from None
            raise

    async def _job(self, key: str, client: str, address: str, job, *args: Any) -> bytes:
        """An answer's job (cached by ``key``), under the check's hard limit; running into it is 'busy'."""
        try:
            return await self.users.run_job(self.answers, key, client, address, self.check_seconds, job, *args)
        except WorkerFailed as exc:
            if exc.kind == "timeout":
                raise _busy() from None
            raise

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
        truth, truth_blob = await asyncio.to_thread(self.scene_truth, scene_id, step, coordinate)
        key = (scene_id, step, truth.coordinate)
        name = spec_key("scene-problem", *key)
        kind = step
        if follow_up is not None:
            pb = (await self._catalogued_scene(key))[0]
            try:
                fu = follow_up_mistake(pb, follow_up).follow_up
            except CheckError as exc:
                raise refusal(exc) from None
            assert fu is not None
            kind = fu.kind
        try:
            # an equation typed lhs = rhs (an acceleration q_ddot = rhs) is read as the step takes it
            if follow_up is None:
                parsed = read_answer(answer, step, truth.coordinate, truth.kinds, truth.absent)[0]
            else:
                parsed = check_answer(answer, kind, truth.kinds)
        except CheckError as exc:
            raise refusal(exc) from None
        answer_key = spec_key("scene", scene_id, step, truth.coordinate, answer.strip(), follow_up)
        cached = self.answers.get(answer_key)
        if cached is not None:
            return cached
        if follow_up is None and key not in self._catalogued:
            # the verdict first, from the truth alone, while the catalogue is built (or loaded) in the pool
            self.catalogue_build(key)
            first = await self._job(
                "first:" + answer_key, client, address, verdict_job, name + ":truth", truth_blob, parsed
            )
            if first != WRONG:
                return first
        catalogued = await self._catalogued_scene(key)
        return await self._job(answer_key, client, address, check_job, name, catalogued[1], parsed, follow_up)

    # ---- a user system's problems ------------------------------------------------------------------

    async def _system_problem(
        self, user: UserSystem, step: str, coordinate: str | None, catalogue: bool, client: str, address: str
    ) -> tuple[str, bytes]:
        """The key and pickle of a user system's step problem, built by a pool job (derive, then the problem)."""
        key = spec_key(user, "problem", step, coordinate, catalogue)
        try:
            blob = await self.users.run_job(
                self.problems, key, client, address, self.derive_seconds, system_problem_job, user, step, coordinate,
                catalogue,
            )  # fmt: skip
        except WorkerFailed as exc:
            if exc.kind == "timeout":
                raise _busy() from None
            raise
        return key, blob

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
        # ones (app.engine.tutor.check_answers.parse_answer)
        kinds = name_kinds(user.coordinates, user.parameter_names, tuple(f"p_{q}" for q in user.coordinates))
        read: Parsed | str = answer
        if follow_up is None:
            # (a follow-up's names are the question's: the worker reads it against the mistake)
            try:
                read = read_answer(answer, step, coordinate, kinds)[0]
            except CheckError as exc:
                raise refusal(exc) from None
        answer_key = spec_key(user, step, coordinate, answer.strip(), follow_up)
        cached = self.answers.get(answer_key)
        if cached is not None:
            return cached
        if follow_up is None and self.problems.get(spec_key(user, "problem", step, coordinate, True)) is None:
            # the verdict first, from the truth alone: a right answer never waits for the catalogue
            name, blob = await self._system_problem(user, step, coordinate, False, client, address)
            first = await self._job("first:" + answer_key, client, address, verdict_job, name, blob, read)
            if first != WRONG:
                return first
        name, blob = await self._system_problem(user, step, coordinate, True, client, address)
        return await self._job(answer_key, client, address, check_job, name, blob, read, follow_up)

    async def system_exercises(self, user: UserSystem, client: str, address: str) -> bytes:
        key = spec_key(user, "practice")
        return await self.users.run_job(
            self.practice, key, client, address, self.check_seconds * 3, system_practice_job, user
        )
