"""An assignment: what the instructor sets (scenes or declared systems, their steps, optional parameters),
checked before it is stored, and how a student's check finds its item in it.

An item is ``{"scene": id}`` or ``{"system": <as POST /api/derive>, "name": label}``, with ``steps``
(``[{"step", "coordinate"}]``; for a scene, none means every step of its practice) and ``parameters``
(``{name: value}``, shown to the students), and for a system its ``setup`` (required: app/service/classroom/setup.py).
Refusals are located under ``items.<i>``.  Runs in a thread:
a scene's exercises come from its cached derivation.

A class holds a series of assignments, each with its items; ``find_target`` says which assignment and item of
the series a student's check (or shown step) is for.
"""

from __future__ import annotations

import json
import math
import re
from datetime import UTC, datetime
from typing import Any

from app.engine.tutor.check import KEYED, PER_COMPONENT, PER_COORDINATE, STEPS
from app.errors import Refused, UnknownScene
from app.service.classroom.setup import checked_setup
from app.service.tutor.checking import Checking, declared
from app.service.users.user_checks import InvalidSystem

MAX_ITEMS = 20
MAX_STEPS = 40
_COMPONENT = re.compile(r"[xyz][1-9]?[0-9]?")


def _refuse(message: str, *loc: Any) -> Refused:
    return Refused(f"items.{'.'.join(str(x) for x in loc)}: {message}" if loc else message, "", ("items", *loc))


def _same(a: dict[str, Any], step: str, coordinate: str | None) -> bool:
    return a["step"] == step and (step not in KEYED or a.get("coordinate") == coordinate)


def _shown(steps: list[dict[str, Any]]) -> str:
    return ", ".join(s["step"] + (f" ({s['coordinate']})" if s.get("coordinate") else "") for s in steps)


def _scene_item(checking: Checking, i: int, item: dict[str, Any]) -> dict[str, Any]:
    scene = item["scene"]
    try:
        practice = json.loads(checking.scene_exercises(scene))
    except UnknownScene as exc:
        raise _refuse(str(exc), i, "scene") from None
    offered = [{"step": e["step"], "coordinate": e["coordinate"]} for e in practice["exercises"]]
    wanted = item.get("steps") or offered
    steps = []
    for j, s in enumerate(wanted):
        found = next((o for o in offered if _same(o, s["step"], s.get("coordinate"))), None)
        if found is None:
            raise _refuse(f"the scene {scene} has no step {_shown([s])}; its steps are: {_shown(offered)}", i, "steps", j)
        steps.append(found)
    names = set(practice["symbols"])
    for name in item.get("parameters") or {}:
        if name not in names:
            raise _refuse(f"{name!r} is not a name of the scene {scene}", i, "parameters", name)
    checked_setup(i, item)  # a scene has none: its page sets it up
    return {"item": scene, "system": None, "steps": steps, "parameters": item.get("parameters") or {}}


def _system_item(i: int, item: dict[str, Any]) -> dict[str, Any]:
    try:
        user = declared(item["system"])
    except (InvalidSystem, Refused) as exc:
        raise Refused(f"items.{i}.{exc}", exc.part, ("items", i, *(exc.loc or ("system",)))) from None
    steps = item.get("steps") or []
    if not steps:
        raise _refuse("list the steps to practise on a system you declare", i, "steps")
    for j, s in enumerate(steps):
        if s["step"] not in STEPS:
            raise _refuse(f"unknown step {s['step']!r}; the steps are: {', '.join(STEPS)}", i, "steps", j)
        if s["step"] in PER_COORDINATE and s.get("coordinate") not in user.coordinates:
            raise _refuse(
                f"the step {s['step']} needs one of the coordinates: {', '.join(user.coordinates)}", i, "steps", j
            )
        # a position names its Cartesian component (x, y, z, or x1, z2 … by body); the check says if it moves
        if s["step"] in PER_COMPONENT and not _COMPONENT.fullmatch(str(s.get("coordinate") or "")):
            raise _refuse(f"the step {s['step']} needs a component: x, y or z, numbered by body (x1, z2)", i, "steps", j)
    for name in item.get("parameters") or {}:
        if name not in user.parameter_names:
            raise _refuse(f"{name!r} is not a parameter of this system", i, "parameters", name)
    clean = [{"step": s["step"], "coordinate": s.get("coordinate") if s["step"] in KEYED else None}
             for s in steps]
    return {"item": item["name"], "system": item["system"], "steps": clean, "parameters": item.get("parameters") or {},
            "setup": checked_setup(i, item)}


def checked_items(checking: Checking, items: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The items as stored, or a located refusal."""
    if len(items) > MAX_ITEMS:
        raise _refuse(f"at most {MAX_ITEMS} items in an assignment")
    names: set[str] = set()
    stored = []
    for i, item in enumerate(items):
        if (item.get("scene") is None) == (item.get("system") is None):
            raise _refuse("give either a scene's id ('scene') or a system ('system' with a 'name')", i)
        if len(item.get("steps") or []) > MAX_STEPS:
            raise _refuse(f"at most {MAX_STEPS} steps in an item", i, "steps")
        for name, value in (item.get("parameters") or {}).items():
            if not isinstance(value, int | float) or not math.isfinite(value):
                raise _refuse("a parameter's value is a finite number", i, "parameters", name)
        if item.get("system") is not None and not item.get("name"):
            raise _refuse("name the system (students pick it by this name)", i, "name")
        entry = _scene_item(checking, i, item) if item.get("scene") is not None else _system_item(i, item)
        if entry["item"] in names:
            raise _refuse(f"{entry['item']!r} is assigned twice; merge its steps into one item", i)
        names.add(entry["item"])
        stored.append(entry)
    return stored


def find_item(
    items: list[dict[str, Any]], target: dict[str, str | None], step: str, coordinate: str | None
) -> dict[str, Any]:
    """The assignment's item a check is for; with no assignment, any scene (and no declared system)."""
    scene, system = target.get("scene"), target.get("system")
    if (scene is None) == (system is None):
        raise Refused("give the item to check: 'scene' (a scene's id) or 'system' (the assigned system's name)",
                      "", ("scene",))
    if not items:
        if system is not None:
            raise Refused("no system is assigned in this class: check a scene", system, ("system",))
        return {"scene": scene, "steps": []}
    field = "scene" if scene is not None else "system"
    wanted = scene if scene is not None else system
    for item in items:
        if (item.get("scene") if field == "scene" else item.get("name") if item.get("system") else None) == wanted:
            break
    else:
        assigned = ", ".join(i.get("scene") or i["name"] for i in items)
        raise Refused(f"{field}: {wanted!r} is not in this class's assignment; assigned: {assigned}", str(wanted),
                      (field,))
    if item["steps"] and not any(_same(s, step, coordinate) for s in item["steps"]):
        raise Refused(f"step: not in the assignment for {wanted}; assigned: {_shown(item['steps'])}", step, ("step",))
    return item


def checked_due(due: datetime | None, kept: str | None = None) -> datetime | None:
    """A due time as stored (naive UTC); a time already past is refused, unless it is the one already stored."""
    if due is None:
        return None
    stored = due.astimezone(UTC).replace(tzinfo=None)
    if kept is not None and stored.isoformat() + "Z" == kept:
        return stored
    if stored <= datetime.now(UTC).replace(tzinfo=None):
        raise Refused(f"due: {stored.isoformat()}Z is already past; give a time to come (ISO 8601 with its zone, "
                      "e.g. 2026-12-04T17:00:00Z)", "", ("due",))
    return stored


def find_target(
    series: list[dict[str, Any]], target: dict[str, Any], step: str, coordinate: str | None
) -> tuple[dict[str, Any] | None, dict[str, Any]]:
    """The assignment of the series (None when nothing is assigned) and its item a check is for.

    ``target["assignment"]`` (a number) names the assignment; without it, the first assignment of the series
    that holds the item and step."""
    n = target.get("assignment")
    if n is not None:
        chosen = [a for a in series if a["n"] == n]
        if not chosen:
            have = f"1 to {len(series)}" if series else "none yet"
            raise Refused(f"assignment: this class has no assignment {n}; its assignments are numbered {have}",
                          str(n), ("assignment",))
        return chosen[0], find_item(chosen[0]["items"], target, step, coordinate)
    if not any(a["items"] for a in series):  # nothing assigned: any scene
        return None, find_item([], target, step, coordinate)
    for each in series:
        try:
            return each, find_item(each["items"], target, step, coordinate)
        except Refused:
            continue
    # in none of them: the refusal says what is assigned over the whole series
    find_item([i for a in series for i in a["items"]], target, step, coordinate)
    raise Refused(f"step: not in the assignments; assigned: {_shown([s for a in series for i in a['items'] for s in i['steps']])}",
                  step, ("step",))
