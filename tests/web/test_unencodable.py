"""Lone surrogates (``\\ud800`` in a JSON escape) in text a page echoes: a refusal with a page, never a 500."""

from __future__ import annotations

import json

import pytest
from fastapi import FastAPI
from fastapi.responses import HTMLResponse
from fastapi.testclient import TestClient

from app.web.api import errors

SYSTEMS = {
    "lagrangian": ('{"coordinates": ["x"], "lagrangian": "x_dot**2/2 - x**2/2\\ud800"}', "f-L"),
    "coordinate": ('{"coordinates": ["x\\udfff"], "lagrangian": "x_dot**2"}', "f-coordinates"),
    "unit": (
        '{"coordinates": ["x"], "lagrangian": "x_dot**2", "parameters": [{"name": "a", "unit": "\\ud800"}]}',
        "f-param-0-unit",
    ),
    "mass": ('{"coordinates": ["x"], "particles": [{"mass": "\\ud83d", "position": ["x", "0"]}]}', "f-particle-0-mass"),
    "force": ('{"coordinates": ["x"], "lagrangian": "x_dot**2", "forces": {"x": "\\udc00"}}', "f-force-0-expression"),
}


@pytest.mark.parametrize("name", SYSTEMS)
def test_a_lone_surrogate_in_the_playgrounds_system_is_refused_with_a_page(client, name):
    system, field = SYSTEMS[name]
    assert any("\ud800" <= c <= "\udfff" for c in json.dumps(json.loads(system), ensure_ascii=False))
    response = client.get("/playground", params={"system": system})
    assert response.status_code == 422 and response.headers["content-type"].startswith("text/html")
    assert "lone surrogate" in response.text
    assert f'data-field="{field}"' in response.text  # the refusal names the field that holds it
    assert "\ufffd" in response.text  # the form is shown again, mended


def test_a_surrogate_pair_is_a_character_and_is_served(client):
    system = '{"coordinates": ["x"], "lagrangian": "x_dot**2/2 - x**2/2", "parameters": [{"name": "a", "unit": "\\ud83d\\ude00"}]}'
    response = client.get("/playground", params={"system": system})
    assert response.status_code == 200 and "\U0001f600" in response.text


def test_the_api_refuses_the_same_input_with_a_422(client):
    body = '{"coordinates": ["x"], "lagrangian": "x_dot**2/2 - x**2/2\\ud800"}'
    response = client.post("/api/derive", content=body, headers={"content-type": "application/json"})
    assert response.status_code == 422


def test_any_page_that_cannot_encode_what_it_echoes_answers_422():
    app = FastAPI()
    errors.install(app)

    @app.get("/page")
    def page(text: str) -> HTMLResponse:
        return HTMLResponse(json.loads(text))  # encodes at once: a lone surrogate raises UnicodeEncodeError

    @app.get("/api/thing")
    def thing(text: str) -> HTMLResponse:
        return HTMLResponse(json.loads(text))

    with TestClient(app) as local:
        response = local.get("/page", params={"text": '"\\ud800"'})
        assert response.status_code == 422 and response.headers["content-type"].startswith("text/html")
        assert "lone surrogate" in response.text
        answer = local.get("/api/thing", params={"text": '"\\ud800"'})
        assert answer.status_code == 422 and "lone surrogate" in answer.json()["detail"]
