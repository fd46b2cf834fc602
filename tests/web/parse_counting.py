"""Counting how often a request reads a user's text and builds SymPy from it (issue 30: each text read once).

``PicklingPool`` is the worker pool in the test process, so that counters see the worker's work too; a job's
arguments and result still cross a pickle boundary, as they do on their way to a worker process and back.
Its jobs run on threads named ``worker``, so a count can tell the web process's work from the worker's.

``Counted`` records, by text and by the thread it ran on, every ``ast.parse`` (the parser's one reading of
a text, app/engine/parser/read.py), every construction of SymPy from a checked tree (the parser's gate 3,
app/engine/parser/build.py) and every reading by SymPy's own parser.
"""

from __future__ import annotations

import ast
import asyncio
import pickle
import threading
from collections import Counter
from concurrent.futures import ThreadPoolExecutor

from sympy.parsing import sympy_parser

from app.engine.parser import build as parse_build

WORKER = "worker"  # the prefix of the names of the pool's threads


class PicklingPool:
    """The worker pool, in this process: a job's arguments and result are pickled as for a worker process."""

    workers = 1

    def __init__(self):
        self.executor = ThreadPoolExecutor(1, thread_name_prefix=WORKER)
        self.jobs: list[str] = []

    def submit(self, job, *args, timeout):
        sent = pickle.dumps((job, args))
        self.jobs.append(job.__name__)

        def run():
            function, arguments = pickle.loads(sent)
            return pickle.loads(pickle.dumps(function(*arguments)))

        return self.executor.submit(run)

    async def run_async(self, future, timeout):
        return await asyncio.wrap_future(future)

    def run(self, job, *args, timeout):
        return self.submit(job, *args, timeout=timeout).result()


def _where() -> str:
    return "worker" if threading.current_thread().name.startswith(WORKER) else "web"


class Counted:
    """Readings and constructions by text (``reads``, ``builds``, ``sympy_reads``) and by (text, where it ran:
    ``web`` or ``worker``) (``reads_at``, ``builds_at``)."""

    def __init__(self, monkeypatch):
        self.reads: Counter[str] = Counter()
        self.builds: Counter[str] = Counter()
        self.sympy_reads: Counter[str] = Counter()
        self.reads_at: Counter[tuple[str, str]] = Counter()
        self.builds_at: Counter[tuple[str, str]] = Counter()
        real_parse, real_init, real_parse_expr = ast.parse, parse_build.Builder.__init__, sympy_parser.parse_expr

        def reading(source, *args, **kwargs):
            self.reads[source] += 1
            self.reads_at[source, _where()] += 1
            return real_parse(source, *args, **kwargs)

        def building(builder, text, *args, **kwargs):
            self.builds[text] += 1
            self.builds_at[text, _where()] += 1
            real_init(builder, text, *args, **kwargs)

        def sympy_reading(text, *args, **kwargs):
            self.sympy_reads[text] += 1
            return real_parse_expr(text, *args, **kwargs)

        monkeypatch.setattr(ast, "parse", reading)
        monkeypatch.setattr(parse_build.Builder, "__init__", building)
        monkeypatch.setattr(sympy_parser, "parse_expr", sympy_reading)

    def clear(self) -> None:
        for counter in (self.reads, self.builds, self.sympy_reads, self.reads_at, self.builds_at):
            counter.clear()
