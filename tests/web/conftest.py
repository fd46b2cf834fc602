"""Fixtures of the web tests."""

from collections.abc import Callable, Iterator
from typing import Any

import pytest

from app.main import app
from app.service.services import Services
from app.web.api.classes import classroom as classroom_dep
from tests.classes import BACKENDS, classroom
from tests.postgres import postgres_server  # noqa: F401 - the session fixture of classes_on_both


@pytest.fixture
def services(client) -> Services:
    """The services the app's lifespan started for the session's client."""
    return client.app_state["services"]


@pytest.fixture
def override() -> Iterator[Callable[[Callable[..., Any], Any], Any]]:
    """``override(dependency, value)``: the routes are given ``value`` for ``dependency`` (a function of
    app/web/api/deps.py) during the test, through ``app.dependency_overrides``, instead of a patched module."""
    given: list[Callable[..., Any]] = []

    def give(dependency: Callable[..., Any], value: Any) -> Any:
        app.dependency_overrides[dependency] = lambda: value
        given.append(dependency)
        return value

    yield give
    for dependency in given:
        app.dependency_overrides.pop(dependency, None)


def _served(room):
    """The routes are given ``room`` for the classes during the test; it stops after."""
    app.dependency_overrides[classroom_dep] = lambda: room
    yield room
    app.dependency_overrides.pop(classroom_dep, None)
    room.stop()


@pytest.fixture
def classes(services, tmp_path):
    """The classes in a SQLite database of the test's own (a module testing both backends asks for
    ``classes_on_both`` under this name)."""
    yield from _served(classroom(services.checking, "sqlite", tmp_path, None))


@pytest.fixture(params=BACKENDS)
def classes_on_both(request, services, tmp_path):
    """The classes in a database of the test's own, once on SQLite and once on PostgreSQL."""
    postgres = request.getfixturevalue("postgres_server") if request.param == "postgresql" else None
    yield from _served(classroom(services.checking, request.param, tmp_path, postgres))
