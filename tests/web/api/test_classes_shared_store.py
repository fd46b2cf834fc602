"""The classes' joins counted by every replica together, through a shared Redis (app/service/classroom/shared_rates.py).

Two ``Classroom`` objects on one database stand for two replicas behind a round-robin balancer: each
request goes to the other one. With the store, the class's limit holds for the two together; without it,
each replica lets the limit through again (the reason the store exists).
"""

from __future__ import annotations

import itertools

from app.main import app
from app.web.api.classes import classroom as classroom_dep
from tests.classes import classroom
from tests.redis import redis_server  # noqa: F401 - the session fixture

LIMIT = 4


def joins_through_two_replicas(client, services, tmp_path, store_url: str | None) -> list[int]:
    """The statuses of LIMIT + 2 joins to one class, sent alternately to two replicas by one session (whose own
    limit is far above), so that only the class's window can refuse."""
    rooms = [
        classroom(
            services.checking,
            "sqlite",
            tmp_path,
            None,
            class_joins_per_minute=LIMIT,
            client_joins_per_minute=100,
            shared_store_url=store_url,
        )
        for _ in range(2)
    ]
    turn = itertools.cycle(rooms)
    app.dependency_overrides[classroom_dep] = lambda: next(turn)
    try:
        code = client.post("/api/classes", json={"title": "Mechanics"}).json()["code"]
        client.get("/api/scenes")  # a session cookie: the joins are one client's, not an address's
        statuses = []
        for i in range(LIMIT + 2):
            r = client.post(f"/api/classes/{code}/join", json={"name": f"Student {i}"})
            statuses.append(r.status_code)
            if r.status_code == 429:
                assert 1 <= int(r.headers["retry-after"]) <= 60 and "joins to this class" in r.json()["detail"]
        return statuses
    finally:
        app.dependency_overrides.pop(classroom_dep, None)
        for room in rooms:
            if room.store is not None:
                client.portal.call(room.store.close)
            room.stop()
        client.cookies.clear()


def test_a_class_limit_holds_across_replicas(client, services, tmp_path, request, fresh_mint_budget):
    statuses = joins_through_two_replicas(client, services, tmp_path, request.getfixturevalue("redis_server"))
    assert statuses == [200] * LIMIT + [429, 429]


def test_without_the_store_each_replica_counts_alone(client, services, tmp_path, fresh_mint_budget):
    # the contrast: the fifth and sixth joins pass, since each replica has seen only three
    assert joins_through_two_replicas(client, services, tmp_path, None) == [200] * (LIMIT + 2)
