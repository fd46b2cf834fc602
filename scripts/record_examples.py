"""Record the user-system API's documented examples: run the API on them, write what it answers.

Usage: python scripts/record_examples.py   (writes app/web/api/examples/user_api.json;
tests/web/api/test_api_user.py fails while the file is stale).  It lives outside the
app, so no app module imports the app it runs.
"""

from __future__ import annotations

import json
from typing import Any

from fastapi.testclient import TestClient

from app.main import app
from app.service.runtime.fairness import COOKIE
from app.service.users.user_systems import UserSystems
from app.settings import Settings
from app.web.api.deps import user_systems_service
from app.web.api.examples_user import (
    EXAMPLES_FILE,
    FORCED_SPRING,
    JSON,
    LONG_CHAIN,
    REFUSED_REQUESTS,
    SIMULATE_EXAMPLES,
    SIMULATE_REFUSED,
    SUMMARIES,
    TIMEOUT_SECONDS,
    UNCACHED_DOUBLE_PENDULUM,
    UNREADABLE,
)
from app.web.api.limits import MAX_BODY_BYTES


def record() -> dict[str, Any]:
    """Run the API on the example requests and collect what it answers."""
    errors: dict[str, dict[str, Any]] = {status: {} for status in SUMMARIES}
    with TestClient(app) as client:
        service = client.app_state["services"].users
        derived = client.post("/api/derive", json=FORCED_SPRING).json()
        simulated = client.post("/api/simulate", json=SIMULATE_EXAMPLES["forced-spring"]["value"]).json()
        errors["422"]["simulate"] = client.post("/api/simulate", json=SIMULATE_REFUSED["value"]).json()
        for name, example in REFUSED_REQUESTS.items():
            errors["422"][name] = client.post("/api/derive", json=example["value"]).json()
        errors["400"]["unreadable"] = client.post("/api/derive", content=UNREADABLE, headers=JSON).json()
        errors["413"]["too-large"] = client.post(
            "/api/derive", content=b" " * (MAX_BODY_BYTES + 1), headers=JSON
        ).json()
        errors["422"]["timeout"] = answer_with_time_limit(client, TIMEOUT_SECONDS)
        # a session of its own (any answer sets its cookie), whose one job is still running
        client.cookies.clear()
        client.post("/api/derive", json=FORCED_SPRING)  # cached: answered at once
        session = service.gate.verify(client.cookies.get(COOKIE))
        ticket = service.gate.admit(service.gate.key(session, "testclient"), "testclient")
        try:
            errors["429"]["one-at-a-time"] = refused(client, 429)
        finally:
            ticket.release()
        tickets = [service.gate.admit(f"filler{i}", f"filler{i}") for i in range(service.gate.capacity)]
        try:
            errors["503"]["busy"] = refused(client, 503)
        finally:
            for ticket in tickets:
                ticket.release()
    return {"derive": derived, "simulate": simulated, "errors": errors}


def refused(client: TestClient, status: int) -> dict[str, Any]:
    """The refusal of a derivation no cache holds (a cached answer is served before the fair-share gate)."""
    response = client.post("/api/derive", json=UNCACHED_DOUBLE_PENDULUM)
    if response.status_code != status:
        raise RuntimeError(
            f"expected {status} for the gate's example, got {response.status_code}: {response.text[:200]}"
        )
    return response.json()


def answer_with_time_limit(client: TestClient, seconds: float) -> dict[str, Any]:
    """The answer to deriving a four-link chain under a short time limit (a service of its own: no cached result)."""
    short = UserSystems(client.app_state["services"].pool, config=Settings(derive_seconds=seconds))
    app.dependency_overrides[user_systems_service] = lambda: short
    try:
        answer = client.post("/api/derive", json=LONG_CHAIN).json()
    finally:
        app.dependency_overrides.pop(user_systems_service)
    if answer.get("kind") != "timeout":
        raise RuntimeError(f"expected the time limit's refusal, got {str(answer)[:200]}")
    return answer


if __name__ == "__main__":
    EXAMPLES_FILE.parent.mkdir(exist_ok=True)
    EXAMPLES_FILE.write_text(json.dumps(record(), indent=1, ensure_ascii=False) + "\n")
    print(f"wrote {EXAMPLES_FILE}")
