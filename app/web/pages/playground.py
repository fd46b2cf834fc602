"""/playground: a student types a system, sees its derivation step by step, then simulates it.

The page is a plain GET form, so the system lives in the query string and every
derivation has a shareable address (``/playground?q=x&form=energies&T=...``);
``?system=<JSON>`` in the API's request shape works too.  The route derives
through the same service as POST /api/derive (checks, cache, fair share, worker
pool: no SymPy here) and renders the derivation with the scene page's markup.
A refusal is shown next to the field it concerns, with the offending part marked.
The derivation comes in two stages (app/service/users/staged.py, app/web/pages/playground_stages.py): unless the
whole document is ready, the page answers with the equations and accelerations and the page's script
fetches the same address with ``stage=whole`` for the rest.
The simulation runs in the browser against POST /api/simulate (static/js/playground.js).
"""

from __future__ import annotations

import json
import threading
from collections.abc import Callable
from typing import Any
from urllib.parse import urlencode

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response
from starlette.concurrency import run_in_threadpool

from app.engine.document.model import Document, FirstStage
from app.engine.parser.parse import FUNCTIONS
from app.engine.parser.user_system import UserSystem
from app.numerics.methods import CHOICES
from app.service.answers import examples_cache
from app.service.runtime.cache import BytesCache
from app.service.users.staged import equations_or_whole
from app.service.users.user_checks import InvalidSystem, checked, spec_key
from app.service.users.user_jobs import derive_job
from app.service.users.user_systems import UserSystems
from app.viz.user_page import model_of
from app.web.api.deps import ClientDep, UserSystemsDep
from app.web.api.errors import KINDS, REFUSED, Failure, held, problem
from app.web.api.examples_user import DOUBLE_PENDULUM, FORCED_SPRING, RELATIVISTIC_OSCILLATOR, SPINNING_HOOP
from app.web.pages.playground_form import (
    AXES,
    FORMS,
    Form,
    FormError,
    form_of,
    located_error,
    query_of,
    read_form,
    spec_of,
)
from app.web.pages.playground_stages import STAGE_PARAMETER, first_view, whole_href
from app.web.rendering.templating import templates
from app.web.schemas.common import SESSION_COOKIE

router = APIRouter(tags=["pages"])

MAX_QUERY = 16_000  # characters of query string: far more than any system the form can hold
EXAMPLES = {
    "Forced, damped spring (T, U and a force)": FORCED_SPRING,
    "Double pendulum (particles)": DOUBLE_PENDULUM,
    "Bead on a spinning hoop (L alone)": SPINNING_HOOP,
    "Relativistic oscillator (L not quadratic in ẋ)": RELATIVISTIC_OSCILLATOR,
}


def example_derivations(
    cache: BytesCache | None = None, derive: Callable[[UserSystem], bytes] = derive_job
) -> dict[str, bytes]:
    """Each example's derivation document by its cache key: from ``cache`` (the examples' documents on disk, which
    set-up fills: python -m app.web.warm; app/service/answers.py), else derived here by ``derive`` and stored."""
    cache = cache or examples_cache()
    found = {}
    for example in EXAMPLES.values():
        user = checked(spec_of(form_of(example)))
        found[spec_key(user)] = cache.get(spec_key(user), lambda user=user: derive(user))
    return found


def load_examples(
    service: UserSystems, cache: BytesCache | None = None, derive: Callable[[UserSystem], bytes] = derive_job
) -> None:
    """Put each example's derivation into the service's cache (``example_derivations``)."""
    for key, document in example_derivations(cache, derive).items():
        if service.derivations.get(key) is None:
            service.derivations.put(key, document)


def warm_examples(
    service: UserSystems,
    cache: BytesCache | None = None,
    after: threading.Thread | None = None,
    load: Callable[[UserSystems, BytesCache | None], None] = load_examples,
) -> threading.Thread:
    """Load the examples in the background at start-up, so that the first reader of each is answered at once.

    A derivation the disk cache lacks runs in this process (a thread, not the worker pool: nothing
    waits on it), after ``after`` (the scenes' warm-up) has finished, so it never slows a first
    simulation down; its answer goes into the service's cache under the key the page asks for."""

    def warm() -> None:
        if after is not None:
            after.join()
        try:
            load(service, cache)
        except Exception:  # noqa: BLE001 - warming is optional: the page derives on demand
            return

    thread = threading.Thread(target=warm, name="warm-examples", daemon=True)
    thread.start()
    return thread


# Where each of the form's texts is shown (the ids of playground_form.field_id), for a refusal of its characters.
_SCALAR_FIELDS = {"coordinates": "f-coordinates", "lagrangian": "f-L", "kinetic": "f-T", "potential": "f-U",
                  "nonnegative": "f-nn", "form": "f-form"}  # fmt: skip
_ROW_FIELDS = {"parameters": "f-param-{i}-{key}", "particles": "f-particle-{i}-{key}", "forces": "f-force-{i}-{key}"}


def _lone_surrogates(text: str) -> bool:
    return any("\ud800" <= c <= "\udfff" for c in text)


def _without_surrogates(text: str) -> str:
    """The text with each lone surrogate (a JSON escape such as \\ud800 decodes to one) replaced by U+FFFD."""
    return "".join("\ufffd" if "\ud800" <= c <= "\udfff" else c for c in text)


def unencodable(form: Form) -> FormError | None:
    """A refusal of the first text in the form that holds a lone surrogate, which no page can encode; the
    form is mended in place (U+FFFD for each), so the page that shows the refusal can show the form too."""
    found: FormError | None = None
    for name, field_id in _SCALAR_FIELDS.items():
        text = getattr(form, name)
        if isinstance(text, str) and _lone_surrogates(text):
            setattr(form, name, _without_surrogates(text))
            found = found or FormError(_SURROGATE_MESSAGE, field_id)
    for name, pattern in _ROW_FIELDS.items():
        for i, row in enumerate(getattr(form, name)):
            for key, text in row.items():
                if isinstance(text, str) and _lone_surrogates(text):
                    row[key] = _without_surrogates(text)
                    found = found or FormError(_SURROGATE_MESSAGE, pattern.format(i=i, key=key))
    return found


_SURROGATE_MESSAGE = (
    "the system in the address holds a lone surrogate escape (\\ud800 to \\udfff without its pair), "
    "which is not a character; it is shown here as \ufffd: type the character itself or remove it"
)


def _example_links() -> list[dict[str, str]]:
    return [
        {"title": title, "href": "/playground?" + urlencode(query_of(form_of(spec)), doseq=True)}
        for title, spec in EXAMPLES.items()
    ]


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
    _query_parameter("nn", "Coordinates that are distances (never negative): a run ends where one reaches 0."),
    _query_parameter("system", "The whole system as JSON in the shape of POST /api/derive (takes precedence)."),
    _query_parameter("new", "Present (any value) for an empty form."),
    STAGE_PARAMETER,
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
async def playground(request: Request, client: ClientDep, users: UserSystemsDep) -> Response:
    error: FormError | None = None
    failed: Failure | None = None
    empty = False
    model = user = first = None
    form = form_of(FORCED_SPRING)
    try:
        if len(str(request.url.query)) > MAX_QUERY:
            raise FormError(f"the system in the address is longer than {MAX_QUERY} characters", "f-form")
        if (stage := request.query_params.get("stage")) not in (None, "whole"):
            raise FormError(f"stage: {stage[:20]!r} is not a stage; the only one is 'whole' (or leave it out)", "f-form")
        if "new" in request.query_params:
            form = Form()  # an empty form to start from
        elif request.query_params:
            form = read_form(request.query_params)
            if (mended := unencodable(form)) is not None:
                raise mended
        if not (form.coordinates or form.parameters or form.lagrangian or form.kinetic or form.particles):
            empty = True  # the page says what to enter
        else:
            user = checked(spec_of(form))
            if request.query_params.get("stage") == "whole":
                whole = await users.derive(user, client.key, client.address)
                doc = await run_in_threadpool(Document.model_validate_json, whole)
            else:  # the equations first, unless the whole document is ready (the page asks for the rest)
                doc = await equations_or_whole(users, user, client.key, client.address)
            if isinstance(doc, FirstStage):
                # the rest is asked for with the form's own query (the default system's page has none)
                first = first_view(doc, whole_href(urlencode(query_of(form), doseq=True)), spec_key(user))
            else:
                model = await run_in_threadpool(model_of, user, doc, CHOICES)
    except FormError as exc:
        error = exc
    except KINDS as exc:
        await held(exc)
        failed = problem(exc)
        if isinstance(exc, InvalidSystem):
            error = located_error(form, exc.loc, str(exc), exc.start, exc.end)
        elif "retry_after" in failed.body:
            error = FormError(f"{exc} (retry in {failed.body['retry_after']} s)", "f-form")
        else:
            error = FormError(str(exc), "f-form")
    context = {
        "form": form,
        "error": error.view() if error else None,
        "empty": empty,
        "submitted": "new" not in request.query_params and bool(request.query_params),
        "model": model,
        "m": model,
        "first": first,
        "system_json": json.dumps(user.as_json() if user else {}, separators=(",", ":")).replace("<", "\\u003c"),
        "examples": _example_links(),
        "forms": FORMS,
        "functions": list(FUNCTIONS),
    }
    # the page's own mistakes (FormError) are refusals too; the rest answer as the API does
    status = failed.status if failed else (REFUSED if error else 200)
    headers = failed.headers if failed else {}
    response = templates.TemplateResponse(request, "playground.html", context, status_code=status, headers=headers)
    return client.keep(response)
