"""The Symbols table says what each coordinate of a scene is (issue 40, prof-f 4, 28)."""

from __future__ import annotations

import re

import pytest

from app.scenes import SCENES


def symbols(page: str) -> dict[str, str]:
    """Each row of the page's Symbols table: its TeX and its meaning as text."""
    table = page[page.index('<table class="symbols">') :]
    table = table[: table.index("</table>")]
    rows = re.findall(r'<tr><td>.*?data-tex="([^"]*)".*?</td><td>(.*?)</td>', table, flags=re.S)
    return {tex: re.sub(r"<[^>]+>", "", meaning) for tex, meaning in rows}


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_no_coordinate_of_a_scene_is_only_a_generalized_coordinate(client, scene_id):
    page = client.get(f"/scenes/{scene_id}").text
    meanings = symbols(page)
    assert meanings and "generalized coordinate" not in meanings.values(), meanings


def test_the_rail_says_where_its_masses_are(client):
    # prof-f 4: "x₁ and x₂ are described only as 'generalized coordinate'"
    meanings = symbols(client.get("/scenes/rail-two-body").text)
    assert meanings["x_{1}"] == "position of mass m₁ along the rail, from a fixed mark"
    assert meanings["x_{2}"] == "position of mass m₂ along the rail, from a fixed mark"


@pytest.mark.parametrize("scene_id", ["pulley", "movable-incline", "rotating-parabola"])
def test_each_force_of_constraint_has_a_letter_the_symbols_table_defines(client, scene_id):
    # prof-f 7, 15, 19, 30: "String tension" followed by a bare fraction; the panel's formula at footnote size
    page = client.get(f"/scenes/{scene_id}").text
    forces = client.get(f"/api/scenes/{scene_id}/derivation").json()["constraint_forces"]
    meanings = symbols(page)
    for k, force in enumerate(forces, start=1):
        assert meanings[f"F_{{{k}}}"] == force["name"]
        # in the Results and in the constraint panel: F_k = …, displayed
        assert page.count(f'<div class="math math-display" data-tex="F_{{{k}}} = ') >= 2, force["name"]
    assert "size of a constraint&#39;s force" not in page and "F" not in meanings


def units(page: str) -> dict[str, str]:
    """Each row of the page's Symbols table: its TeX and its unit cell."""
    table = page[page.index('<table class="symbols">') :]
    table = table[: table.index("</table>")]
    rows = re.findall(r'<tr><td>.*?data-tex="([^"]*)".*?</td><td>.*?</td><td>(.*?)</td></tr>', table, flags=re.S)
    return dict(rows)


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_every_row_of_the_symbols_table_has_its_unit(client, scene_id):
    # prof-g 4, 14, 18, 29: f, ℳ, K, η, a, A, Q, 𝒞 and λ listed without a unit
    cells = units(client.get(f"/scenes/{scene_id}").text)
    assert cells and all(cells.values()), {tex: unit for tex, unit in cells.items() if not unit}


def test_the_units_of_the_normal_mode_letters_follow_the_coordinates(client):
    pendulum = units(client.get("/scenes/simple-pendulum").text)
    assert pendulum["\\lambda_{1}"] == "N/m" and pendulum["\\mathcal{M}"] == "kg·m²" and pendulum["\\eta"] == "rad"
    springs = units(client.get("/scenes/coupled-oscillators").text)
    assert springs["K"] == "N/m" and springs["\\mathcal{M}"] == "kg" and springs["f"] == "N"
    assert units(client.get("/scenes/damped-pendulum").text)["Q"] == "N·m"


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_each_letter_of_the_symbols_table_is_printed_elsewhere_on_the_page(client, scene_id):
    page = client.get(f"/scenes/{scene_id}").text
    table_at = page.index('<table class="symbols">')
    rest = page[:table_at] + page[page.index("</table>", table_at) :]
    letters = {r["latex"]: r["unicode"] for r in client.get(f"/api/scenes/{scene_id}/derivation").json()["notation"]}
    for tex in units(page):
        # the letter's TeX inside some formula of the page outside the table, or its Unicode form in its words
        assert tex in rest or letters[tex.replace("&#39;", "'")] in rest, (scene_id, tex)


def test_the_radicand_named_in_the_double_pendulums_frequencies_is_in_its_symbols_table(client):
    # issue 40: ω² = g/(2m₁l₁l₂) [(m₁ + m₂)(l₁ + l₂) ∓ √Δ] prints Δ; the table says what it is where it is printed
    pendulum = units(client.get("/scenes/double-pendulum").text)
    assert pendulum["\\Delta"] == "that of the square of the other term in its bracket"
    assert "\\Delta" not in units(client.get("/scenes/coupled-oscillators").text)


def test_the_symbols_table_names_the_cartesian_letters_the_constraint_steps_print(client):
    # the pulley's coordinates are y₁, y₂, so its bodies' heights print as ζ₁, ζ₂, ζ₃: the table says ζ, never z
    body = client.get("/scenes/pulley").text
    table = body[body.index("Symbols") : body.index("</table>", body.index("Symbols"))]
    assert "Cartesian z of the left mass" in table and r'data-tex="\zeta_{1}"' in table and 'data-tex="z_{1}"' not in table


def test_the_mass_matrix_is_one_glyph_in_the_symbol_column_and_the_prose(client):
    # prof-n 11: the symbol column set \mathcal{M} (a plain script M) and the meaning beside f a bold script 𝓜
    import unicodedata

    from app.engine.display.names import MASS_MATRIX

    page = client.get("/scenes/simple-pendulum").text
    meanings = symbols(page)
    assert MASS_MATRIX[0] in meanings and MASS_MATRIX[1] in meanings["f"]
    # the letter KaTeX's \mathcal{M} draws: the plain script capital, never a bold one anywhere on the page
    assert unicodedata.name(MASS_MATRIX[1]) == "SCRIPT CAPITAL M"
    assert not [c for c in set(page) if unicodedata.name(c, "").startswith("MATHEMATICAL BOLD SCRIPT")]
