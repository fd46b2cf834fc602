"""The OpenAPI document as the API answers: its HTTP conventions written once, over what FastAPI generates.

* every operation is named by its endpoint (``derive_system``, not ``derive_system_api_derive_post``);
* every error response is an RFC 9457 problem, ``application/problem+json`` with the one ``Problem`` schema
  (app/web/schemas/common.py), where FastAPI would document its own ``HTTPValidationError`` (a ``detail`` array)
  that the handler of app/web/api/errors.py never sends;
* an operation with a request body may answer 415 (a body that is not JSON: app/web/api/limits.py);
* a 201 says where the new resource is (``Location``);
* the cacheable GETs (app/web/http/etags.py) send an ``ETag`` and answer ``If-None-Match`` with a 304.
"""

from __future__ import annotations

from copy import deepcopy
from typing import Any

from fastapi import FastAPI
from fastapi.openapi.utils import get_openapi
from fastapi.routing import APIRoute

from app.web.api.errors import PROBLEM_JSON, problem_body
from app.web.api.limits import NOT_JSON
from app.web.http.etags import cacheable

PROBLEM_REF = {"$ref": "#/components/schemas/Problem"}
# FastAPI's own shapes of a validation error, which the API never sends (app/web/api/errors.py sends a Problem)
UNSENT = ("HTTPValidationError", "ValidationError")
ETAG = {"description": "The answer's version: send it back in If-None-Match.", "schema": {"type": "string"}}


def operation_id(route: APIRoute) -> str:
    """An operation's id: its endpoint's name (one per operation; tests/web/test_openapi.py checks)."""
    return route.name


def _as_problem(content: dict[str, Any]) -> dict[str, Any]:
    """An error response's content as a problem, keeping its examples (completed with type, title and status)."""
    found = next(iter(content.values()), {}) if content else {}
    shown: dict[str, Any] = {"schema": PROBLEM_REF}
    if "example" in found and isinstance(found["example"], dict) and "detail" in found["example"]:
        shown["example"] = found["example"]
    if "examples" in found:
        shown["examples"] = deepcopy(found["examples"])
    return {PROBLEM_JSON: shown}


def _completed(example: dict[str, Any], status: int) -> dict[str, Any]:
    """An example error body as the problem the API sends (type, title and status first)."""
    fields = {k: v for k, v in example.items() if k not in ("type", "title", "status", "detail")}
    return problem_body(status, example["detail"], **fields)


def _complete_examples(content: dict[str, Any], status: int) -> None:
    shown = content[PROBLEM_JSON]
    if "example" in shown:
        shown["example"] = _completed(shown["example"], status)
    for example in shown.get("examples", {}).values():
        value = example.get("value")
        if isinstance(value, dict) and "detail" in value:
            example["value"] = _completed(value, status)


def conventions(schema: dict[str, Any]) -> dict[str, Any]:
    """The document with the conventions above applied (in place), and returned."""
    components = schema.setdefault("components", {}).setdefault("schemas", {})
    for path, operations in schema.get("paths", {}).items():
        for method, operation in operations.items():
            responses = operation.setdefault("responses", {})
            for code, response in responses.items():
                content = response.get("content", {})
                if code.isdigit() and int(code) >= 400 and (not content or "application/json" in content):
                    # (a page's errors are pages: their HTML is left as documented)
                    response["content"] = _as_problem(content)
                    _complete_examples(response["content"], int(code))
            if "requestBody" in operation:
                unsupported = {"schema": PROBLEM_REF, "example": problem_body(415, NOT_JSON)}
                responses.setdefault(
                    "415", {"description": f"Not JSON: {NOT_JSON}.", "content": {PROBLEM_JSON: unsupported}}
                )
            if "201" in responses:
                responses["201"].setdefault("headers", {})["Location"] = {
                    "description": "The address of what was created.",
                    "schema": {"type": "string"},
                }
            if method == "get" and cacheable(path):
                responses["200"].setdefault("headers", {})["ETag"] = ETAG
                responses["304"] = {
                    "description": "Not modified: the ETag sent in If-None-Match is still current.",
                    "headers": {"ETag": ETAG},
                }
                operation.setdefault("parameters", []).append(
                    {
                        "name": "If-None-Match",
                        "in": "header",
                        "required": False,
                        "schema": {"type": "string"},
                        "description": "ETags of answers you hold: a 304 without a body when one is still current.",
                    }
                )
    for name in UNSENT:
        components.pop(name, None)
    return schema


def install(app: FastAPI) -> None:
    """Serve the document with the conventions (built once, on the first request for it)."""

    def document() -> dict[str, Any]:
        if app.openapi_schema is None:
            app.openapi_schema = conventions(
                get_openapi(
                    title=app.title,
                    version=app.version,
                    summary=app.summary,
                    description=app.description,
                    routes=app.routes,
                    tags=app.openapi_tags,
                    servers=app.servers,
                )
            )
        return app.openapi_schema

    app.openapi = document  # type: ignore[method-assign]
