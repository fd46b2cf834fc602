"""Security headers on every response, pages, API answers, errors and static files alike."""

import pytest

from app.web.http.headers import CSP


@pytest.mark.slow
@pytest.mark.parametrize(
    ("method", "path", "status"),
    [
        ("get", "/", 200),
        ("get", "/docs", 200),
        ("get", "/healthz", 200),
        ("get", "/api/scenes", 200),
        ("get", "/no-such-page", 404),
        ("get", "/static/js/api-docs.js", 200),
        ("post", "/api/derive", 422),
    ],
)
def test_every_response_carries_the_security_headers(client, method, path, status):
    response = getattr(client, method)(path, **({"json": {}} if method == "post" else {}))
    assert response.status_code == status
    assert response.headers["content-security-policy"] == CSP
    assert response.headers["x-content-type-options"] == "nosniff"
    assert response.headers["x-frame-options"] == "DENY"
    assert response.headers["referrer-policy"] == "same-origin"


def test_the_policy_allows_this_origin_only():
    rules = dict(rule.split(" ", 1) for rule in CSP.split("; "))
    # no inline scripts, no other host; eval for the live preview's generated right-hand side
    assert rules["script-src"] == "'self' 'unsafe-eval'"
    assert rules["frame-ancestors"] == "'none'"
    assert all("http" not in value for value in rules.values())


def test_the_api_docs_load_swagger_ui_from_this_server(client):
    page = client.get("/docs").text
    assert "/static/vendor/swagger-ui/swagger-ui-bundle.js" in page and "/static/js/api-docs.js" in page
    assert "cdn" not in page.lower() and "<script>" not in page
    assert client.get("/redoc").status_code == 404  # FastAPI's ReDoc page would load from a CDN
