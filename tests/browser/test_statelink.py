"""A link to a view keeps every piece of it (issue 45, item 4): parameters, initial conditions, method and tolerance,
the instant shown, the open panels and the practice step, on a scene page and in the playground, at a desktop size
and on a phone (390×844, touch). The view is set as a reader sets it, the link copied with "Link to this view",
opened in a fresh context, and the view read back and compared."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.browser

VIEWPORTS = {
    "desktop": {"viewport": {"width": 1366, "height": 768}},
    "phone": {"viewport": {"width": 390, "height": 844}, "has_touch": True, "is_mobile": True},
}
READY = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'

# what a reader sees, read from the page: the controls' numbers, the selects, the instant, the open panels and
# details, practice mode and the step that has the focus
READ_VIEW = """() => {
  const controls = {};
  for (const ctl of document.querySelectorAll('#controls .control')) {
    controls[ctl.dataset.name] = Number(ctl.querySelector('input[type="number"]').value);
  }
  for (const s of document.querySelectorAll('#controls select')) controls[s.name] = s.value;
  const sim = document.querySelector('[data-dt]');
  const scrub = document.querySelector('input.scrub');
  const open = [...document.querySelectorAll('.panels > section.panel')]
    .filter((s) => s.querySelector(':scope > h3 > button.fold[aria-expanded="true"]')).map((s) => s.id);
  const details = [...document.querySelectorAll('details[id][open]')].map((d) => d.id);
  const step = document.activeElement?.closest('.practice-step');
  return {
    controls, time: Number(scrub.value) * Number(sim.dataset.dt), open, details,
    practising: document.getElementById('practice-switch')?.checked ?? null, step: step ? step.dataset.key : null,
  };
}"""


@pytest.fixture(params=list(VIEWPORTS))
def context(request, browser, live_server):
    def new():
        made = browser.new_context(base_url=live_server, **VIEWPORTS[request.param])
        contexts.append(made)
        page = made.new_page()
        page.set_default_timeout(90_000)
        page.errors = []
        page.on("pageerror", lambda exc: page.errors.append(str(exc)))
        return page

    contexts: list = []
    yield request.param, new
    for made in contexts:
        made.close()


def set_number(page, name: str, value: str) -> None:
    box = page.locator(f'#controls .control[data-name="{name}"] input[type="number"]')
    box.fill(value)
    box.dispatch_event("change")


def settle(page) -> None:
    page.wait_for_selector(READY, state="attached")
    page.wait_for_function("document.querySelector('#run-status').dataset.state !== 'running'")
    page.wait_for_selector(READY, state="attached")


def copy_link(page) -> str:
    page.click("#view-link")
    page.wait_for_function("document.getElementById('view-link-status').dataset.link")
    return page.get_attribute("#view-link-status", "data-link")


def set_instant(page, index: int) -> None:
    page.evaluate(
        "(i) => { const s = document.querySelector('input.scrub'); s.value = String(i);"
        " s.dispatchEvent(new Event('input', { bubbles: true })); }",
        index,
    )


def test_a_scene_view_round_trips_through_its_link(context):
    size, new = context
    page = new()
    page.goto("/scenes/simple-pendulum")
    settle(page)
    set_number(page, "R", "0.8")
    set_number(page, "theta", "0.7")
    page.locator("#controls details.controls-run-details > summary").click()
    page.select_option("#ctl-rtol", index=0)
    settle(page)
    set_instant(page, 137)
    if size == "phone":
        page.click("#panel-phase > h3 > button.fold")
    else:
        page.locator("#details-work-precision > summary").click()
    page.click("#practice-switch")
    second = page.locator(".practice-step").nth(1)
    second.locator("input, textarea").first.focus()
    before = page.evaluate(READ_VIEW)  # before the button takes the focus
    link = copy_link(page)
    assert "#" in link and "R=0.8" in link and "theta=0.7" in link and "practice-step=" in link

    again = new()
    again.goto(link)
    settle(again)
    again.wait_for_function("Number(document.querySelector('input.scrub').value) > 0")
    again.wait_for_function("document.activeElement?.closest('.practice-step') !== null")
    after = again.evaluate(READ_VIEW)
    assert after["controls"] == before["controls"]
    assert after["time"] == pytest.approx(before["time"], abs=1e-9) and after["time"] > 0
    assert after["open"] == before["open"] and after["details"] == before["details"]
    assert after["practising"] is True and after["step"] == before["step"] is not None
    assert page.errors == again.errors == []


def test_a_playground_view_keeps_the_system_and_its_settings(context):
    size, new = context
    page = new()
    spec = "q=x&pn=m&pv=1&pn=k&pv=4&T=m*x_dot**2%2F2&U=k*x**2%2F2"
    page.goto(f"/playground?form=energies&{spec}")
    settle(page)
    set_number(page, "k", "9")
    set_number(page, "x", "0.3")
    settle(page)
    set_instant(page, 42)
    link = copy_link(page)
    assert "k=9" in link and "x=0.3" in link and "U=" in link
    before = page.evaluate(READ_VIEW)

    again = new()
    again.goto(link)
    settle(again)
    again.wait_for_function("Number(document.querySelector('input.scrub').value) > 0")
    after = again.evaluate(READ_VIEW)
    assert after["controls"] == before["controls"] and after["controls"]["k"] == 9
    assert after["time"] == pytest.approx(before["time"], abs=1e-9)
    assert page.errors == again.errors == []


def test_a_cut_or_changed_link_says_what_it_could_not_show(context):
    # inst-b 17: #theta=99 ran θ = 99 rad beside "allowed: −3.142 to 3.142 rad"; #theta=abc silently showed the default
    _, new = context
    page = new()
    page.goto("/scenes/simple-pendulum#theta=99&R=abc&thet=1&R2=2")
    settle(page)
    theta = page.locator('#controls .control[data-name="theta"]')
    assert float(theta.locator('input[type="number"]').input_value()) == float(theta.get_attribute("data-default"))
    note = page.locator("#controls .link-note")
    text = note.inner_text()
    assert "outside the allowed" in text and "99" in text
    assert "“abc” is not a number" in text and "“thet” is not a setting of this page" in text
    assert note.is_visible()
    # a link whose values all fit says nothing
    again = new()
    again.goto("/scenes/simple-pendulum#theta=0.5")
    settle(again)
    assert again.locator("#controls .link-note").count() == 0
    assert float(again.locator('#controls .control[data-name="theta"] input[type="number"]').input_value()) == 0.5
    assert page.errors == again.errors == []
