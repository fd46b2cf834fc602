"""GET /api/scenes/{id}/export and POST /api/export: files, headers, refusals, and the download buttons."""

import os

import nbformat
import pytest

from app.scenes import SCENES
from app.service.export.source import FORMATS
from tests.service.export.common import USER_SYSTEMS, exported
from tests.web.api.test_api_user_hostile import CORPUS

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

STARTS = {"ipynb": "{", "py": "#!/usr/bin/env python3", "tex": "\\documentclass"}


@pytest.mark.parametrize("scene_id", list(SCENES))
def test_every_scene_exports_in_every_format(client, scene_id):
    for fmt, (media_type, _) in FORMATS.items():
        response = client.get(f"/api/scenes/{scene_id}/export", params={"format": fmt})
        assert response.status_code == 200, response.text
        assert response.headers["content-type"] == media_type
        assert response.headers["content-disposition"] == f'attachment; filename="{scene_id}.{fmt}"'
        assert response.text.startswith(STARTS[fmt]) and response.text == exported(scene_id, fmt)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["user-double-pendulum", "forced-spring", "hostile"])
def test_user_systems_export_through_the_worker_pool_as_they_do_in_process(client, name):
    body, initial, t_end = USER_SYSTEMS[name]
    for fmt, (media_type, _) in FORMATS.items():
        response = client.post("/api/export", json={"system": body, "format": fmt, "initial": initial, "t_end": t_end})
        assert response.status_code == 200, response.text
        assert response.headers["content-type"] == media_type
        assert response.headers["content-disposition"] == f'attachment; filename="system.{fmt}"'
        assert skeleton(response.text, fmt) == skeleton(exported(name, fmt), fmt)


def skeleton(text: str, fmt: str) -> object:
    """What must not depend on where the file was made: the script whole, the notebook's code, the
    document's headings (display forms may differ when the simplification budget runs out under load)."""
    if fmt == "py":
        return text
    if fmt == "ipynb":
        return [c.source for c in nbformat.reads(text, as_version=4).cells if c.cell_type == "code"]
    return [line for line in text.splitlines() if line.startswith(("\\section", "\\subsection"))]


def test_refusals_say_what_was_wrong_and_what_is_allowed(client):
    wrong = client.get("/api/scenes/simple-pendulum/export", params={"format": "docx"})
    assert wrong.status_code == 422 and "'ipynb', 'py' or 'tex'" in wrong.json()["detail"]
    unknown = client.get("/api/scenes/no-such-scene/export", params={"format": "py"})
    assert unknown.status_code == 404 and "simple-pendulum" in unknown.json()["detail"]

    spring = USER_SYSTEMS["forced-spring"][0]
    cases = [
        ({"system": spring, "format": "py", "initial": {"y": 1.0}}, ["body", "initial"], "allowed: x, x_dot"),
        ({"system": spring, "format": "py", "t_end": 1e9}, ["body", "t_end"], "less than or equal"),
        (
            {"system": {**spring, "coordinates": ["x y"]}, "format": "tex"},
            ["body", "system", "coordinates", "0"],
            "letter",
        ),
        ({"system": {**spring, "potential": "k*y**2/2"}, "format": "ipynb"}, ["body", "system", "potential"], "y"),
        ({"system": {**spring, "lagrangian": "x_dot**2"}, "format": "py"}, ["body", "system"], "exactly one"),
    ]
    for body, loc, says in cases:
        response = client.post("/api/export", json=body)
        assert response.status_code == 422, (body, response.text)
        answer = response.json()
        where = answer.get("loc") or answer["errors"][0]["loc"]
        assert where[: len(loc)] == loc or [x for x in where if x != "body"][: len(loc) - 1] == loc[1:], (where, loc)
        assert says in answer["detail"], answer


def fill(value, canary):
    """The corpus entry with its canary path filled in."""
    if isinstance(value, str):
        return value.replace("{canary}", canary)
    if isinstance(value, dict):
        return {k: fill(v, canary) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [fill(v, canary) for v in value]
    return value


def test_the_hostile_corpus_is_refused_by_the_export_too(client):
    formats = list(FORMATS)
    for i, (case, body) in enumerate(CORPUS):
        if not isinstance(body, dict):
            continue
        canary = f"/tmp/lagrange-canary-export-{case}"
        system = fill(body, canary)
        response = client.post("/api/export", json={"system": system, "format": formats[i % 3]})
        assert 400 <= response.status_code < 500, (case, response.status_code, response.text[:200])
        assert not os.path.exists(canary), case


def test_scene_pages_link_the_exports_and_the_playground_posts_them(client):
    page = client.get("/scenes/helix-bead").text
    for fmt, text in (("ipynb", "Open as notebook"), ("py", "Python script"), ("tex", "LaTeX")):
        assert f'href="/api/scenes/helix-bead/export?format={fmt}" download>{text}</a>' in page
    playground = client.get("/playground?q=x&pn=m&pv=1&form=lagrangian&L=m*x_dot**2/2&stage=whole").text
    for fmt in FORMATS:
        assert f'<button type="button" data-export-format="{fmt}">' in playground
    assert "js/export.js" in playground
