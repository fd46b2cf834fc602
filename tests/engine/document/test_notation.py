"""One letter, one quantity: every scene's served document (its Symbols table, steps and results) read whole.

Issue 40's first complaint was a letter naming two quantities (ω the turning rate and ω² the frequency on the
rotating parabola; s the exponent and the second).  These tests read what the API serves, not the code that
chooses the letters.
"""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

import pytest

from app.engine.document import notation
from app.engine.document.model import Document, FirstStage
from app.scenes import SCENES
from app.service.chapter.derivations import derivation, derivation_document

# a row's left side: a bare letter, maybe squared (ω², \Omega^2), maybe with a subscript (\omega_{1}, F_{1})
_NAME = re.compile(r"^\s*&?\s*((?:\\[A-Za-z]+|[A-Za-z])(?:_\{?[0-9A-Za-z]+\}?)?)(?:\^\{?2\}?)?\s*&?=")
# a unit as the document typesets it: \mathrm{s}^{-2}, \mathrm{kg\,m^{2}\,s^{-1}}
_UNIT = re.compile(r"\\mathrm\{([^}]*)\}")


def _rows(tex: str) -> list[str]:
    body = tex.replace(r"\begin{aligned}", "").replace(r"\end{aligned}", "")
    # rows, and the clauses of a row (ρ₀ = 0,\quad Ω² = …; \text{about } ρ = 0:\quad Ω² = …)
    return [part.lstrip(",:; ") for part in re.split(r"\\\\|\\quad|,\\;", body)]


def _formulas(doc: object, where: str = "") -> list[tuple[str, str]]:
    """Every formula the document serves (steps and results), with where it is; the chapter's own formulas in
    the errata (wrong on purpose) aside."""
    if isinstance(doc, dict):
        return [f for k, v in doc.items() if k != "chapter_latex" for f in _formulas(v, f"{where}/{k}")]
    if isinstance(doc, list):
        return [f for i, v in enumerate(doc) for f in _formulas(v, f"{where}[{i}]")]
    return [(where, doc)] if isinstance(doc, str) and where.endswith("latex") else []


def _defined(doc: dict) -> dict[str, list[str]]:
    """Each letter a formula defines (its rows' left sides, ``ω^2 = …``), with where."""
    out: dict[str, list[str]] = {}
    for where, tex in _formulas(doc):
        for row in _rows(tex):
            if m := _NAME.match(row):
                out.setdefault(re.sub(r"[{}\s]", "", m.group(1)), []).append(where)
    return out


def _units(doc: dict) -> set[str]:
    letters: set[str] = set()
    for _, tex in _formulas(doc):
        for unit in _UNIT.findall(tex):
            letters |= set(re.findall(r"[A-Za-z]+", unit.replace(r"\,", " ")))
    return letters


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_no_letter_names_two_quantities(scene_id):
    doc = derivation_document(scene_id)
    rows = doc["notation"]
    # each letter (with its decorations) is one row of the Symbols table: one meaning
    seen: dict[str, str] = {}
    for row in rows:
        assert row["unicode"] not in seen, (row["unicode"], seen.get(row["unicode"]), row["meaning"])
        seen[row["unicode"]] = row["meaning"]
    declared = {re.sub(r"[{}\s]", "", r["latex"]) for r in rows if r["kind"] in ("parameter", "coordinate")}
    defined = _defined(doc)
    # the mass matrix's letter is none of the declaration's (ℳ beside the wedge's mass M)
    assert _mass_matrix_letter(rows) not in {r["unicode"] for r in rows if r["kind"] in ("parameter", "coordinate")}
    # a parameter's or a coordinate's letter is never the name of a result (ω² = 2gα − ω²): a result equal
    # to a coordinate's value is that coordinate's equilibrium (θ = π), which is no new quantity
    results = {name: keys for name, keys in defined.items() if name in declared and name not in _coordinates(rows)}
    assert not results, results
    # nor a unit's letter (s the exponent beside s⁻¹ the unit)
    clashes = {name for name in defined if name in _units(doc) and name not in declared}
    assert not clashes, clashes


def _coordinates(rows: list[dict]) -> set[str]:
    return {re.sub(r"[{}\s]", "", r["latex"]) for r in rows if r["kind"] == "coordinate"}


def test_the_rotating_parabola_calls_its_effective_potential_by_one_name():
    # prof-g 41: "V = −L at ρ̇ = 0 is the Ueff of the effective-potential step" and a Symbols row V
    doc = derivation_document("rotating-parabola")
    letters = {r["unicode"] for r in doc["notation"]}
    assert "U_eff" in letters and "V" not in letters
    step = next(s for s in doc["steps"] if s["key"] == "equilibria")
    assert step["latex"].startswith(r"\begin{aligned}U_\text{eff} &= -L\big|_{\dot q = 0} = ")
    assert r"\frac{\partial U_\text{eff}}{\partial \rho}" in step["latex"] and "V" not in step["latex"]
    words = step["explanation"]
    assert "effective potential U_eff" in words and "V" not in words and "step" not in words


# a number with the metre's bare "m" in running text: 1 m either side, z = 2.294 m. (not 2 m R², 2 m (1 + α²R²),
# a product with the mass m)
_METRES = re.compile(r"\d(?:\.\d+)? m(?=$|[,.;:)]|\s+[a-z]{2,})")


def _prose(doc: dict) -> list[str]:
    scene = doc.get("scene") or {}
    return [
        *(s["explanation"] for s in doc["steps"]),
        *(v for v in scene.values() if isinstance(v, str)),
        *(r["meaning"] for r in doc["notation"]),
    ]


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_metres_are_written_out_in_prose_where_m_is_a_mass(scene_id):
    # prof-g 33, 38: "the constant 2 m places M below the pulleys" on a page where m₁, m₂ and M are masses
    doc = derivation_document(scene_id)
    masses = {r["unicode"] for r in doc["notation"] if r["kind"] == "parameter" and r["unit"] == "kg"}
    if not any(name.startswith("m") for name in masses):
        pytest.skip("no mass m on this page")
    found = [text[max(0, m.start() - 40) : m.end() + 20] for text in _prose(doc) for m in _METRES.finditer(text)]
    assert not found, found



@pytest.mark.slow
def test_the_letters_of_a_constraint_are_read_from_one_home(monkeypatch):
    # issue 40: F₁, λ₁ and 𝒞₁ were each spelled in the Symbols table, the steps of the forces of constraint and
    # the page's Results; with other letters given in notation.py, all three print those and none of the old.
    # The served document is read before the letters change, and nothing below goes through a cache.
    from app.engine.derivation.derive import derive, value_or
    from app.engine.document import notation
    from app.engine.document.report import Printer
    from app.engine.document.report_members import constraint_steps
    from app.viz.page_model import scene_page

    doc = derivation_document("helix-bead")
    monkeypatch.setattr(notation, "surface", lambda a: (rf"\Sigma_{{{a}}}", f"Σ{a}"))
    monkeypatch.setattr(notation, "multiplier", lambda a: (rf"\mu_{{{a}}}", f"μ{a}"))
    monkeypatch.setattr(notation, "force", lambda a: (f"G_{{{a}}}", f"G{a}"))
    d = derive(SCENES["helix-bead"].system)
    forces = value_or(d.constraint_forces, ())
    assert len(forces) == 2
    letters = {r["unicode"] for r in notation.table(d, forces)}
    assert {"Σ1", "Σ2", "μ1", "μ2", "G1", "G2"} <= letters
    assert not {"𝒞₁", "λ₁", "F₁", "𝒞₂", "λ₂", "F₂"} & letters
    steps = " ".join(s["latex"] for s in constraint_steps(d, forces, Printer(d.table.latex_names())))
    assert r"\Sigma_{1} &= " in steps and r"G_{2} &= \mu_{2} \left|\frac{\partial \Sigma_{2}}" in steps
    assert r"\lambda_{" not in steps and "F_{" not in steps and r"\mathcal{C}_{" not in steps
    shown = scene_page(Document.model_validate(doc), {"title": "helix"})["summary"]["constraint_forces"]
    assert [f["symbol"] for f in shown] == ["G_{1}", "G_{2}"]
    assert all(f["latex"].startswith(f["symbol"] + " = ") for f in shown)


# the mass matrix written as a bare M: M q̈ = f, M⁻¹f, M^{-1} f, \mathcal-less M \ddot{q}, M = (matrix)
_BARE_M = re.compile(r"(?<![\\\w{])M\s*(?:q̈|⁻¹|\^\{-1\}|\\ddot\{q\}|=\s*\\begin\{pmatrix\})")
# a chain of three pendulums, the last bob of mass M: its accelerations stay ℳ⁻¹f (too long in closed form)
_CHAIN = {
    "coordinates": ["a", "b", "c"],
    "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "M", "value": 2.0, "unit": "kg"},
                   {"name": "l", "value": 1.0, "unit": "m"}, {"name": "g", "value": 9.81, "unit": "m/s^2"}],
    "particles": [
        {"mass": "m", "position": ["l*sin(a)", "0", "-l*cos(a)"]},
        {"mass": "m", "position": ["l*sin(a) + l*sin(b)", "0", "-l*cos(a) - l*cos(b)"]},
        {"mass": "M", "position": ["l*sin(a) + l*sin(b) + l*sin(c)", "0", "-l*cos(a) - l*cos(b) - l*cos(c)"]},
    ],
    "potential": "-g*l*((2*m + M)*cos(a) + (m + M)*cos(b) + M*cos(c))",
}  # fmt: skip


def _mass_matrix_letter(rows: list[dict]) -> str:
    return next(r["unicode"] for r in rows if r["meaning"].startswith("mass matrix"))


@pytest.mark.parametrize("scene_id", ["movable-incline", "pulley"])
def test_a_scene_with_a_mass_m_writes_its_mass_matrix_with_another_letter(scene_id):
    # issue 40: the wedge's (the pulley's) mass is M; the mass matrix its page and its notebook print is not
    from app.service.chapter.derivations import derivation, scene_document
    from app.service.export.notebook import notebook
    from app.service.export.source import scene_source

    doc = derivation_document(scene_id)
    declared = {r["unicode"] for r in doc["notation"] if r["kind"] in ("parameter", "coordinate")}
    assert "M" in declared and _mass_matrix_letter(doc["notation"]) not in declared
    mass_step = next(s for s in doc["steps"] if s["key"] == "mass-matrix")
    assert r"\mathcal{M}" in mass_step["latex"]
    assert not [m.group() for m in _BARE_M.finditer(json.dumps(doc, ensure_ascii=False))]
    scene = SCENES[scene_id]
    d = derivation(scene_id)
    words = notebook(scene_source(scene, d, scene_document(scene_id), tuple(float(x) for x in range(2 * len(d.table.q)))))
    markdown = [" ".join(c["source"]) if isinstance(c["source"], list) else c["source"] for c in json.loads(words)["cells"] if c["cell_type"] == "markdown"]  # fmt: skip
    assert any("mass matrix" in text for text in markdown)
    assert not [text for text in markdown if _BARE_M.search(text)]


@pytest.mark.slow
def test_a_typed_system_with_a_mass_m_left_as_m_inverse_f_names_the_mass_matrix_apart():
    # a typed chain whose last bob has the mass M: the first stage prints ℳ q̈ = f and ℳ = (…), never M q̈ = f
    from app.engine.document.contract import first_stage
    from app.service.users.user_checks import InvalidSystem, checked
    from app.service.users.user_jobs import derive_checked
    from app.web.pages.playground_stages import first_view

    doc = first_stage(derive_checked(checked(_CHAIN)))
    assert doc["accelerations"] == {} and len(doc["mass_matrix"]) == 3
    letter = _mass_matrix_letter(doc["notation"])
    assert letter != "M" and letter in doc["skipped"][0]["reason"]
    view = first_view(FirstStage.model_validate(doc), "/playground?stage=whole", "key")
    assert view["system"].startswith(r"\mathcal{M} \ddot{q} = f") and view["mass_matrix"].startswith(r"\mathcal{M} = ")
    assert not [m.group() for m in _BARE_M.finditer(json.dumps([doc, view], ensure_ascii=False))]
    # the same system with a parameter called f is refused: the refusal names the page's f without a bare M
    with pytest.raises(InvalidSystem) as refused:
        checked({**_CHAIN, "parameters": [*_CHAIN["parameters"], {"name": "f", "value": 1.0, "unit": ""}]})
    assert "q̈ = f" in str(refused.value) and not _BARE_M.search(str(refused.value))


def _reduction_rows(scene_id: str) -> tuple[str, dict[str, dict]]:
    doc = derivation_document(scene_id)
    step = next(s for s in doc["steps"] if s["key"] == "effective-potential")
    return step["latex"], {r["unicode"]: r for r in doc["notation"]}


def test_an_angles_inertia_is_a_moment_of_inertia_written_i():
    # prof-n 5: the simple pendulum printed m_eff = mR², a quantity in kg·m² written as a mass
    tex, rows = _reduction_rows("simple-pendulum")
    assert r"I_\text{eff} &= m R^{2}" in tex and r"m_\text{eff}" not in tex
    assert rows["I_eff"]["meaning"].startswith("effective moment of inertia of θ: the moment of inertia θ turns with")
    assert rows["I_eff"]["latex"] == r"I_\text{eff}" and rows["I_eff"]["unit"] == "kg·m²"
    assert "m_eff" not in rows


def test_a_lengths_inertia_stays_an_effective_mass():
    tex, rows = _reduction_rows("tabletop-spring")
    assert r"m_\text{eff} &= m" in tex and r"I_\text{eff}" not in tex
    assert rows["m_eff"]["meaning"].startswith("effective mass of r") and rows["m_eff"]["unit"] == "kg"
    assert "I_eff" not in rows


# the inertia's letter typed anywhere: m_eff, I_eff, m_\text{eff}, I_{\mathrm{eff}}
_INERTIA_LETTER = re.compile(r"\b[mI]_(?:eff\b|\\text\{eff\}|\{\\(?:text|mathrm)\{eff\}\})")


def _reader_strings(path: Path) -> list[tuple[int, str]]:
    """The string constants of a module a reader can be shown: every literal and f-string piece, docstrings aside."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docstrings = {
        id(node.body[0].value)
        for node in ast.walk(tree)
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
        and node.body
        and isinstance(node.body[0], ast.Expr)
        and isinstance(node.body[0].value, ast.Constant)
    }
    return [
        (node.lineno, node.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docstrings
    ]


@pytest.mark.slow
def test_the_inertias_letter_is_typed_in_one_place():
    # issue 40: the letter (I_eff for an angle, m_eff for a length) is chosen in app/engine/document/notation.py alone;
    # every step, sentence, hint and panel reads it from there
    root = Path(__file__).resolve().parents[3]
    home = root / "app" / "engine" / "document" / "notation.py"
    typed = [
        f"{path.relative_to(root)}:{line}: {text!r}"
        for path in sorted((root / "app").rglob("*.py"))
        if path != home
        for line, text in _reader_strings(path)
        if _INERTIA_LETTER.search(text)
    ]
    for path in sorted((root / "static" / "js").glob("*.js")):
        # the script without its comments
        code = re.sub(r"/\*.*?\*/|//[^\n]*", "", path.read_text(encoding="utf-8"), flags=re.S)
        typed += [f"{path.relative_to(root)}: {m.group()}" for m in _INERTIA_LETTER.finditer(code)]
    for path in sorted((root / "templates").rglob("*.html")):
        # the template without its comments; LaTeX in a Jinja string has its backslashes doubled
        page = re.sub(r"\{#.*?#\}", "", path.read_text(encoding="utf-8"), flags=re.S).replace("\\\\", "\\")
        typed += [f"{path.relative_to(root)}: {m.group()}" for m in _INERTIA_LETTER.finditer(page)]
    assert not typed, typed
    assert _INERTIA_LETTER.search(home.read_text(encoding="utf-8"))


def _said(doc: object) -> list[str]:
    """Every string a document gives a reader: its values, never its members' names (``forcing`` stays a key)."""
    if isinstance(doc, dict):
        return [s for v in doc.values() for s in _said(v)]
    if isinstance(doc, list):
        return [s for v in doc for s in _said(v)]
    return [doc] if isinstance(doc, str) else []


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_the_matrix_form_is_named_in_a_textbooks_words(scene_id):
    # prof-n 11: "Mass matrix and forcing" in every derivation; "forcing" is a numerical solver's word
    doc = derivation_document(scene_id)
    step = next(s for s in doc["steps"] if s["key"] == "mass-matrix")
    assert step["title"] == "The equations in matrix form"
    f = next(r for r in doc["notation"] if r["unicode"] == "f")
    assert f["meaning"].startswith("the terms without accelerations, moved to the right side of the equations")
    assert not [s for s in _said(doc) if re.search(r"\bforcing\b", s, re.I)]


@pytest.mark.slow
def test_a_system_left_as_m_inverse_f_says_what_f_is():
    from app.engine.document.contract import first_stage
    from app.service.users.user_checks import checked
    from app.service.users.user_jobs import derive_checked

    doc = first_stage(derive_checked(checked(_CHAIN)))
    note = doc["skipped"][0]["reason"]
    assert "f (the terms without accelerations, moved to the right side) shown" in note
    assert not [s for s in _said(doc) if re.search(r"\bforcing\b", s, re.I)]


@pytest.mark.slow
def test_a_typed_systems_matrix_step_says_what_f_is():
    # a typed system has no scene's sentence: the step's own words say what f is
    from app.engine.derivation.derive import derive
    from app.engine.document.contract import derivation_json
    from app.engine.parser.user_system import UserSystem

    spec = {
        "coordinates": ["x"],
        "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "k", "value": 2.0, "unit": "N/m"}],
        "lagrangian": "m/2*x_dot**2 - k/2*x**2",
    }
    doc = derivation_json(derive(UserSystem.of(spec).system()))
    step = next(s for s in doc["steps"] if s["key"] == "mass-matrix")
    assert step["title"] == "The equations in matrix form"
    assert "f the terms without accelerations, moved to the right side (the forces and the velocity terms)" in (
        step["explanation"]
    )
    assert not [s for s in _said(doc) if re.search(r"\bforcing\b", s, re.I)]


@pytest.mark.parametrize(("scene_id", "cartesian"), [("helix-bead", {"ξ", "η", "ζ"}), ("pulley", {"ζ₁", "ζ₂", "ζ₃"})])
def test_a_cartesian_letter_has_one_meaning_in_the_symbols_table(scene_id, cartesian):
    """prof-o F2: the helix writes its constraints in ξ, η, ζ (z is its coordinate), the pulley its L′ in ξᵢ, ηᵢ, ζᵢ;
    the table listed η as the modes' small displacement and left the helix's η and ζ out."""
    d = derivation(scene_id)
    rows = {r["unicode"]: r["meaning"] for r in notation.table(d, d.constraint_forces)}
    assert all(rows.get(c, "").startswith("Cartesian") for c in cartesian), rows
    # the small displacement takes a letter no Cartesian coordinate of the page is printed with
    assert notation.text("displacement", d) not in {"ξ", "η", "ζ"}


def test_no_conserved_momentum_is_said_held_where_there_is_none():
    """prof-o F8: the helix (no conserved momentum) read "(conserved momenta held fixed)" in its U_eff and m_eff rows;
    the wedge, whose X is cyclic, still says it."""
    helix = {r["unicode"]: r["meaning"] for r in notation.table(derivation("helix-bead"))}
    assert helix["U_eff"] and "conserved momenta" not in helix["U_eff"] + helix["m_eff"]
    wedge = {r["unicode"]: r["meaning"] for r in notation.table(derivation("movable-incline"))}
    assert "conserved momenta" in wedge["U_eff"] and "conserved momenta" in wedge["m_eff"]


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_a_position_vector_is_never_written_with_a_parameters_letter(scene_id):
    # review prof-q 4: the cylinder's radius is r, so its page writes the positions R⃗ (R⃗ = (X, 0, 0) for the
    # wedge, R⃗_cm for the cylinder's centre); every other page keeps r⃗, the puck's too, whose coordinate r is the
    # vector's own length
    doc = derivation_document(scene_id)
    parameters = {r["unicode"] for r in doc["notation"] if r["kind"] == "parameter"}
    rows = [s["latex"] for s in doc["steps"] if s["key"] in ("positions", "bodies")]
    vectors = {m.group(1) for tex in rows for m in re.finditer(r"\\vec\s*\\?([A-Za-z]+)", tex)}
    assert vectors, rows
    assert not {("ρ" if v == "rho" else v) for v in vectors} & parameters, (vectors, parameters)
    assert vectors == ({"R"} if scene_id == "rolling-cylinder-wedge" else {"r"}), vectors


@pytest.mark.slow
def test_practice_names_the_axes_greek_only_where_a_coordinate_takes_an_axis_name_without_being_that_displacement():
    from app.engine.derivation.derive import derive
    from app.engine.document.notation import practice_axes
    from app.scenes.types import Parameter, Particle, System

    # the massive pulley's z is m₂'s height, so m₁'s z is −z (prof-r 1); the helix's z turns the bead in x and y too
    assert practice_axes(derive(SCENES["massive-pulley"].system)) == ("xi", "eta", "zeta")
    assert practice_axes(derive(SCENES["helix-bead"].system)) == ("xi", "eta", "zeta")
    # a cart's x carries the cart and the bob along x alone: the axes keep their letters
    cart = System(
        coordinates=("x", "phi"),
        parameters=tuple(Parameter(n, 1.0, min=0.1) for n in ("M", "m", "l", "g")),
        particles=(Particle("M", ("x", "0", "0"), "cart"), Particle("m", ("x + l*sin(phi)", "0", "-l*cos(phi)"), "bob")),
        potential="-m*g*l*cos(phi)",
    )
    assert practice_axes(derive(cart)) == ("x", "y", "z")
    assert practice_axes(derive(SCENES["simple-pendulum"].system)) == ("x", "y", "z")
