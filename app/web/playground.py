"""/playground: a student types a system, sees its derivation step by step, then simulates it.

The page is a plain GET form, so the system lives in the query string and every
derivation has a shareable address (``/playground?q=x&form=energies&T=...``);
``?system=<JSON>`` in the API's request shape works too.  The route derives
through the same service as POST /api/derive (checks, cache, fair share, worker
pool: no SymPy here) and renders the derivation with the scene page's markup.
A refusal is shown next to the field it concerns, with the offending part marked.
The simulation runs in the browser against POST /api/simulate (static/js/playground.js).
"""

from __future__ import annotations

import json
import re
import threading
from dataclasses import dataclass, field
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response
from pydantic import ValidationError
from starlette.concurrency import run_in_threadpool
from starlette.datastructures import QueryParams

from app.engine.errors import excerpt
from app.engine.parse import FUNCTIONS
from app.service import user_systems
from app.service.fairness import COOKIE, COOKIE_MAX_AGE, Busy
from app.service.user_systems import InvalidSystem
from app.service.worker import JobFailed
from app.viz.exprtree import TreeError, tree
from app.viz.page_model import angles, scene_page
from app.web.examples_user import DOUBLE_PENDULUM, FORCED_SPRING, SPINNING_HOOP
from app.web.limits import TooDeep, check_json_depth
from app.web.pages import simulation_methods
from app.web.schemas import SESSION_COOKIE
from app.web.schemas_user import SystemSpec
from app.web.templating import templates

router = APIRouter(tags=["pages"])

MAX_QUERY = 16_000  # characters of query string: far more than any system the form can hold
FORMS = ("lagrangian", "energies", "particles")
EXAMPLES = {
    "Forced, damped spring (T, U and a force)": FORCED_SPRING,
    "Double pendulum (particles)": DOUBLE_PENDULUM,
    "Bead on a spinning hoop (L alone)": SPINNING_HOOP,
}
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


def spec_of(form: Form) -> dict[str, Any]:
    """The API request for what was typed (validated with the API's model)."""
    parameters = []
    for i, p in enumerate(form.parameters):
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
        where = ".".join(excerpt(x) for x in loc)
        raise _located(form, loc, f"{where}: {first['msg']}") from None


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


def _located(form: Form, loc: tuple, message: str, start: int | None = None, end: int | None = None) -> FormError:
    target = field_id(form, loc)
    return FormError(message, target, _value_at(form, target), start, end)


def _display_particles(spec: dict[str, Any], doc: dict[str, Any]) -> list[tuple[str, tuple[str, str, str]]]:
    """What the animation draws: the particles, or else one bead per coordinate (on a circle for an angle)."""
    if spec.get("particles"):
        return [
            (p.get("label") or "", tuple(p["position"]) + ("0",) * (3 - len(p["position"]))) for p in spec["particles"]
        ]
    angular = angles(doc)
    beads = []
    for k, q in enumerate(spec["coordinates"]):
        x0, z0 = 3 * k, 0
        position = (f"{x0} + sin({q})", "0", f"{z0} - cos({q})") if q in angular else (q, "0", f"{-1.5 * k}")
        beads.append((q, position))
    return beads


def _moves_in_3d(particles: list[tuple[str, tuple[str, str, str]]], coordinates: list[str]) -> bool:
    moving = set(coordinates) | {"t"}

    def names(node: Any) -> set[str]:
        if isinstance(node, str):
            return {node}
        if isinstance(node, list):
            return set().union(*(names(c) for c in node[1:])) if len(node) > 1 else set()
        return set()

    def moves(text: str) -> bool:
        try:
            return bool(names(tree(text)) & moving)
        except TreeError:
            return False

    return all(any(moves(pos[i]) for _, pos in particles) for i in range(3))


def model_of(spec: dict[str, Any], doc: dict[str, Any]) -> dict[str, Any]:
    """The scene page model for a user system (pure Python: expression trees, no SymPy)."""
    particles = _display_particles(spec, doc)
    three_d = bool(spec.get("particles")) and _moves_in_3d(particles, spec["coordinates"])
    panels = ["animation-3d" if three_d else "animation-2d", "energy"]
    if doc["hamiltonian_equals_energy"] is False:
        panels.append("h-vs-e")
    panels += ["momenta", "phase", "effective-potential", "small-oscillations"]
    info = {
        "id": "playground",
        "title": "Your system",
        "section": "",
        "summary": "",
        "statement": "",
        "figure": "The system as declared, drawn at its initial state.",
        "panels": panels,
        "initial": {q: 1.0 for q in spec["coordinates"]},
        "t_end": 10.0,
    }
    return scene_page(doc, info, particles, simulation_methods(), spec.get("nonnegative") or ())


def warm_examples() -> threading.Thread:
    """Derive the examples in the background at start-up, so that the first reader of each is answered at once.

    The derivation runs in this process (a thread, not the worker pool: nothing waits on it)
    and its answer goes into the service's cache under the key the page asks for."""

    def warm() -> None:
        service = user_systems.service
        for example in EXAMPLES.values():
            spec = spec_of(form_of(example))
            key = user_systems.spec_key(spec)
            if service.derivations.get(key) is None:
                try:
                    service.derivations.put(key, user_systems.derive_job(spec))
                except Exception:  # noqa: BLE001 - warming is optional: the page derives on demand
                    return

    thread = threading.Thread(target=warm, name="warm-examples", daemon=True)
    thread.start()
    return thread


def _example_links() -> list[dict[str, str]]:
    from urllib.parse import urlencode

    return [
        {"title": title, "href": "/playground?" + urlencode(query_of(form_of(spec)), doseq=True)}
        for title, spec in EXAMPLES.items()
    ]


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


def _query_parameter(name: str, description: str, repeated: bool = False) -> dict[str, Any]:
    schema: dict[str, Any] = {"type": "array", "items": {"type": "string"}} if repeated else {"type": "string"}
    return {"name": name, "in": "query", "required": False, "description": description, "schema": schema}


# The form's fields as the query string carries them (read by read_form); documented so that
# generated requests (schemathesis) reach every one of them.
QUERY_PARAMETERS = [
    _query_parameter("q", "Generalized coordinates, separated by commas or spaces."),
    _query_parameter("form", f"Which form the mechanics is given in: one of {', '.join(FORMS)}."),
    _query_parameter("L", "The Lagrangian (form=lagrangian)."),
    _query_parameter("T", "The kinetic energy (form=energies)."),
    _query_parameter("U", "The potential energy (form=energies or particles)."),
    *(
        _query_parameter(key, f"Parameters: {what}, one per parameter.", repeated=True)
        for key, what in (("pn", "names"), ("pv", "values"), ("pu", "units"), ("plo", "lowest"), ("phi", "highest"))
    ),
    _query_parameter("m", "Particles: masses, one per particle.", repeated=True),
    *(_query_parameter(a, f"Particles: {a} positions, one per particle.", repeated=True) for a in AXES),
    _query_parameter("fq", "Generalized forces: the coordinate each acts on.", repeated=True),
    _query_parameter("fQ", "Generalized forces: the expressions, in the order of fq.", repeated=True),
    _query_parameter("nn", "Coordinates that are distances (never negative)."),
    _query_parameter("system", "The whole system as JSON in the shape of POST /api/derive (takes precedence)."),
    _query_parameter("new", "Present (any value) for an empty form."),
    SESSION_COOKIE,
]
HTML = {"text/html": {"schema": {"type": "string"}}}


@router.get(
    "/playground",
    response_class=HTMLResponse,
    summary="Type a system and see its derivation",
    description=(
        f"The playground page. The system comes from the query string (at most {MAX_QUERY} characters); a "
        "refusal is shown on the page next to the field it concerns, with status 422."
    ),
    openapi_extra={"parameters": QUERY_PARAMETERS},
    responses={
        200: {"description": "The page, with the derivation when a system was given.", "content": HTML},
        422: {"description": "The page, with the refusal shown next to the offending field.", "content": HTML},
        429: {"description": "You already have a derivation running; the page says so.", "content": HTML},
        503: {"description": "The server is busy; the page says so.", "content": HTML},
    },
)
async def playground(request: Request) -> Response:
    service = user_systems.service
    address = request.client.host if request.client else "unknown"
    session = service.gate.verify(request.cookies.get(COOKIE))
    minted = None if session else service.gate.mint(address)
    client = f"session:{session}" if session else f"address:{address}"
    error: FormError | None = None
    busy: Busy | None = None
    empty = False
    model = spec = None
    form = form_of(FORCED_SPRING)
    try:
        if len(str(request.url.query)) > MAX_QUERY:
            raise FormError(f"the system in the address is longer than {MAX_QUERY} characters", "f-form")
        if "new" in request.query_params:
            form = Form()  # an empty form to start from
        elif request.query_params:
            form = read_form(request.query_params)
        if not (form.coordinates or form.parameters or form.lagrangian or form.kinetic or form.particles):
            empty = True  # the page says what to enter
        else:
            spec = spec_of(form)
            doc = json.loads(await service.derive(spec, client, address))
            model = await run_in_threadpool(model_of, spec, doc)
    except FormError as exc:
        error = exc
    except InvalidSystem as exc:
        error = _located(form, exc.loc, str(exc), exc.start, exc.end)
    except JobFailed as exc:
        error = FormError(str(exc), "f-form")
    except Busy as exc:
        busy = exc
        error = FormError(f"{exc} (retry in {exc.retry_after} s)", "f-form")
    context = {
        "form": form,
        "error": error.view() if error else None,
        "empty": empty,
        "submitted": "new" not in request.query_params and bool(request.query_params),
        "model": model,
        "m": model,
        "system_json": json.dumps(spec or {}, separators=(",", ":")).replace("<", "\\u003c"),
        "examples": _example_links(),
        "forms": FORMS,
        "functions": list(FUNCTIONS),
    }
    status = 200 if error is None else (busy.status if busy else 422)
    response = templates.TemplateResponse(request, "playground.html", context, status_code=status)
    if busy:
        response.headers["Retry-After"] = str(busy.retry_after)
    if minted:
        response.set_cookie(COOKIE, minted, max_age=COOKIE_MAX_AGE, httponly=True, samesite="lax")
    return response
