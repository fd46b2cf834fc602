"""The playground's form: read from the query string, shown again as typed, turned into the API's request.

The form is text field by field (so a refusal can be shown next to what was
typed); ``spec_of`` validates it with the API's model (``SystemSpec``), the one
shape of a user system from there on; ``field_id`` maps a refusal's location in
the request back to the input that holds it.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from typing import Any

from pydantic import ValidationError
from starlette.datastructures import QueryParams

from app.engine.errors import excerpt
from app.web.api.limits import TooDeep, check_json_depth
from app.web.schemas.user import SystemSpec

FORMS = ("lagrangian", "energies", "particles")
AXES = ("x", "y", "z")


@dataclass
class Form:
    """What the student typed, field by field, as text (so it can be shown again as typed)."""

    coordinates: str = ""
    parameters: list[dict[str, str]] = field(default_factory=list)  # name, value, unit, min, max
    form: str = "energies"
    lagrangian: str = ""
    kinetic: str = ""
    potential: str = ""
    particles: list[dict[str, str]] = field(default_factory=list)  # mass, x, y, z
    forces: list[dict[str, str]] = field(default_factory=list)  # coordinate, expression
    nonnegative: str = ""


class FormError(Exception):
    def __init__(
        self, message: str, field_id: str = "", text: str = "", start: int | None = None, end: int | None = None
    ):
        super().__init__(message)
        self.field_id, self.text, self.start, self.end = field_id, text, start, end

    def view(self) -> dict[str, Any]:
        marked = self.start is not None and self.end is not None and self.start < self.end <= len(self.text)
        return {
            "message": str(self),
            "field_id": self.field_id,
            "text": self.text,
            "before": self.text[: self.start] if marked else "",
            "part": self.text[self.start : self.end] if marked else "",
            "after": self.text[self.end :] if marked else "",
            "marked": marked,
        }


def _rows(query: QueryParams, keys: dict[str, str]) -> list[dict[str, str]]:
    columns = {name: query.getlist(key) for name, key in keys.items()}
    count = max((len(v) for v in columns.values()), default=0)
    rows = [
        {name: (values[i] if i < len(values) else "").strip() for name, values in columns.items()} for i in range(count)
    ]
    return [r for r in rows if any(r.values())]


def read_form(query: QueryParams) -> Form:
    """The form as typed, from the query string (``system`` JSON takes precedence)."""
    if query.get("system"):
        try:
            # the nesting is checked by a scan before json.loads, which recurses once per level
            check_json_depth(query["system"])
            return form_of(json.loads(query["system"]))
        except TooDeep as exc:
            raise FormError(f"the system in the address is not a system: {exc}", "f-coordinates") from None
        except (ValueError, TypeError, AttributeError, RecursionError):
            raise FormError("the system in the address is not valid JSON in the API's shape", "f-coordinates") from None
    return Form(
        coordinates=query.get("q", "").strip(),
        parameters=_rows(query, {"name": "pn", "value": "pv", "unit": "pu", "min": "plo", "max": "phi"}),
        form=query.get("form", "energies") if query.get("form") in FORMS else "energies",
        lagrangian=query.get("L", ""),
        kinetic=query.get("T", ""),
        potential=query.get("U", ""),
        particles=_rows(query, {"mass": "m", "x": "x", "y": "y", "z": "z"}),
        forces=_rows(query, {"coordinate": "fq", "expression": "fQ"}),
        nonnegative=query.get("nn", "").strip(),
    )


def _text(value: Any) -> str:
    return "" if value is None else str(value)


def form_of(spec: dict[str, Any]) -> Form:
    """The form showing a system given in the API's shape."""
    params = []
    for p in spec.get("parameters") or []:
        p = {"name": p} if isinstance(p, str) else p
        params.append(
            {k: _text(p.get(k, "1" if k == "value" else "")) for k in ("name", "value", "unit", "min", "max")}
        )
    particles = [
        {"mass": _text(p.get("mass")), **{a: _text(c) for a, c in zip(AXES, p.get("position") or [], strict=False)}}
        for p in spec.get("particles") or []
    ]
    kind = "particles" if particles else ("lagrangian" if spec.get("lagrangian") is not None else "energies")
    return Form(
        coordinates=", ".join(map(str, spec.get("coordinates") or [])),
        parameters=params,
        form=kind,
        lagrangian=_text(spec.get("lagrangian")),
        kinetic=_text(spec.get("kinetic")),
        potential=_text(spec.get("potential")),
        particles=particles,
        forces=[{"coordinate": str(k), "expression": _text(v)} for k, v in (spec.get("forces") or {}).items()],
        nonnegative=", ".join(map(str, spec.get("nonnegative") or [])),
    )


def _names(text: str) -> list[str]:
    return [n for n in re.split(r"[\s,]+", text) if n]


def _number(text: str, field_id: str, what: str) -> float | None:
    if not text:
        return None
    try:
        return float(text)
    except ValueError:
        raise FormError(f"{what}: {text[:30]!r} is not a number", field_id, text) from None


# Quantities that are positive by nature: masses, lengths, stiffnesses and gravity, by unit or by the usual name.
POSITIVE_UNITS = {"kg", "m", "N/m", "m/s^2", "m/s²", "m/s**2"}
POSITIVE_NAMES = re.compile(r"(m|M|mu|l|L|R|r|k|g)\d*")
JUST_ABOVE_ZERO = 1e-9  # the lowest value such a parameter gets when the form leaves it empty


def positive_by_nature(name: str, unit: str) -> bool:
    """A mass, length, spring constant or g: its lowest value defaults to just above 0 (never negative)."""
    return unit.strip() in POSITIVE_UNITS if unit.strip() else bool(POSITIVE_NAMES.fullmatch(name.strip()))


def _where(loc: tuple) -> str:
    """A refusal's place in the form's own words: ("parameters", 0, "name") -> "parameter 1, name"."""
    words = {"parameters": "parameter", "particles": "particle", "coordinates": "coordinate", "forces": "force on"}
    out: list[str] = []
    for x in loc:
        if isinstance(x, int) and out:
            out[-1] = f"{out[-1]} {x + 1}"
        else:
            out.append(words.get(str(x), excerpt(x)))
    return ", ".join(out)


def spec_of(form: Form) -> dict[str, Any]:
    """The API request for what was typed (validated with the API's model).

    What the form itself can tell (no coordinate, a parameter without a name or a value) is said in
    its own words at the field; a blank value is never filled in silently."""
    if not _names(form.coordinates):
        raise FormError("add at least one coordinate (for example theta, or x, y)", "f-coordinates", form.coordinates)
    parameters = []
    for i, p in enumerate(form.parameters):
        if not p.get("name", "").strip():
            raise FormError(f"parameter {i + 1}: a name is needed", f"f-param-{i}-name")
        if not p.get("value", "").strip():
            name = p["name"].strip()
            raise FormError(f"parameter {i + 1} ({excerpt(name)}): a value is needed", f"f-param-{i}-value")
        entry: dict[str, Any] = {"name": p.get("name", ""), "unit": p.get("unit", "")}
        for key, what in (("value", "value"), ("min", "lowest value"), ("max", "highest value")):
            number = _number(p.get(key, ""), f"f-param-{i}-{key}", f"parameter {p.get('name') or i + 1}, {what}")
            if number is not None:
                entry[key] = number
        if "min" not in entry and positive_by_nature(entry["name"], entry["unit"]):
            entry["min"] = JUST_ABOVE_ZERO
        parameters.append(entry)
    spec: dict[str, Any] = {"coordinates": _names(form.coordinates), "parameters": parameters}
    if form.form == "lagrangian":
        spec["lagrangian"] = form.lagrangian
    else:
        spec["potential"] = form.potential or "0"
        if form.form == "energies":
            spec["kinetic"] = form.kinetic
        else:
            spec["particles"] = [
                {"mass": p.get("mass", ""), "position": [p.get(a) or "0" for a in AXES]} for p in form.particles
            ]
    forces = {f["coordinate"]: f["expression"] for f in form.forces if f.get("expression")}
    if forces:
        spec["forces"] = forces
    if form.nonnegative:
        spec["nonnegative"] = _names(form.nonnegative)
    try:
        return SystemSpec.model_validate(spec).to_spec()
    except ValidationError as exc:
        first = exc.errors()[0]
        # a parameter is a name or an object: drop the union member from the location
        loc = tuple(x for x in first["loc"] if x not in ("ParameterSpec", "str"))
        message = str(first["msg"]).removeprefix("Value error, ")
        raise located_error(form, loc, message) from None


def field_id(form: Form, loc: tuple) -> str:
    """The id of the input that holds the part of the request at ``loc``."""
    head = loc[0] if loc else ""
    if head == "coordinates":
        return "f-coordinates"
    if head == "parameters" and len(loc) > 1 and isinstance(loc[1], int):
        key = loc[2] if len(loc) > 2 and loc[2] in ("name", "value", "unit", "min", "max") else "name"
        return f"f-param-{loc[1]}-{key}"
    if head in ("lagrangian", "kinetic", "potential"):
        return {"lagrangian": "f-L", "kinetic": "f-T", "potential": "f-U"}[head]
    if head == "particles" and len(loc) > 2 and isinstance(loc[1], int):
        column = "mass" if loc[2] == "mass" else (AXES[loc[3]] if len(loc) > 3 and isinstance(loc[3], int) else "x")
        return f"f-particle-{loc[1]}-{column}"
    if head == "forces" and len(loc) > 1:
        rows = [i for i, f in enumerate(form.forces) if f.get("coordinate") == loc[1]]
        return f"f-force-{rows[0]}-expression" if rows else "f-forces"
    if head == "nonnegative":
        return "f-nn"
    return "f-form" if head == "" else f"f-{head}"


def _value_at(form: Form, field: str) -> str:
    if field == "f-coordinates":
        return form.coordinates
    if field in ("f-L", "f-T", "f-U"):
        return {"f-L": form.lagrangian, "f-T": form.kinetic, "f-U": form.potential}[field]
    parts = field.split("-")
    groups = {"param": form.parameters, "particle": form.particles, "force": form.forces}
    if len(parts) == 4 and parts[1] in groups and parts[2].isdigit() and int(parts[2]) < len(groups[parts[1]]):
        return groups[parts[1]][int(parts[2])].get(parts[3], "")
    return ""


# the request's field names as the form calls them, for the start of a message ("In the Lagrangian: …")
_FIELDS = {"lagrangian": "In the Lagrangian", "kinetic": "In the kinetic energy T",
           "potential": "In the potential energy U", "nonnegative": "In the coordinates that are never negative"}  # fmt: skip
# a request location as the API prints it at the start of a message: lagrangian, parameters[1].name, particles[0].mass
_API_PLACE = re.compile(r"^[a-z]+(?:\[\d+\]|\.[A-Za-z0-9_]+)*: ")


def readable(loc: tuple, message: str) -> str:
    """A refusal as the form says it: its place in the form's words ("In the Lagrangian: unknown name …",
    "Parameter 2 (name): …") instead of the request's field name ("lagrangian: …")."""
    head = loc[0] if loc else ""
    if head in _FIELDS:
        place = _FIELDS[str(head)]
    elif head == "forces" and len(loc) > 1:
        place = f"In the force on {excerpt(loc[1])}"
    elif head == "particles" and len(loc) > 2 and isinstance(loc[1], int):
        column = "mass" if loc[2] == "mass" else f"{AXES[loc[3]]}" if len(loc) > 3 and isinstance(loc[3], int) else loc[2]
        place = f"In particle {loc[1] + 1}, {column}"
    elif head in ("parameters", "coordinates") and len(loc) > 1 and isinstance(loc[1], int):
        place = f"{'Parameter' if head == 'parameters' else 'Coordinate'} {loc[1] + 1}"
        place += f" ({excerpt(loc[2])})" if len(loc) > 2 else ""
    elif loc:
        words = _where(loc)
        place = words[:1].upper() + words[1:]
    else:
        return message
    return f"{place}: {_API_PLACE.sub('', message, count=1)}"


def located_error(form: Form, loc: tuple, message: str, start: int | None = None, end: int | None = None) -> FormError:
    target = field_id(form, loc)
    return FormError(readable(loc, message), target, _value_at(form, target), start, end)


def query_of(form: Form) -> dict[str, Any]:
    """The query string that reproduces a form (the shareable address)."""
    query: dict[str, Any] = {"q": form.coordinates, "form": form.form}
    for key, name in (("pn", "name"), ("pv", "value"), ("pu", "unit"), ("plo", "min"), ("phi", "max")):
        query[key] = [p.get(name, "") for p in form.parameters]
    if form.form == "lagrangian":
        query["L"] = form.lagrangian
    else:
        query["U"] = form.potential
        if form.form == "energies":
            query["T"] = form.kinetic
        else:
            for key in ("m", *AXES):
                query[key] = [p.get("mass" if key == "m" else key, "") for p in form.particles]
    if form.forces:
        query["fq"] = [f["coordinate"] for f in form.forces]
        query["fQ"] = [f["expression"] for f in form.forces]
    if form.nonnegative:
        query["nn"] = form.nonnegative
    return {k: v for k, v in query.items() if (any(v) if isinstance(v, list) else v)}
