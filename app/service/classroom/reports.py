"""What an instructor reads of a class: the summary per assignment and step, each student's progress, the CSV
export of every attempt.  (The gradebook, scores per student and assignment, is ``grades``.)

Counted in the database (GROUP BY) in one statement, so a dashboard polling
every few seconds reads a few rows per student and step, not every attempt,
and every figure of one answer comes from the same state of the database.  A step is done for a student
once one of their answers to it was ``correct`` or ``equivalent``; the
``correct`` count of a step counts such answers, ``incorrect`` the others.
"""

from __future__ import annotations

import csv
import io
import json
from collections import defaultdict
from datetime import UTC, datetime
from typing import Any

from sqlalchemy import case, func, literal, null, select, union_all

from app.engine.tutor.check_problem import step_heading
from app.engine.tutor.mistake_teacher import for_teacher
from app.scenes import SCENES
from app.service.classroom.database import Database
from app.service.classroom.models import AttemptRow, HintRow, StudentRow
from app.service.classroom.store import DONE, NOT_READ

Key = tuple[int | None, str, str, str | None]  # (assignment's id, item, step, coordinate)
CSV_COLUMNS = ("time (UTC)", "student", "assignment", "item", "step", "verdict", "after shown", "late", "counted",
               "mistake", "answer")
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
# a verdict in a teacher's words: "equivalent" is right (the grade counts it), in another form than the book's
# an answer the checker could not read, in a teacher's words: the one home of the phrase (the dashboard's too)
NOT_READ_WORDS = "could not be read"
VERDICT_WORDS = {"correct": "right", "equivalent": "right, in an equivalent form", "incorrect": "wrong",
                 NOT_READ: NOT_READ_WORDS}
TIME_FORMAT = "%Y-%m-%d %H:%M:%S"  # to the second, in UTC (the column says so)
BOM = "\ufeff"  # a spreadsheet opened by a double click reads the file as UTF-8 (θ̈, ≈, ₁) only with it


SHOWN = "shown"  # a row of the tallies that is a step shown ("Show this step"), not an answer


def on_own(right_at: datetime | None, shown_at: datetime | None, due: Any = None) -> bool:
    """A step done on one's own: answered right, not shown before the first right answer, and that answer not
    after the due time (``due``: None for an undated assignment).  The one rule the dashboard's "done", the
    gradebook's score and the student's own page ("2 of 8 steps done") share."""
    return right_at is not None and (shown_at is None or shown_at > right_at) and not is_late(right_at, due)


def late_only(right_at: datetime | None, shown_at: datetime | None, due: Any) -> bool:
    """Right on one's own, but only after the due time: recorded, not counted (neither done nor stuck)."""
    return right_at is not None and on_own(right_at, shown_at) and is_late(right_at, due)


def due_utc(when: Any) -> datetime | None:
    """A due time as a naive UTC datetime (stored naive; ISO text read back from a snapshot); None when undated."""
    if when is None:
        return None
    found = datetime.fromisoformat(when.rstrip("Z")) if isinstance(when, str) else when
    return found.astimezone(UTC).replace(tzinfo=None) if found.tzinfo else found


def is_late(at: datetime, due: Any) -> bool:
    """An answer is late when it came after its assignment's due time (an undated assignment is never late)."""
    limit = due_utc(due)
    return limit is not None and at > limit


def assigned_keys(series: list[dict[str, Any]]) -> list[Key]:
    """Every assigned step of the series, in order."""
    return [
        (each["id"], item.get("scene") or item["name"], s["step"], s.get("coordinate"))
        for each in series
        for item in each["items"]
        for s in item["steps"]
    ]


def _step_entry(key: Key, series: list[dict[str, Any]]) -> dict[str, Any]:
    assignment_id, item, step, coordinate = key
    items = [i for a in series if a["id"] == assignment_id for i in a["items"]]
    systems = {i["name"] for i in items if i.get("system") is not None}
    kind = "system" if item in systems else "scene"
    number = next((a["n"] for a in series if a["id"] == assignment_id), None)
    return {"assignment": number, kind: item, "step": step, "coordinate": coordinate, "correct": 0, "incorrect": 0,
            "not_read": 0, "students_done": 0, "students_late": 0, "students_shown": 0, "students_shown_unanswered": 0,
            "students_right": 0, "students_wrong": 0,
            "students_equivalent": 0, "mistakes": {}, "mistake_names": {}}


def _tallies(db: Database, class_id: int) -> list[Any]:
    """The class in one statement, so in one snapshot of the database: per student (every student, those who
    have not answered yet with empty columns) and per item, step, coordinate, verdict and named mistake, how many
    answers, the mistake's words, the last answer's time, the first right answer's time and the student's
    institution login (None when the class does not ask); and, in the same statement (UNION ALL), each step shown
    to a student, as a row of verdict ``SHOWN`` with its time.

    One SELECT reads one consistent state on SQLite and on PostgreSQL alike (two statements in READ COMMITTED,
    or in SQLite's autocommit reads, may each see a different state while answers arrive)."""
    answers = (
        select(StudentRow.id, StudentRow.name, StudentRow.joined_at, AttemptRow.assignment_id, AttemptRow.item,
               AttemptRow.step, AttemptRow.coordinate, AttemptRow.verdict, AttemptRow.mistake,
               func.count(AttemptRow.id), func.max(AttemptRow.mistake_name), func.max(AttemptRow.at),
               func.min(case((AttemptRow.verdict.in_(DONE), AttemptRow.at))),
               func.max(StudentRow.login))  # one per student: the institution login, when the class asks for it
        .select_from(StudentRow)
        .outerjoin(AttemptRow, AttemptRow.student_id == StudentRow.id)
        .where(StudentRow.class_id == class_id)
        .group_by(StudentRow.id, StudentRow.name, StudentRow.joined_at, AttemptRow.assignment_id, AttemptRow.item,
                  AttemptRow.step, AttemptRow.coordinate, AttemptRow.verdict, AttemptRow.mistake)
    )
    shown = (
        select(StudentRow.id, StudentRow.name, StudentRow.joined_at, HintRow.assignment_id, HintRow.item,
               HintRow.step, HintRow.coordinate, literal(SHOWN), null(), literal(0), null(), HintRow.at, null(),
               StudentRow.login)
        .join(StudentRow, StudentRow.id == HintRow.student_id)
        .where(HintRow.class_id == class_id)
    )
    with db.session() as session:
        return list(session.execute(union_all(answers, shown)).all())


def _item_of(entry: dict[str, Any]) -> dict[str, Any]:
    return {k: entry[k] for k in ("assignment", "scene", "system") if k in entry} | {
        "step": entry["step"], "coordinate": entry["coordinate"]}


def _per_assignment(
    series: list[dict[str, Any]], names: dict[int, str], tried: dict[Key, set[int]], finished: dict[Key, set[int]],
    shown: dict[Key, set[int]], late: dict[Key, set[int]],
) -> list[dict[str, Any]]:
    """Each assignment of the series: its steps, the students done with all of them on their own by the due time,
    those through every step with one shown (or right only late) at least, and those stuck on one."""
    out = []
    for each in series:
        keys = [k for k in assigned_keys([each])]
        done = {s for s in names if keys and all(s in finished[k] for k in keys)}
        through = {s for s in names if keys and all(s in finished[k] | shown[k] | late[k] for k in keys)} - done
        stuck = {s for k in keys for s in tried[k] - finished[k] - shown[k] - late[k]}
        out.append({"n": each["n"], "title": each["title"], "due": each["due"], "steps": len(keys),
                    "students_done": sorted(names[s] for s in done),
                    "students_shown": sorted(names[s] for s in through),
                    "students_stuck": sorted(names[s] for s in stuck)})
    return out


def summary(db: Database, class_id: int, series: list[dict[str, Any]]) -> dict[str, Any]:
    """``{"students", "attempts", "assignments": [...], "steps": [...], "mistakes": [...]}`` from one snapshot.

    ``assignments``: each of the series with the students done with it and those stuck on one of its steps.
    ``steps``: the assigned steps first (in the series' order), then any other tried; each with its assignment's
    number, its counts, the students stuck on it (tried, not done yet) and its named mistakes.  ``mistakes``: each
    named mistake totalled over every step and scene it was made in (mistakes are totalled by their words, so the
    same slip in two scenes is one line), the one most students made first, with its answers (``count``), the
    steps (each with its answers and students) and the students concerned."""
    rows = _tallies(db, class_id)
    steps: dict[Key, dict[str, Any]] = {key: _step_entry(key, series) for key in assigned_keys(series)}
    names = {student_id: name for student_id, name, *_ in rows}
    tried: dict[Key, set[int]] = defaultdict(set)
    finished: dict[Key, set[int]] = defaultdict(set)
    by_mistake: dict[Key, dict[str, set[int]]] = defaultdict(lambda: defaultdict(set))
    right_at: dict[tuple[int, Key], datetime] = {}
    shown_at: dict[tuple[int, Key], datetime] = {}
    wrong: dict[Key, set[int]] = defaultdict(set)
    equivalent: dict[Key, set[int]] = defaultdict(set)
    attempts = 0
    for student_id, _name, _joined, assignment_id, item, step, coordinate, verdict, mistake, n, text, last, first_right, \
            _login in rows:
        if item is None:  # a student who has not answered yet
            continue
        key = (assignment_id, item, step, coordinate or None)
        entry = steps.setdefault(key, _step_entry(key, series))
        if verdict == SHOWN:
            shown_at[(student_id, key)] = min(last, shown_at.get((student_id, key), last))
            continue
        # an answer not read is one of the step's answers, neither right nor wrong
        entry["correct" if verdict in DONE else "not_read" if verdict == NOT_READ else "incorrect"] += n
        attempts += n
        tried[key].add(student_id)
        if verdict in DONE:
            earlier = right_at.get((student_id, key))
            right_at[(student_id, key)] = first_right if earlier is None else min(earlier, first_right)
        elif verdict != NOT_READ:
            wrong[key].add(student_id)
        if verdict == "equivalent":
            equivalent[key].add(student_id)
        if mistake:
            entry["mistakes"][mistake] = entry["mistakes"].get(mistake, 0) + n
            by_mistake[key][mistake].add(student_id)
            if text:  # the mistake in words (one system's mistakes are worded alike), spoken about the student
                entry["mistake_names"][mistake] = for_teacher(text)
    # done: right on one's own (the gradebook's rule); shown: "Show this step" pressed before any right answer
    shown: dict[Key, set[int]] = defaultdict(set)
    late: dict[Key, set[int]] = defaultdict(set)  # right on their own, but after the due time: not counted
    dues = {each["id"]: each["due"] for each in series}
    for (student_id, key), at in right_at.items():
        seen, due = shown_at.get((student_id, key)), dues.get(key[0])
        (finished if on_own(at, seen, due) else late if late_only(at, seen, due) else shown)[key].add(student_id)
    for student_id, key in shown_at:
        if student_id not in finished[key] | late[key]:
            shown[key].add(student_id)
    totals: dict[str, dict[str, Any]] = {}
    for key, entry in steps.items():
        stuck = tried[key] - finished[key] - shown[key] - late[key]
        entry["students_done"] = len(finished[key])
        entry["students_late"] = len(late[key])
        entry["students_shown"] = len(shown[key])
        # shown without an answer yet: among the shown, but in neither of the bar's counts (it counts answers)
        entry["students_shown_unanswered"] = len(shown[key] - tried[key])
        # the bars count students: each once, by their best answer (right, else wrong)
        entry["students_right"] = len({s for (s, k) in right_at if k == key})
        entry["students_wrong"] = len(wrong[key] - {s for (s, k) in right_at if k == key})
        entry["students_equivalent"] = len(equivalent[key])
        entry["stuck"] = len(stuck)
        entry["students_stuck"] = sorted(names[s] for s in stuck)
        # the most common mistake first
        entry["mistakes"] = dict(sorted(entry["mistakes"].items(), key=lambda kv: (-kv[1], kv[0])))
        for mistake, count in entry["mistakes"].items():
            words = entry["mistake_names"].get(mistake, "")
            total = totals.setdefault(words or mistake, {"key": mistake, "name": words, "count": 0, "steps": [],
                                                         "students": set(), "still": set()})
            total["count"] += count
            total["steps"].append(_item_of(entry) | {"count": count, "students": len(by_mistake[key][mistake])})
            total["students"] |= by_mistake[key][mistake]
            # still without a right answer on a step where they made it (the list mixed them with
            # the students who have since put it right)
            total["still"] |= by_mistake[key][mistake] - {s for (s, k) in right_at if k == key}
    # the mistake most students made first (then the most answers): a student who makes it twice is one student
    mistakes = sorted(totals.values(), key=lambda t: (-len(t["students"]), -t["count"], t["name"] or t["key"]))
    for total in mistakes:
        total["students_since_right"] = sorted(names[s] for s in total["students"] - total.pop("still"))
        total["students"] = sorted(names[s] for s in total["students"])
        total["steps"].sort(key=lambda s: (-s["students"], -s["count"]))
    return {"students": len(names), "attempts": attempts,
            "assignments": _per_assignment(series, names, tried, finished, shown, late),
            "steps": list(steps.values()), "mistakes": mistakes}


def students(db: Database, class_id: int, series: list[dict[str, Any]]) -> dict[str, Any]:
    """Each student's progress (from one snapshot): attempts, steps done of the series', and per step tried its
    tally (with its assignment's number).  A step is ``done`` once answered right; ``shown`` when "Show this step"
    was pressed before the first right answer (or with none yet): a step done but shown does not count toward the
    grade, so ``own`` counts the assigned steps done on one's own by the due time (``on_own``, the gradebook's
    rule), and ``late`` those right on one's own only after it (a step's tally says ``late`` likewise)."""
    people: dict[int, tuple[str, Any, str | None]] = {}
    per: dict[int, dict[Key, dict[str, Any]]] = defaultdict(dict)
    shown_at: dict[tuple[int, Key], datetime] = {}
    number = {a["id"]: a["n"] for a in series}
    dues = {a["id"]: a["due"] for a in series}
    for student_id, name, joined, assignment_id, item, step, coordinate, verdict, _mistake, n, _text, last, first_right, \
            login in _tallies(db, class_id):
        people[student_id] = (name, joined, login)
        if item is None:
            continue
        key = (assignment_id, item, step, coordinate or None)
        if verdict == SHOWN:
            shown_at[(student_id, key)] = min(last, shown_at.get((student_id, key), last))
            continue
        tally = per[student_id].setdefault(key, {
            "assignment": number.get(assignment_id), "item": item, "step": step, "coordinate": coordinate,
            "attempts": 0, "not_read": 0, "done": False, "shown": False, "last": last, "_key": key, "_right": None})
        tally["attempts"] += n
        tally["not_read"] += n if verdict == NOT_READ else 0
        tally["done"] = tally["done"] or verdict in DONE
        tally["last"] = max(tally["last"], last)
        if first_right is not None:
            tally["_right"] = first_right if tally["_right"] is None else min(tally["_right"], first_right)
    assigned = set(assigned_keys(series))
    rows = []
    for student_id, (name, joined, login) in sorted(people.items(), key=lambda p: (p[1][1], p[0])):
        tallies = list(per.get(student_id, {}).values())
        for t in tallies:
            seen_at, due = shown_at.get((student_id, t["_key"])), dues.get(t["_key"][0])
            t["shown"] = seen_at is not None and not on_own(t["_right"], seen_at)
            # what the grade counts (right on one's own by the due time); late: right on one's own, only after it
            t["counted"] = on_own(t["_right"], seen_at, due)
            t["late"] = late_only(t["_right"], seen_at, due)
        finished = {t["_key"] for t in tallies if t["done"]}
        # done as the grade counts it; right on their own only late, apart
        own = {t["_key"] for t in tallies if t["counted"]}
        late = {t["_key"] for t in tallies if t["late"]}
        # a step shown and not answered yet is shown too
        seen = {t["_key"] for t in tallies if t["shown"]} | {k for (s, k) in shown_at if s == student_id} - own
        steps = [{k: v for k, v in t.items() if not k.startswith("_")} | {"last": t["last"].isoformat() + "Z"}
                 for t in tallies]
        rows.append({
            "name": name,
            "login": login,  # their institution login (None: the class does not ask, or they joined before it did)
            "joined": joined.isoformat() + "Z",
            "attempts": sum(s["attempts"] for s in steps),
            "not_read": sum(s["not_read"] for s in steps),
            "done": len(finished & assigned) if assigned else len(finished),
            "own": len(own & assigned) if assigned else len(own),
            "counted": len(own & assigned) if assigned else len(own),
            "late": len(late & assigned) if assigned else len(late),
            "shown": len(seen & assigned) if assigned else len(seen),
            "assigned": len(assigned),
            "steps": steps,
        })
    return {"students": rows}


def own_record(db: Database, class_id: int, student_id: int, series: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """What a student's own page shows again after a reload or on another device, per step they answered or were
    shown: their last answer as typed, what it was answered (the verdict as the checker gave it, or for an answer
    not read the refusal: ``status`` 200 or 422 and its ``body``; None for an answer recorded without it) and
    whether the step was shown ("Show this step"), whenever that was."""
    number = {a["id"]: a["n"] for a in series}
    with db.session() as session:
        answers = session.execute(
            select(AttemptRow.assignment_id, AttemptRow.item, AttemptRow.step, AttemptRow.coordinate,
                   AttemptRow.verdict, AttemptRow.answer, AttemptRow.response)
            .where(AttemptRow.class_id == class_id, AttemptRow.student_id == student_id)
            .order_by(AttemptRow.id)
        ).all()
        hints = session.execute(
            select(HintRow.assignment_id, HintRow.item, HintRow.step, HintRow.coordinate)
            .where(HintRow.class_id == class_id, HintRow.student_id == student_id)
        ).all()
    mine: dict[Key, dict[str, Any]] = {}

    def entry(assignment_id: int | None, item: str, step: str, coordinate: str | None) -> dict[str, Any]:
        key = (assignment_id, item, step, coordinate or None)
        return mine.setdefault(key, {"assignment": number.get(assignment_id), "item": item, "step": step,
                                     "coordinate": coordinate or None, "answer": None, "answered": None,
                                     "shown": False})

    for assignment_id, item, step, coordinate, verdict, answer, response in answers:  # oldest first: the last stays
        found = entry(assignment_id, item, step, coordinate)
        found["answer"] = answer
        found["answered"] = None if response is None else {
            "status": 422 if verdict == NOT_READ else 200, "body": json.loads(response)}
    for assignment_id, item, step, coordinate in hints:
        entry(assignment_id, item, step, coordinate)["shown"] = True
    return list(mine.values())


def _cell(value: Any) -> str:
    """A cell a spreadsheet will not run: text starting like a formula gets a leading apostrophe."""
    text = "" if value is None else str(value)
    return "'" + text if text.startswith(FORMULA_START) else text


def _counted(verdict: str, shown: bool, late: bool) -> str:
    """Whether the answer counts toward the grade (``grades``' rule: right, on one's own, by the due time)."""
    if verdict not in DONE:
        return "no: wrong"
    if shown:
        return "no: typed after the step was shown"
    return "no: after the due time" if late else "yes"


def export_csv(db: Database, class_id: int, series: list[dict[str, Any]]) -> bytes:
    """Every attempt of the class, oldest first, as CSV (UTF-8 with a byte-order mark): its time to the second in
    UTC, its assignment ("1. Week 1"), the scene by its title or the typed system by its name, the step in words, as a heading
    ("Energy function h", "Position x₁"), the verdict in words (``NOT_READ_WORDS`` for an answer the checker could not read), whether it
    was typed after "Show this step" on that step, whether it came after the due time, whether it counts toward the
    grade (and if not, why), the mistake in the third person (for an answer not read, why: the refusal's words) and
    the answer exactly as typed (a judged answer is a checked expression: names, numbers, operators and the allowed
    functions, nothing a spreadsheet could run).  Every other cell, an answer not read included, gets an apostrophe
    before a formula's first character."""
    titles = {a["id"]: f"{a['n']}. {a['title']}" for a in series}
    dues = {a["id"]: a["due"] for a in series}
    with db.session() as session:
        rows = session.execute(
            select(AttemptRow.at, StudentRow.id, StudentRow.name, AttemptRow.assignment_id, AttemptRow.item,
                   AttemptRow.step, AttemptRow.coordinate, AttemptRow.verdict, AttemptRow.mistake,
                   AttemptRow.mistake_name, AttemptRow.answer, AttemptRow.response)
            .join(StudentRow, StudentRow.id == AttemptRow.student_id)
            .where(AttemptRow.class_id == class_id)
            .order_by(AttemptRow.id)
        ).all()
        hints = session.execute(
            select(HintRow.student_id, HintRow.assignment_id, HintRow.item, HintRow.step, HintRow.coordinate,
                   HintRow.at).where(HintRow.class_id == class_id)
        ).all()
    shown_at: dict[tuple[int, int | None, str, str, str], datetime] = {
        (student, assignment, item, step, coordinate or ""): at
                for student, assignment, item, step, coordinate, at in hints}
    out = io.StringIO()
    out.write(BOM)
    writer = csv.writer(out, lineterminator="\r\n")
    writer.writerow(CSV_COLUMNS)
    for at, student, name, assignment, item, step, coordinate, verdict, mistake, words, answer, response in rows:
        where = SCENES[item].title if item in SCENES else item
        unread = verdict == NOT_READ
        seen = shown_at.get((student, assignment, item, step, coordinate or ""))
        shown = seen is not None and seen <= at
        late = is_late(at, dues.get(assignment))
        why = refusal_words(response) if unread else for_teacher(words) if words else mistake
        counted = f"no: {NOT_READ_WORDS}" if unread else _counted(verdict, shown, late)
        cells = [name, titles.get(assignment, ""), where, step_heading(step, coordinate),
                 VERDICT_WORDS.get(verdict, verdict), "yes" if shown else "no", "yes" if late else "no", counted, why]
        writer.writerow([at.strftime(TIME_FORMAT), *(_cell(v) for v in cells), _cell(answer) if unread else answer])
    return out.getvalue().encode("utf-8")


def refusal_words(response: str | None) -> str:
    """Why an answer was not read: the refusal's words as the student was told them (without the field's name)."""
    detail = str(json.loads(response).get("detail", "")) if response else ""
    return detail.removeprefix("answer: ")
