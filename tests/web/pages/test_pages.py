"""The HTML pages: every page renders, shows exactly the declared panels, loads nothing from the internet."""

import html as html_text
import json
import math
import re
import xml.etree.ElementTree as ET
from html.parser import HTMLParser
from pathlib import Path

import pytest
import sympy as sp

from app.engine.display.names import prose
from app.engine.document.trees import TreeError, of_text
from app.scenes import SCENES
from app.service.chapter.derivations import PROCESS_SCENES, derivation_document
from app.viz.chapter import SECTIONS, section_numbers, table_of_contents
from app.viz.exprtree import evaluate
from app.viz.names import label
from app.viz.panels import NAMES
from app.web.pages.chapter import page_model
from app.web.rendering.prose import prose_html

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

ROOT = Path(__file__).resolve().parents[3]


class Tags(HTMLParser):
    """Every start tag with its attributes, and the text of the page."""

    def __init__(self):
        super().__init__()
        self.tags: list[tuple[str, dict[str, str]]] = []
        self.text: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, {k: v or "" for k, v in attrs}))

    def handle_data(self, data):
        self.text.append(data)


def parse(html: str) -> Tags:
    tags = Tags()
    tags.feed(html)
    return tags


def shown_panels(scene_id: str) -> list[str]:
    return page_model(scene_id, None, PROCESS_SCENES)["panels"]


@pytest.fixture(scope="module")
def pages(client):
    urls = ["/", *(f"/scenes/{sid}" for sid in SCENES)]
    return {url: client.get(url) for url in urls}


def test_every_page_renders(pages):
    for url, response in pages.items():
        assert response.status_code == 200, url
        assert response.headers["content-type"].startswith("text/html")
        assert "<h1" in response.text


def test_contents_lists_every_scene_in_section_order(pages):
    html = pages["/"].text
    for sid in SCENES:
        assert f'href="/scenes/{sid}"' in html
    positions = [html.index(f'id="section-{s.number}"') for s in SECTIONS]
    assert positions == sorted(positions)


def test_contents_names_no_section_it_does_not_list(pages):
    # a book never mentions a section it lacks (prof-h 14: "(The chapter has no section 4.8.)")
    text = "".join(parse(pages["/"].text).text)
    named = set(re.findall(r"\b4\.\d\b", text))
    assert named and named <= {s.number for s in SECTIONS}, named - {s.number for s in SECTIONS}


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_panels_rendered_are_exactly_the_shown_ones(pages, scene_id):
    tags = parse(pages[f"/scenes/{scene_id}"].text)
    rendered = [a["data-panel"] for t, a in tags.tags if "data-panel" in a]
    declared = shown_panels(scene_id)
    assert set(declared) <= set(NAMES), f"unknown panel in {declared}"
    assert set(SCENES[scene_id].panels) <= set(declared)  # every optional panel a scene asks for applies to it
    assert rendered == declared
    data = json.loads(
        re.search(
            r'<script type="application/json" id="scene-data">(.*?)</script>', pages[f"/scenes/{scene_id}"].text, re.S
        ).group(1)
    )
    assert data["panels"] == declared
    if any(p.startswith("animation") for p in declared):
        assert data["mechanism"]["dim"] == (3 if "animation-3d" in declared else 2)


def as_read(sentence: str) -> str:
    """A sentence's text as the page holds it: its subscripts set as <sub> (app/web/rendering/prose.py), tags dropped."""
    return html_text.unescape(re.sub(r"<[^>]+>", "", str(prose_html(sentence))))


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_scene_page_shows_every_step_and_the_results(pages, scene_id):
    html = pages[f"/scenes/{scene_id}"].text
    tags = parse(html)
    doc = derivation_document(scene_id)
    steps = [a for t, a in tags.tags if t == "li" and "step" in a.get("class", "").split()]
    assert len(steps) == len(doc["steps"])
    # the TeX of every formula rides in data-tex (its MathML is the element's content)
    text = "".join(tags.text) + "".join(a["data-tex"] for t, a in tags.tags if "data-tex" in a)
    for step in doc["steps"]:
        # a sentence reads with its subscripts set (U_eff as U<sub>eff</sub>: "Ueff" as text)
        assert as_read(step["title"]) in text and as_read(step["explanation"]) in text
        assert step["latex"] in text  # Jinja escapes & and <, which the parser undoes
    for eq in doc["equations_of_motion"]:
        assert eq["latex"] in text
    assert as_read(doc["hamiltonian_energy_reason"]) in text and as_read(doc["hamiltonian_conserved_reason"]) in text
    for e in doc.get("errata") or []:
        # typeset: the chapter's formula as written and the correct one, both as TeX; names in the reason as a reader writes them
        assert e["chapter_latex"] in text and e["correct_latex"] in text and as_read(prose(e["reason"])) in text
    for c in doc.get("constraint_forces") or []:
        assert c["latex"] in text and as_read(c["convention"]) in text


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_every_control_has_a_label(pages, scene_id):
    tags = parse(pages[f"/scenes/{scene_id}"].text)
    label_for = {a["for"] for t, a in tags.tags if t == "label" and "for" in a}
    ids = {a["id"] for t, a in tags.tags if "id" in a}
    controls = [(t, a) for t, a in tags.tags if t in ("input", "select", "textarea")]
    assert controls
    for t, a in controls:
        named = (
            a.get("id") in label_for
            or a.get("aria-label")
            or (a.get("aria-labelledby") and all(i in ids for i in a["aria-labelledby"].split()))
        )
        assert named, f"{t} {a} has no label"
    doc = derivation_document(scene_id)
    names = {a.get("name") for t, a in controls}
    assert set(doc["parameters"]) <= names
    assert {f"{q}{s}" for q in doc["coordinates"] for s in ("", "_dot")} <= names


def test_no_page_or_module_loads_anything_from_the_internet(pages, client):
    for url, response in pages.items():
        for tag, attrs in parse(response.text).tags:
            for key in ("src", "href"):
                value = attrs.get(key, "")
                assert not re.match(r"^(https?:)?//", value), f"{url}: <{tag} {key}={value}>"
                if tag in ("script", "link") and key in attrs:
                    assert value.startswith("/static/"), f"{url}: <{tag} {key}={value}>"
    own = [p for p in (ROOT / "static").rglob("*") if p.is_file() and "vendor" not in p.parts]
    assert any(p.suffix == ".js" for p in own)
    for path in own:
        text = path.read_text()
        assert not re.search(r"""(import|from|fetch\(|url\()\s*["'(]?(https?:)?//""", text), path
        rel = path.relative_to(ROOT / "static").as_posix()
        assert client.get(f"/static/{rel}").status_code == 200


def test_unknown_scene_is_a_404_page_listing_the_scenes(client):
    response = client.get("/scenes/no-such-scene")
    assert response.status_code == 404
    assert response.headers["content-type"].startswith("text/html")
    assert "no-such-scene" in response.text
    for sid in SCENES:
        assert f'href="/scenes/{sid}"' in response.text
    # an id is echoed escaped, never as markup
    response = client.get("/scenes/%3Cscript%3Ealert(1)%3C%2Fscript%3E")
    assert response.status_code == 404 and "<script>alert" not in response.text


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_set_up_diagram_labels_the_coordinates_and_parameters(pages, scene_id):
    html = pages[f"/scenes/{scene_id}"].text
    svg = re.search(r'<svg class="diagram".*?</svg>', html, re.S).group(0)
    root = ET.fromstring(svg)  # well-formed
    ns = "{http://www.w3.org/2000/svg}"
    assert root.find(f"{ns}title").text and root.find(f"{ns}desc").text
    words = " ".join(t.text or "" for t in root.iter(f"{ns}text"))
    doc = derivation_document(scene_id)
    for name in [*doc["coordinates"], *doc["parameters"]]:
        assert label(name) in words, f"{scene_id}: {label(name)} is not labelled in {words!r}"


def test_every_scene_is_in_exactly_one_section():
    scenes = [
        {"id": s.id, "section": s.section, "panels": shown_panels(s.id), "beyond_chapter": s.beyond_chapter}
        for s in SCENES.values()
    ]
    toc = table_of_contents(scenes)
    owners = {sid: [s["number"] for s in toc if sid in [x["id"] for x in s["scenes"]]] for sid in SCENES}
    assert all(len(v) == 1 for v in owners.values()), owners
    # the scenes beyond the chapter under their own heading, after the chapter's sections
    assert toc[-1]["title"] == "Beyond the chapter"
    assert {x["id"] for x in toc[-1]["scenes"]} == {sid for sid, s in SCENES.items() if s.beyond_chapter}
    assert section_numbers("§ 4.6–4.7") == ["4.6", "4.7"]


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_expression_trees_evaluate_like_sympy(scene_id):
    # the browser evaluates these trees (the engine wrote them from SymPy objects); check them against
    # SymPy on the served strings
    doc = derivation_document(scene_id)
    names = [*doc["coordinates"], *(f"{q}_dot" for q in doc["coordinates"]), *doc["parameters"], "t"]
    symbols = {n: sp.Symbol(n, real=True) for n in names}
    env = {n: 0.3 + 0.17 * i for i, n in enumerate(names)}
    exprs = [doc["lagrangian"], doc["hamiltonian"], *doc["momenta"].values(), *doc["accelerations"].values()]
    for pair in exprs:
        expected = float(sp.sympify(pair["sympy"], locals=symbols).subs({symbols[k]: v for k, v in env.items()}))
        assert math.isclose(evaluate(pair["tree"], env), expected, rel_tol=1e-9, abs_tol=1e-12)


@pytest.mark.parametrize("text", ["__import__('os')", "x.real", "x[0]", "lambda: 1", "f(x)", "sin(x, y)", ""])
def test_expression_trees_refuse_anything_but_arithmetic(text):
    with pytest.raises(TreeError):
        of_text(text, ["x", "y"])


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_every_formula_is_mathml_with_its_tex(pages, scene_id):
    html = pages[f"/scenes/{scene_id}"].text
    tags = parse(html)
    formulas = [a for t, a in tags.tags if "math" in a.get("class", "").split()]
    assert formulas and all(a.get("data-tex") for a in formulas)
    # each formula element holds a <math> element: the derivation reads without JavaScript
    assert html.count('<math xmlns="http://www.w3.org/1998/Math/MathML"') == len(formulas)


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_the_core_steps_are_never_folded(pages, scene_id):
    tags = parse(pages[f"/scenes/{scene_id}"].text)
    steps = [a for t, a in tags.tags if t == "li" and "step" in a.get("class", "").split()]
    titles = [s["title"] for s in derivation_document(scene_id)["steps"]]
    folded = {title for title, a in zip(titles, steps, strict=True) if "bookkeeping" in a["class"].split()}
    assert {"Lagrangian", "Euler–Lagrange equations", "Accelerations"}.isdisjoint(folded)
    # the kinematics is bookkeeping: the particles' positions, or a rigid body's centre and turning
    assert {"Positions", "Centre of mass and moment of inertia"} & folded and len(folded) < len(titles)


def test_a_scene_page_is_sent_compressed(client):
    response = client.get("/scenes/simple-pendulum", headers={"Accept-Encoding": "gzip"})
    assert response.headers["content-encoding"] == "gzip" and "<h1" in response.text
    plain = client.get("/scenes/simple-pendulum", headers={"Accept-Encoding": "identity"})
    assert "content-encoding" not in plain.headers and plain.text == response.text
    module = client.get("/static/js/simulation.js", headers={"Accept-Encoding": "gzip"})
    assert module.headers["content-encoding"] == "gzip" and "connectSimulation" in module.text


def test_the_damped_pendulum_is_marked_as_ours(client):
    # the chapter has no damped pendulum: it builds on 4.1's generalized forces, as our own example
    assert SCENES["damped-pendulum"].beyond_chapter and SCENES["damped-pendulum"].section == "4.1"
    page = client.get("/scenes/damped-pendulum").text
    assert "Further example, extending section 4.1" in page and "our example" not in page
    assert (
        "Beyond the chapter" not in client.get("/scenes/simple-pendulum").text.split("<main")[1].split("</header>")[0]
    )


@pytest.mark.parametrize("scene_id", ["pulley", "rotating-parabola"])
def test_the_symbols_table_is_on_the_page(client, scene_id):
    html = client.get(f"/scenes/{scene_id}").text
    tags = parse(html)
    assert ("dt", {"id": "symbols"}) in tags.tags
    text = "".join(tags.text) + "".join(a["data-tex"] for t, a in tags.tags if "data-tex" in a)
    notation = derivation_document(scene_id)["notation"]
    # the document's letters the page prints are listed (each coordinate and parameter at least); the others not
    shown = [row for row in notation if row["meaning"] in text]
    assert {r["kind"] for r in notation} - {r["kind"] for r in shown} <= {"derived"}
    for row in shown:
        assert row["latex"] in text
    assert all(r in shown for r in notation if r["kind"] in ("coordinate", "parameter"))
    if scene_id == "rotating-parabola":
        # ω is the turning rate, so the frequency along the wire is Ω, in the results box as in the steps
        assert r"\Omega^2 = " in text and r"\omega^2 = 2" not in text
    else:
        assert r"\mathcal{M}" in text


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "double-pendulum", "pulley"])
def test_T_and_U_are_shown_without_asking_for_all_steps(client, scene_id):
    html = client.get(f"/scenes/{scene_id}").text
    for title in ("Kinetic energy", "Potential energy"):
        # the step's list item is a core step: not folded behind "Show all steps"
        head = html.split(f">{title}<", 1)[0].rsplit("<li ", 1)[1]
        assert 'class="step"' in head and "bookkeeping" not in head, head


def test_the_wedge_block_starts_on_the_slope():
    """D(0) runs from the top corner (0) down: a start above the corner contradicted the picture (prof-f 12)."""
    (D,) = [c for c in page_model("movable-incline", None, PROCESS_SCENES)["initial"] if c["name"] == "D"]
    assert float(D["min"]) == 0.0 and float(D["max"]) > 0 and D["allowed"].startswith("0 to")


def test_the_tabletop_spring_constant_has_a_tabletop_range():
    """prof-e 20: "0.01 to 100,000,000 N/m" is no table's spring."""
    (k,) = [c for c in page_model("tabletop-spring", None, PROCESS_SCENES)["parameters"] if c["name"] == "k"]
    assert k["allowed"] == "0.01 to 1,000 N/m"
