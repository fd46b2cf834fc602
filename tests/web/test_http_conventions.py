"""The API's HTTP conventions (issue 45, item 8): RFC 9457 problems for every error, keeping the fields the pages
read; named operation ids; 415 for a body that is not JSON; Location on a 201; ETags and 304 on the cacheable
GETs; and an OpenAPI document that says all of it."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

PROBLEM = "application/problem+json"
SYSTEM = {
    "coordinates": ["x"],
    "parameters": [{"name": "k", "value": 2.0}],
    "kinetic": "x'^2/2",
    "potential": "k x^2/2",
}


def assert_problem(response, status: int) -> dict:
    assert response.status_code == status, response.text
    assert response.headers["content-type"].split(";")[0] == PROBLEM
    body = response.json()
    assert body["status"] == status and body["type"] == "about:blank" and body["title"] and body["detail"]
    return body


def test_a_refused_expression_is_a_problem_with_its_location_and_readings(client):
    body = assert_problem(client.post("/api/derive", json={**SYSTEM, "potential": "k x^2/2m"}), 422)
    # the fields the pages read (static/js/api.js: detail; the forms: loc, part, start, end) are all there
    assert (
        body["loc"] == ["body", "potential"] and body["part"] == "k x^2/2m" and (body["start"], body["end"]) == (0, 8)
    )
    assert body["readings"] == ["(k x^2/2) m", "k x^2/(2 m)"]
    assert body["detail"].startswith("potential: a factor after a quotient is ambiguous")


@pytest.mark.parametrize(
    ("method", "path", "kwargs", "status", "fields"),
    [
        ("post", "/api/derive", {"json": {"coordinates": []}}, 422, {"errors"}),  # the shape: FastAPI's validation
        ("post", "/api/derive", {"content": b"{", "headers": {"content-type": "application/json"}}, 422, {"errors"}),
        ("post", "/api/derive", {"content": b"[" * 40, "headers": {"content-type": "application/json"}}, 400, set()),
        ("post", "/api/derive", {"content": b"x" * 40000, "headers": {"content-type": "application/json"}}, 413, set()),
        ("get", "/api/scenes/nope/derivation", {}, 404, set()),
        ("get", "/api/no-such-address", {}, 404, set()),
        ("delete", "/api/scenes", {}, 405, set()),
        (
            "post",
            "/api/scenes/simple-pendulum/check",
            {"json": {"step": "kinetic", "answer": "m q"}},
            422,
            {"loc", "part"},
        ),
        (
            "post",
            "/api/typeset",
            {"json": {"text": "2^x^2", "step": "kinetic", "scene": "simple-pendulum"}},
            422,
            {"loc", "part", "start", "end", "readings"},
        ),
    ],
)
def test_every_error_is_a_problem(client, method, path, kwargs, status, fields):
    body = assert_problem(getattr(client, method)(path, **kwargs), status)
    assert fields <= set(body)


def test_a_class_route_without_a_key_is_a_problem_with_its_challenge(client, classes):
    code = client.post("/api/classes", json={"title": "Mechanics"}).json()["code"]
    response = client.get(f"/api/classes/{code}/summary")
    assert_problem(response, 401)
    assert response.headers["www-authenticate"] == "Bearer"


def test_a_busy_answer_keeps_retry_after(client, services):
    gate = services.users.gate
    tickets = [gate.admit(f"other{i}", f"10.0.0.{i}") for i in range(gate.capacity)]
    try:
        response = client.post("/api/derive", json={**SYSTEM, "potential": "k x^2/2 + 3 x"})
    finally:
        for ticket in tickets:
            ticket.release()
    body = assert_problem(response, 503)
    assert body["retry_after"] >= 1 and response.headers["retry-after"] == str(body["retry_after"])


@pytest.mark.parametrize(
    "media", ["application/x-www-form-urlencoded", "text/plain", "multipart/form-data; boundary=x"]
)
def test_a_body_that_is_not_json_gets_415(client, media):
    response = client.post("/api/derive", content=b"coordinates=x&kinetic=x", headers={"content-type": media})
    body = assert_problem(response, 415)
    assert "application/json" in body["detail"] and response.headers["accept-post"] == "application/json"


@pytest.mark.slow
def test_json_under_another_json_media_type_is_read(client):
    response = client.post(
        "/api/typeset",
        content=b'{"text": "m R^2", "step": "kinetic", "scene": "simple-pendulum"}',
        headers={"content-type": "application/json; charset=utf-8"},
    )
    assert response.status_code == 200, response.text


@pytest.mark.slow
def test_a_created_class_says_where_it_is(client, classes):
    response = client.post("/api/classes", json={"title": "Mechanics"})
    assert response.status_code == 201
    created = response.json()
    location = response.headers["location"]
    assert location == f"/api/classes/{created['code']}/summary"
    summary = client.get(location, headers={"Authorization": f"Bearer {created['teacher_key']}"})
    assert summary.status_code == 200


@pytest.mark.parametrize("path", ["/api/scenes", "/api/scenes/simple-pendulum/derivation", "/openapi.json"])
def test_cacheable_gets_have_etags_and_answer_304(client, path):
    first = client.get(path)
    tag = first.headers["etag"]
    assert first.status_code == 200 and re.fullmatch(r'W/"[0-9a-f]{32}"', tag)
    again = client.get(path)
    assert again.headers["etag"] == tag  # the same answer, the same tag
    unchanged = client.get(path, headers={"If-None-Match": tag})
    assert unchanged.status_code == 304 and unchanged.content == b"" and unchanged.headers["etag"] == tag
    listed = client.get(path, headers={"If-None-Match": f'"other", {tag.removeprefix("W/")}'})  # weak comparison
    assert listed.status_code == 304
    stale = client.get(path, headers={"If-None-Match": 'W/"0000"'})
    assert stale.status_code == 200 and stale.content == first.content


def test_a_compressed_answer_has_the_same_etag(client):
    plain = client.get("/api/scenes/double-pendulum/derivation", headers={"Accept-Encoding": "identity"})
    packed = client.get("/api/scenes/double-pendulum/derivation", headers={"Accept-Encoding": "gzip"})
    assert packed.headers.get("content-encoding") == "gzip" and packed.headers["etag"] == plain.headers["etag"]


@pytest.mark.slow
def test_class_answers_are_never_given_an_etag(client, classes):
    created = client.post("/api/classes", json={"title": "Mechanics"}).json()
    view = client.get(
        f"/api/classes/{created['code']}/summary", headers={"Authorization": f"Bearer {created['teacher_key']}"}
    )
    assert view.headers["cache-control"] == "no-store" and "etag" not in view.headers


def test_the_openapi_document_says_so(client):
    schema = client.get("/openapi.json").json()
    ids = [op["operationId"] for ops in schema["paths"].values() for op in ops.values()]
    assert len(ids) == len(set(ids))
    # named by their endpoints, not FastAPI's derive_system_api_derive_post
    assert not [i for i in ids if re.search(r"_(get|post|put|delete)$", i)], ids
    assert "derive_system" in ids and "typeset" in ids and "create_class" in ids
    assert "HTTPValidationError" not in schema["components"]["schemas"]
    problem = schema["components"]["schemas"]["Problem"]
    assert {"type", "title", "status", "detail"} <= set(problem["required"])
    for path, operations in schema["paths"].items():
        for method, operation in operations.items():
            for status, response in operation["responses"].items():
                if int(status) >= 400 and path != "/playground":  # a page: its errors are HTML pages
                    assert list(response["content"]) == [PROBLEM], (path, method, status)
                    assert response["content"][PROBLEM]["schema"] == {"$ref": "#/components/schemas/Problem"}
            if "requestBody" in operation:
                assert "415" in operation["responses"], (path, method)
    assert "Location" in schema["paths"]["/api/classes"]["post"]["responses"]["201"]["headers"]
    derivation = schema["paths"]["/api/scenes/{scene_id}/derivation"]["get"]
    assert "ETag" in derivation["responses"]["200"]["headers"] and "304" in derivation["responses"]
    assert any(p["name"] == "If-None-Match" for p in derivation["parameters"])


def test_the_pages_read_the_problem_fields_they_always_read():
    # the one fetch helper of the pages reads detail (and hands the whole body on); the problem keeps it
    source = Path("static/js/api.js").read_text()
    assert "answer.detail" in source and "response.json()" in source
