"""The CPU time of one check, in the worker's code path, before (another source tree, main's) and after (this one).

Each tree is measured in a process of its own (``PYTHONPATH`` set to it, its caches read from a copy so nothing
is written into it): the double pendulum's ten practice steps (bench_classroom's hall), each step's problem
built as ``app.service.tutor.check_jobs`` builds it and sent as its pickle, and every answer read as the web process
reads it (``read_answer``), then judged as a worker does (``app.service.runtime.worker.execute`` of ``check_job``: the
SymPy cache emptied first).  CPU seconds (``time.process_time``) per check, by kind of answer:

* the hall's answers: the engine's step and the step doubled (``2*(…)``), each made a distinct text with
  ``+ 0*k`` as bench_classroom makes them, ``--checks`` of each kind spread over the steps;
* distinct expressions: the same, with ``+ k*(sin(θ₁)² + cos(θ₁)² − 1)`` instead (a zero SymPy does not
  see, so every answer is another expression, judged from scratch).

The ratio before ÷ after is what is reported (a ratio, not a timed goal: both run in the same minute, on the
same machine).  ``--profile N`` prints each tree's top N functions (cumulative) for the hall's doubled answers
(a worker that judged none of them yet).

``--verdicts`` compares instead what both trees answer, byte for byte: every scene's practice steps, each with
the engine's step, twice it, it plus one and its first generated mistake, and the tutor's corpus of realistic
slips and correct unusual forms (tests/engine/slip_corpus.py), each sent as typed and again ``+ 0*7``, through
the worker's path (one worker: what it judged before is remembered).

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_check_cpu --before /work/main
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENE = "double-pendulum"
STEPS = 10
KINDS = ("engine's, + 0*k", "doubled, + 0*k", "engine's, distinct", "doubled, distinct")


def answer(base: str, doubled: bool, distinct: bool, k: int) -> str:
    """An answer as a student of the hall sends it: the step (or twice it) plus a zero that makes it unique."""
    zero = f"{k}*(sin(theta1)**2 + cos(theta1)**2 - 1)" if distinct else f"0*{k}"
    return f"{'2*(' + base + ')' if doubled else base} + {zero}"


def measure(checks: int, profile: int) -> dict:
    """In the tree on ``sys.path``: CPU milliseconds per check of each kind (and a profile, as text)."""
    import cProfile
    import io
    import pstats

    from app.engine.tutor.answer_sides import read_answer
    from app.engine.tutor.exercises import exercise_json
    from app.service.chapter import derivations
    from app.service.runtime.worker import execute
    from app.service.tutor import check_jobs

    steps = []
    for e in exercise_json(derivations.derivation(SCENE))["exercises"][:STEPS]:
        pb = check_jobs.scene_problem(SCENE, e["step"], e["coordinate"])
        steps.append((f"scene-problem:{SCENE}:{e['step']}:{e['coordinate']}", check_jobs.pickled(pb), pb, e))

    def jobs(doubled: bool, distinct: bool, first: int) -> list[tuple]:
        out = []
        for n in range(checks):
            key, blob, pb, e = steps[n % len(steps)]
            text = answer(e["answer"]["sympy"], doubled, distinct, first + n)
            out.append((key, blob, read_answer(text, pb.step, pb.coordinate, pb.kinds)[0]))
        return out

    # a worker that has judged each step once (its problems unpickled, the truths' values known)
    for key, blob, parsed in jobs(False, True, 10**6)[: len(steps)]:
        execute(check_jobs.check_job, key, blob, parsed)
    result: dict = {"ms": {}}
    for kind in KINDS:
        todo = jobs(kind.startswith("doubled"), kind.endswith("distinct"), 1)
        started = time.process_time()
        for key, blob, parsed in todo:
            execute(check_jobs.check_job, key, blob, parsed)
        result["ms"][kind] = 1000 * (time.process_time() - started) / len(todo)
    if profile:
        check_jobs.__dict__.get("_verdicts", {}).clear()  # (after: nothing remembered of the runs above)
        todo = jobs(True, False, 10**7)
        profiler = cProfile.Profile()
        profiler.enable()
        for key, blob, parsed in todo:
            execute(check_jobs.check_job, key, blob, parsed)
        profiler.disable()
        text = io.StringIO()
        pstats.Stats(profiler, stream=text).sort_stats("cumulative").print_stats(profile)
        result["profile"] = text.getvalue()
    return result


def decided(found: bytes) -> bytes:
    """What a check decides: the verdict, its message and hint, the named mistake, what else is right and the
    follow-up question (without the forms of the difference and the piece shown for the reveal, which depend on
    the SymPy cache a worker's earlier jobs left: on main, one text judged twice by one worker may show the
    same difference in two forms)."""
    import orjson

    v = orjson.loads(found)
    keys = ("verdict", "message", "hint", "partial", "follow_up")
    return orjson.dumps([v.get(k) for k in keys] + [(v.get("mistake") or {}).get("key")])


def verdicts() -> dict[str, list[str]]:
    """In the tree on ``sys.path``: every answer of ``--verdicts``, with the SHA-256 of what the worker's path
    answers (the verdict's bytes, or the refusal's words), whole and of what it decides."""
    import hashlib

    from app.engine.tutor.answer_sides import read_answer
    from app.engine.tutor.check import CheckError
    from app.engine.tutor.exercises import exercise_json
    from app.scenes import SCENES
    from app.service.chapter import derivations
    from app.service.runtime.worker import execute
    from app.service.tutor import check_jobs
    from tests.engine.slip_corpus import CORRECT, SLIPS

    out = {}
    for scene in SCENES:
        asked: list[tuple[str, str | None, str]] = []
        for e in exercise_json(derivations.derivation(scene))["exercises"]:
            truth = e["answer"]["sympy"]
            asked += [(e["step"], e["coordinate"], t) for t in (truth, f"2*({truth})", f"{truth} + 1")]
            named = [m for m, _, _ in check_jobs.scene_problem(scene, e["step"], e["coordinate"]).mistakes]
            if named and len(str(named[0].expr)) < 2000:
                asked.append((e["step"], e["coordinate"], str(named[0].expr)))
        asked += [
            (step, coordinate, text) for system, step, coordinate, text, *_ in [*SLIPS, *CORRECT] if system == scene
        ]
        for step, coordinate, text in asked:
            pb = check_jobs.scene_problem(scene, step, coordinate)
            key = f"scene-problem:{scene}:{step}:{pb.coordinate}"
            for typed in (text, f"{text} + 0*7"):
                try:
                    parsed = read_answer(typed, step, pb.coordinate, pb.kinds)[0]
                    found = execute(check_jobs.check_job, key, check_jobs.pickled(pb), parsed)
                    parts = (found, decided(found))
                except (CheckError, ValueError) as exc:  # a refusal (the service's is a ValueError)
                    parts = (f"{type(exc).__name__}: {exc}".encode(),) * 2
                out[f"{scene} {step} {coordinate} {typed}"] = [hashlib.sha256(p).hexdigest() for p in parts]
    return out


def run_tree(tree: Path, checks: int, profile: int, mode: str = "--measure") -> dict:
    """``measure`` in a process of its own with ``tree`` first on its path, its cache a copy."""
    with tempfile.TemporaryDirectory() as cache:
        if (tree / ".cache").is_dir():
            shutil.copytree(tree / ".cache", cache, dirs_exist_ok=True)
        # one hash seed for both trees: SymPy's work (so what a bound of work lets through) follows hash order
        env = {**os.environ, "PYTHONPATH": str(tree), "LAGRANGE_CACHE_DIR": cache, "PYTHONDONTWRITEBYTECODE": "1",
               "PYTHONHASHSEED": "0"}  # fmt: skip
        done = subprocess.run(
            [sys.executable, __file__, mode, "--checks", str(checks), "--profile", str(profile)],
            env=env, cwd=cache, capture_output=True, text=True, check=True,
        )  # fmt: skip
    return json.loads(done.stdout.splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--before", type=Path, default=Path("/work/main"), help="the source tree measured before (main)"
    )
    parser.add_argument("--checks", type=int, default=200, help="checks of each kind")
    parser.add_argument("--profile", type=int, default=0, metavar="N", help="print each tree's top N functions")
    parser.add_argument("--verdicts", action="store_true", help="compare both trees' verdicts instead")
    parser.add_argument("--measure", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--judge-all", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.measure:
        print(json.dumps(measure(args.checks, args.profile)))
        return
    if args.judge_all:
        print(json.dumps(verdicts()))
        return
    if args.verdicts:
        before = run_tree(args.before.resolve(), 0, 0, "--judge-all")
        after = run_tree(ROOT, 0, 0, "--judge-all")
        # (an exercise's answer is asked as the tree prints it: a display form, which may differ between trees)
        answers = sorted(before.keys() & after.keys())
        bytewise = [k for k in answers if before[k] != after[k]]
        differ = [k for k in answers if before[k][1] != after[k][1]]
        print(
            f"{len(answers)} answers judged by both trees ({len(before.keys() ^ after.keys())} asked of one only, "
            f"printed otherwise by its exercise): {len(answers) - len(differ)} decided alike (verdict, message, hint, "
            f"mistake, what else is right, follow-up), {len(differ)} not; {len(answers) - len(bytewise)} alike byte "
            f"for byte; before: {args.before}, after: {ROOT}"
        )
        for k in bytewise:
            print(f"  {'DECIDED OTHERWISE' if k in differ else 'shown otherwise'}: {k[:160]}")
        sys.exit(1 if differ else 0)
    load = " ".join(Path("/proc/loadavg").read_text().split()[:3])
    before = run_tree(args.before.resolve(), args.checks, args.profile)
    after = run_tree(ROOT, args.checks, args.profile)
    print(f"CPU per check in the worker's path, {args.checks} checks of each kind over the double pendulum's {STEPS} "
          f"steps; before: {args.before}, after: {ROOT}; load average {load} before, "
          f"{' '.join(Path('/proc/loadavg').read_text().split()[:3])} after")  # fmt: skip
    for kind in KINDS:
        b, a = before["ms"][kind], after["ms"][kind]
        print(f"  {kind:>20}: before {b:6.1f} ms, after {a:6.1f} ms, before ÷ after {b / a:5.2f}")
    # the hall's mix: two answers in three the engine's step, one in three doubled
    mix = {
        t: (2 * r["ms"]["engine's, + 0*k"] + r["ms"]["doubled, + 0*k"]) / 3 for t, r in (("b", before), ("a", after))
    }
    print(f"  the hall's mix (2 : 1): before {mix['b']:.1f} ms, after {mix['a']:.1f} ms, "
          f"before ÷ after {mix['b'] / mix['a']:.2f}")  # fmt: skip
    for name, found in (("before", before), ("after", after)):
        if "profile" in found:
            print(f"---- {name}: the hall's doubled answers, top {args.profile} functions by cumulative time")
            print(found["profile"])


if __name__ == "__main__":
    main()
