"""Fixtures of the web tests."""

import pytest

from app.service.services import Services


@pytest.fixture
def services(client) -> Services:
    """The services the app's lifespan started for the session's client."""
    return client.app_state["services"]
