"""One mapping from the kinds of failure to responses, the same for the API and the pages.

The user-systems service is replaced through the app's dependencies by one that
fails with each kind in turn; the JSON route and the HTML page must answer with
the same status and Retry-After.
"""

from __future__ import annotations

import html
import json

import pytest

from app.errors import OverCapacity, Refused, TooMuchWork, UnknownScene, WorkerFailed
from app.main import app
from app.service.users.user_checks import InvalidSystem, TooCostly
from app.web.api.deps import Client, client_identity, user_systems_service
from app.web.api.errors import problem
from app.web.api.examples_user import SPINNING_HOOP


class Failing:
    """A user-systems service whose every derivation fails with ``exc``."""

    def __init__(self, exc: Exception):
        self.exc = exc
        self.derivations: dict = {}  # nothing derived before: the page's first stage is a job of its own
        self.derive_seconds = 1.0

    async def derive(self, spec, client, address):
        raise self.exc

    async def run_job(self, *args, **kwargs):  # the first stage's job (app/service/users/staged.py)
        raise self.exc


# (failure, status, Retry-After, fields of the JSON body)
KINDS = {
    "refused": (
        InvalidSystem("coordinates[0]: 'x y' is not a name", ("coordinates", 0), "x y", 0, 3),
        422,
        None,
        {"loc": ["body", "coordinates", "0"], "part": "x y", "start": 0, "end": 3},
    ),
    "too-much-work": (TooCostly("lagrangian: deriving this system takes longer", ("lagrangian",)), 422, None, {}),
    "busy-client": (OverCapacity("you already have a derivation running", 7), 429, "7", {"retry_after": 7}),
    "busy-server": (OverCapacity("the server is busy", 9, whole_server=True), 503, "9", {"retry_after": 9}),
    "worker-timeout": (WorkerFailed("the work took longer than the limit", "timeout"), 422, None, {"kind": "timeout"}),
    "worker-unavailable": (WorkerFailed("no worker could be started", "unavailable"), 503, "1", {"retry_after": 1}),
}


@pytest.fixture
def failing(client):
    def install(exc: Exception) -> None:
        app.dependency_overrides[user_systems_service] = lambda: Failing(exc)
        app.dependency_overrides[client_identity] = lambda: Client("address:test", "test")

    yield install
    app.dependency_overrides.clear()


@pytest.mark.parametrize("kind", KINDS)
def test_the_api_answers_each_kind_of_failure_as_mapped(client, failing, kind):
    exc, status, retry_after, fields = KINDS[kind]
    failing(exc)
    answer = client.post("/api/derive", json=SPINNING_HOOP)
    assert answer.status_code == status
    assert answer.headers.get("Retry-After") == retry_after
    body = answer.json()
    assert body["detail"] == str(exc)
    assert fields.items() <= body.items()


@pytest.mark.parametrize("stage", [None, "whole"])
@pytest.mark.parametrize("kind", KINDS)
def test_the_playground_page_answers_each_kind_of_failure_as_the_api_does(client, failing, kind, stage):
    exc, status, retry_after, _ = KINDS[kind]
    failing(exc)
    params = {"system": json.dumps(SPINNING_HOOP), **({"stage": stage} if stage else {})}
    page = client.get("/playground", params=params)
    assert page.status_code == status
    assert page.headers.get("Retry-After") == retry_after
    assert page.headers["content-type"].startswith("text/html")
    # the page names the place in words ("Coordinate 1", not "coordinates[0]") and then says what the API says
    message = str(exc).rpartition(": ")[2]
    assert html.escape(message, quote=False) in page.text.replace("&#39;", "'")
    assert "coordinates[0]" not in page.text


def test_an_unknown_scene_is_404_from_the_api_and_the_page(client):
    api = client.get("/api/scenes/nope/derivation")
    page = client.get("/scenes/nope")
    assert api.status_code == page.status_code == 404
    assert "simple-pendulum" in api.json()["detail"]
    assert page.headers["content-type"].startswith("text/html") and "simple-pendulum" in page.text


def test_every_kind_maps_to_one_response():
    assert problem(Refused("bad")).body == {"detail": "bad", "part": ""}  # not located: no loc
    assert problem(TooMuchWork("too long", "t_end")).status == 422
    assert problem(UnknownScene("x", ("a", "b"))).status == 404
    with pytest.raises(TypeError):
        problem(RuntimeError("not a kind of failure"))
