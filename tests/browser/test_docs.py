"""/docs works with the network off: swagger-ui from our own server, no request leaves loopback."""

from urllib.parse import urlsplit

import pytest

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


@pytest.mark.parametrize("path", ["/docs", "/scenes/simple-pendulum", "/playground"])
def test_no_request_leaves_the_server_and_the_policy_blocks_nothing(page, path):
    requested = []
    page.on("request", lambda request: requested.append(request.url))
    page.goto(path)
    page.wait_for_load_state("networkidle")
    if path == "/docs":
        page.wait_for_selector(".opblock")  # swagger-ui ran and drew the operations of our spec
        assert page.locator(".opblock").count() >= 5
        assert "/api/derive" in page.inner_text("#swagger-ui")
    hosts = {urlsplit(url).hostname for url in requested if urlsplit(url).scheme in ("http", "https")}
    assert hosts == {"127.0.0.1"}, requested
    assert not [e for e in page.console_errors if "Content Security Policy" in e or "Refused" in e]
    assert page.console_errors == []
