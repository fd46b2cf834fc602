"""axe-core (installed from npm by scripts/assets.sh, never served by the app) on every scene page and the
playground, after the first run has been drawn: no serious or critical violation."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.scenes import SCENES

pytestmark = pytest.mark.browser

AXE = Path(__file__).resolve().parents[2] / "node_modules" / "axe-core" / "axe.min.js"
DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'


def violations(page) -> list[str]:
    page.evaluate(AXE.read_text())
    found = page.evaluate(
        """async () => (await axe.run(document, { resultTypes: ['violations'] })).violations
             .filter((v) => v.impact === 'serious' || v.impact === 'critical')
             .map((v) => `${v.impact} ${v.id}: ${v.nodes.length} × ${v.nodes[0].target.join(' ')} (${v.help})`)"""
    )
    return found


@pytest.mark.parametrize("path", [*(f"/scenes/{s}" for s in sorted(SCENES)), "/playground"])
@pytest.mark.parametrize("size", [(1366, 768), (390, 844)])
def test_no_serious_violation(browser, live_server, path, size):
    if not AXE.exists():
        pytest.fail("axe-core is not installed: run scripts/assets.sh (npm ci installs it)")
    context = browser.new_context(base_url=live_server, viewport={"width": size[0], "height": size[1]})
    page = context.new_page()
    page.set_default_timeout(60_000)
    page.goto(path)
    page.wait_for_selector(DONE, state="attached")
    # every panel drawn (they draw when scrolled into view or when the browser is idle)
    page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
    page.wait_for_timeout(800)
    assert violations(page) == []
    context.close()
