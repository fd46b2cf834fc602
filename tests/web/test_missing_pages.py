"""A page address that leads nowhere answers with a page that says where to go, never the API's JSON."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize(
    ("path", "heading", "hint"),
    [
        ("/j/", "This class link has no class code", 'href="/join"'),
        ("/j", "This class link has no class code", "/j/K34EKX"),
        ("/embed", "No embedded page at", 'href="/embed/scenes/simple-pendulum"'),
        ("/embed/simple-pendulum", "No embedded page at", "?panel="),
        ("/no-such-page", "No page at", 'href="/playground"'),
    ],
)
def test_a_page_address_that_leads_nowhere_says_where_to_go(client, path, heading, hint):
    # inst-b 5, 16: a class link cut before its code, and guessed embed addresses, showed {"detail":"Not Found"}
    r = client.get(path)
    assert r.status_code == 404
    assert r.headers["content-type"].startswith("text/html")
    assert heading in r.text and hint in r.text
    assert '"detail"' not in r.text


def test_the_api_and_static_files_keep_their_plain_404(client):
    api = client.get("/api/no-such-thing")
    assert api.status_code == 404 and api.headers["content-type"] == "application/problem+json"
    assert client.get("/static/no-such-file.js").status_code == 404
    assert "<h1" not in client.get("/static/no-such-file.js").text
