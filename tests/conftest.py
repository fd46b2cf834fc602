"""Shared fixtures: an in-process client for the ASGI app."""

import os

# No warm-up thread in tests: it would compile and derive beside every test.  Set before the app
# (and its settings) are imported; the tests that need the start-up behaviour set it up themselves.
os.environ["LAGRANGE_WARM"] = "0"

import pytest  # noqa: E402
from fastapi.testclient import TestClient  # noqa: E402
from hypothesis import settings  # noqa: E402

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
