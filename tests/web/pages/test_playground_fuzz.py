"""Hypothesis fuzzing of the playground's query string: every query answers a page, never a 5xx."""

import json

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from app.web.pages.playground import QUERY_PARAMETERS

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

SETTINGS = settings(max_examples=120, deadline=None, suppress_health_check=list(HealthCheck))
KEYS = [p["name"] for p in QUERY_PARAMETERS if p["in"] == "query"]
PAGE_STATUSES = {200, 422, 429, 503}

texts = st.one_of(
    st.text(max_size=40),
    st.sampled_from(["x", "x_dot**2/2 - x**2/2", "9**+-80**+-19**-33", "asin(2)", "k\n", "exp(99*log(x))", ""]),
)
json_values = st.recursive(
    st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=False), st.text(max_size=10)),
    lambda children: st.one_of(
        st.lists(children, max_size=4), st.dictionaries(st.text(max_size=8), children, max_size=4)
    ),
    max_leaves=20,
)
queries = st.dictionaries(
    st.sampled_from(KEYS),
    st.one_of(texts, st.lists(texts, max_size=3), json_values.map(json.dumps)),
    max_size=8,
)


@SETTINGS
@given(queries)
@example({"system": "[" * 5000 + "]" * 5000})
@example({"system": '{"coordinates": ' + "[" * 2000 + "]" * 2000 + "}"})
@example({"q": "x", "form": "lagrangian", "L": "x_dot**2/2 - asin(2 + x - x)"})
@example({"q": "x", "pn": "k\n", "form": "lagrangian", "L": "x_dot**2/2"})
def test_every_query_answers_a_page(client, query):
    client.cookies.clear()
    response = client.get("/playground", params=query)
    assert response.status_code in PAGE_STATUSES, (query, response.status_code, response.text[:300])
    assert response.headers["content-type"].startswith("text/html")
