"""Typeset a student's answer as it is typed: the one grammar (app/engine/parser/parse.py), printed by the engine.

The practice boxes of the pages show, while the student types, what the checker will read: the text
goes through the same gates as an answer sent to POST /api/check, in the same order, so a text the
preview refuses is refused by the checker with the same words, and one it typesets is one the checker
reads (the browser has no grammar of its own):

* in the web process, pure Python: the step's name rules and the parser's first two gates
  (``app.engine.tutor.check.check_answer``), answered at once with the checker's message; this is the one
  reading of the text;
* in the worker pool, under the checker's hard time limit and fair share: gate 3 (what was read built
  into SymPy, refused when undefined or nowhere real), then the LaTeX of the text as typed (its structure
  kept, never evaluated: app/engine/tutor/typed_latex.py),
  names written as ``app.engine.display.names`` writes them.

What an answer may name depends on the step and the system: a scene's names come from its cached
derivation (a thread, once per scene), a declared system's from its coordinates and parameters (as
POST /api/check takes them before the worker derives it).  Typeset answers are kept in a small LRU
keyed by the text and its context, so retyping or undoing answers without a job.
"""

from __future__ import annotations

import asyncio
import threading
from typing import TYPE_CHECKING, Any

import sympy as sp

from app.engine.parser.parse import ExpressionError, Parsed, build
from app.engine.parser.reality import real_somewhere
from app.engine.tutor.answer_sides import read_answer
from app.engine.tutor.check import CheckError, answer_error, conserved_momenta, name_kinds
from app.engine.tutor.mistakes import absent_names
from app.engine.tutor.typed_latex import typed_equation, typed_latex
from app.service.chapter import derivations
from app.service.users.user_checks import InvalidSystem, spec_key
from app.service.users.user_jobs import guarded
from app.service.users.user_systems import ResultCache

if TYPE_CHECKING:  # the service that runs the jobs (imported for its type only)
    from app.service.users.user_systems import UserSystems

MAX_TYPESET = 2048  # typeset answers kept (each a few hundred bytes of LaTeX)


def _refusal(exc: CheckError) -> InvalidSystem:
    """The checker's refusal, word for word, located at the request's ``text``."""
    return InvalidSystem(str(exc), ("text",), exc.part, exc.start, exc.end, exc.readings)


def system_kinds(coordinates: tuple[str, ...], parameters: tuple[str, ...]) -> dict[str, str]:
    """The names a declared system's answers may mention, as POST /api/check reads them before deriving:
    every coordinate's momentum may turn out conserved."""
    return name_kinds(coordinates, parameters, tuple(f"p_{q}" for q in coordinates))


def scene_kinds(scene_id: str) -> dict[str, str]:
    """The names a scene's answers may mention (its derivation's, with its conserved momenta); in a thread."""
    d = derivations.derivation(scene_id)  # UnknownScene for an unknown id
    return name_kinds(d.table.names, d.table.parameter_names, tuple(p.name for p in conserved_momenta(d)))


def scene_absent(scene_id: str) -> dict[str, str]:
    """The names a scene's student may expect that it has not, with why (as the checker's refusal says them)."""
    return absent_names(derivations.derivation(scene_id))


def typeset_job(parsed: Parsed, equation: bool = False) -> bytes:
    """Worker job: the answer the web process read (``check_answer``) through gate 3, as the checker builds
    it, then its LaTeX."""

    def run() -> dict[str, Any]:
        # every name the step allows is a real symbol, as in the derivation's table (the checker's namespace)
        symbols = {name: sp.Symbol(name, real=True) for name in sorted(parsed.names)}
        try:
            real_somewhere(parsed.text, build(parsed, symbols))
        except ExpressionError as exc:
            raise _refusal(answer_error(exc)) from None
        # printed as typed, never as SymPy rewrote it: the student checks their own typing
        if equation:  # typed as lhs = rhs: printed so, whole
            return {"latex": typed_equation(parsed), "equation": True}
        return {"latex": typed_latex(parsed)}

    return guarded(run)


class Typesetter:
    """Answers typeset through the users' pool (its fair share and limits), with an LRU of results."""

    def __init__(self, users: UserSystems, seconds: float) -> None:
        self.users = users
        self.seconds = seconds
        self.results = ResultCache(entries=MAX_TYPESET, total_bytes=4 * 2**20)
        self._scenes: dict[str, tuple[dict[str, str], dict[str, str]]] = {}
        self._lock = threading.Lock()

    def _scene_kinds(self, scene_id: str) -> tuple[dict[str, str], dict[str, str]]:
        """A scene's names and kinds, and the names it has not with why."""
        with self._lock:
            found = self._scenes.get(scene_id)
        if found is None:
            found = (scene_kinds(scene_id), scene_absent(scene_id))
            with self._lock:
                self._scenes[scene_id] = found
        return found

    async def typeset(
        self,
        text: str,
        step: str,
        scene: str | None,
        names: tuple[tuple[str, ...], tuple[str, ...]],
        client: str,
        address: str,
        coordinate: str | None = None,
    ) -> bytes:
        """``{"latex"}`` of the answer, or InvalidSystem with the checker's message and the offending part."""
        kinds, absent = (
            await asyncio.to_thread(self._scene_kinds, scene) if scene is not None else (system_kinds(*names), {})
        )
        # a position step's coordinate is a Cartesian component (x, z1), not a generalized coordinate
        if coordinate is not None and step != "position" and kinds.get(coordinate) != "position":
            coordinates = ", ".join(n for n, k in kinds.items() if k == "position" and n != "t")
            raise InvalidSystem(f"coordinate: {coordinate!r} is not a coordinate here; the coordinates are: {coordinates}",
                                ("coordinate",), coordinate)  # fmt: skip
        try:
            parsed, equation = read_answer(text, step, coordinate, kinds, absent)
        except CheckError as exc:
            raise _refusal(exc) from None
        key = spec_key("typeset", step, kinds, text.strip())
        return await self.users.run_job(self.results, key, client, address, self.seconds, typeset_job, parsed, equation)
