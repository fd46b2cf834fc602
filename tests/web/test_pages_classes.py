"""The classes' pages: served without touching the database, with their scripts and the scenes to assign."""

import json
import re

from app.service import derivations


def test_the_pages_are_shells_that_need_no_database(client, services):
    for path, script in (("/teach", "js/teach.js"), ("/join", "js/join.js")):
        page = client.get(path)
        assert page.status_code == 200 and script in page.text and "css/classroom.css" in page.text
        scenes = json.loads(re.search(r'id="class-scenes">(.*?)</script>', page.text, re.S).group(1))
        assert [s["id"] for s in scenes] == list(derivations.SCENES)
    assert not services.classes.db.started  # no class route used: the database was never opened
