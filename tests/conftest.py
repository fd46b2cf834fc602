"""Shared fixtures: an in-process client for the ASGI app."""

import os
import re

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


@pytest.fixture
def fresh_mint_budget():
    """Sessions minted by a gate of their own, so the per-address budget (mint_per_minute) starts untouched.

    Every in-process request comes from the address "testclient", and many tests clear their cookies: how much
    of the shared gate's budget is left would depend on how many tests ran in the last minute, and how fast.
    The gate signs with the same secret as the app's, so the sessions it mints verify everywhere.
    """
    from app.service.runtime.fairness import Fairness
    from app.web.api.deps import fairness_gate

    gate = Fairness(capacity=4)
    app.dependency_overrides[fairness_gate] = lambda: gate
    yield gate
    app.dependency_overrides.pop(fairness_gate, None)


# a module's own marks near its top: ``pytestmark = pytest.mark.slow`` or a list of marks, whose lines after the
# first are indented or close the list
MODULE_MARKS = re.compile(r"^pytestmark = (.*(?:\n[ )\]].*)*)", re.MULTILINE)


def excluded_marks(markexpr: str) -> set[str]:
    """The marks a ``-m`` expression of the form "not a and not b …" leaves out (none for any other form)."""
    terms = [term.strip() for term in markexpr.split(" and ")] if markexpr else []
    if not terms or not all(re.fullmatch(r"not \w+", term) for term in terms):
        return set()
    return {term.split()[1] for term in terms}


def pytest_ignore_collect(collection_path, config):
    """A module whose own marks the ``-m`` expression leaves out is not even imported: each of its tests would be
    deselected, and importing the heavy ones took most of the fast tier's time (scripts/test-fast.sh)."""
    if collection_path.suffix != ".py" or not collection_path.name.startswith("test_"):
        return None
    excluded = excluded_marks(config.getoption("markexpr", ""))
    if not excluded:
        return None
    found = MODULE_MARKS.search(collection_path.read_text(encoding="utf-8"))
    marks = set(re.findall(r"pytest\.mark\.(\w+)", found.group(1))) if found else set()
    return True if marks & excluded else None
