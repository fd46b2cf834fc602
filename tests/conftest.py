"""Shared fixtures: an in-process client for the ASGI app."""

import os

import pytest
from fastapi.testclient import TestClient
from hypothesis import settings

# the playground's examples are derived in the background by a serving process, not by the tests
os.environ.setdefault("LAGRANGE_WARM_EXAMPLES", "0")

from app.main import app  # noqa: E402

# In CI the property tests draw the same examples on every run, so a submission's result does not
# depend on luck; on a developer's machine they search afresh each time (and so keep finding new cases,
# which then become explicit @example regressions).
settings.register_profile("ci", derandomize=True)
if os.environ.get("CI"):
    settings.load_profile("ci")


@pytest.fixture(scope="session")
def client():
    with TestClient(app) as c:
        yield c
