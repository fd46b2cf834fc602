"""axe-core on the playground at both sizes, after its first run has been drawn: no serious or critical violation
(every scene page: test_scene_read.py)."""

from __future__ import annotations

import pytest

from tests.browser.reading import DONE, axe_violations

pytestmark = pytest.mark.browser


@pytest.mark.parametrize("size", [(1366, 768), (390, 844)])
def test_no_serious_violation_on_the_playground(browser, live_server, size):
    context = browser.new_context(base_url=live_server, viewport={"width": size[0], "height": size[1]})
    page = context.new_page()
    page.set_default_timeout(60_000)
    try:
        page.goto("/playground")
        page.wait_for_selector(DONE, state="attached")
        # every panel drawn (they draw when scrolled into view or when the browser is idle)
        page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
        page.wait_for_timeout(800)
        assert axe_violations(page) == []
    finally:
        context.close()
