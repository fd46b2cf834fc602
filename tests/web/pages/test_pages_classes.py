"""The classes' pages: served without touching the database, with their scripts and the scenes to assign."""

import json
import re

import pytest

from app.service.chapter import derivations


def test_the_pages_are_shells_that_need_no_database(client, services):
    for path, script in (("/teach", "js/teach.js"), ("/join", "js/join.js")):
        page = client.get(path)
        assert page.status_code == 200 and script in page.text and "css/classroom.css" in page.text
        scenes = json.loads(re.search(r'id="class-scenes">(.*?)</script>', page.text, re.S).group(1))
        assert [s["id"] for s in scenes] == list(derivations.SCENES)
    assert not services.classes.db.started  # no class route used: the database was never opened


def test_a_short_link_opens_the_join_page_with_its_code(client):
    r = client.get("/j/ack-3x7", follow_redirects=False)  # typed loosely: the code as stored
    assert r.status_code == 303 and r.headers["location"] == "/join?code=ACK3X7"
    assert client.get("/join?code=ACK3X7").status_code == 200


def test_a_short_link_that_is_no_code_says_what_a_code_is(client):
    for bad in ("nope", "ABC12", "A" * 300):
        r = client.get(f"/j/{bad}")
        assert r.status_code == 404 and "is not a class code" in r.text and "6 letters and digits" in r.text
        assert f"It has {len(bad)} characters" in r.text
        assert client.get(f"/j/{bad}/qr.svg").status_code == 404


def test_a_short_link_with_a_character_no_code_holds_names_it(client):
    # six letters and digits, but Z is never in a code (easily confused with 2)
    r = client.get("/j/K34EKZ")
    assert r.status_code == 404
    assert "“Z” is never in a class code" in r.text
    assert "leaves out the characters easily read as another" in r.text and "(no B, D" not in r.text  # inst-b 6


def test_the_qr_code_is_the_short_link_on_this_server(client):
    from app.viz.qr import qr_svg

    r = client.get("/j/ack3x7/qr.svg")
    assert r.status_code == 200 and r.headers["content-type"] == "image/svg+xml"
    # the code of the absolute short link as this server is reached (the Host the browser used)
    assert r.content == qr_svg("http://testserver/j/ACK3X7", "QR code of http://testserver/j/ACK3X7")
    assert r.content != qr_svg("http://testserver/j/ACK3X9", "QR code of http://testserver/j/ACK3X7")


@pytest.mark.slow
def test_the_home_page_and_the_header_lead_to_the_classes(client):
    home = client.get("/").text
    body = home.split("</header>", 1)[1]  # past the site's header: the home page's own words
    assert '<a href="/join">Join a class</a>' in body and '<a href="/teach">Teach a class</a>' in body
    for path in ("/", "/playground", "/scenes/simple-pendulum"):
        header = client.get(path).text.split('<nav aria-label="Site">', 1)[1].split("</nav>", 1)[0]
        assert '<a href="/join">Join a class</a>' in header and '<a href="/teach">Teach a class</a>' in header, path


def test_the_class_page_says_how_to_type_an_answer_as_the_scene_page_does(client):
    # student-f 23: the class page's help listed "sin cos exp sqrt" and never said that a box takes only the
    # right-hand side, as the scene page's practice mode does
    def syntax(text: str, id_: str) -> str:
        return re.search(rf'<p class="help" id="{id_}">(.*?)</p>', text, re.S).group(1)

    said = syntax(client.get("/join").text, "join-syntax")
    assert said == syntax(client.get("/scenes/simple-pendulum").text, "practice-syntax")
    assert "every other box takes only the right-hand side" in said and "sin cos tan exp log sqrt" in said
