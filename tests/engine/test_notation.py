"""One letter, one quantity: every scene's served document (its Symbols table, steps and results) read whole.

Issue 40's first complaint was a letter naming two quantities (ω the turning rate and ω² the frequency on the
rotating parabola; s the exponent and the second).  These tests read what the API serves, not the code that
chooses the letters.
"""

from __future__ import annotations

import re

import pytest

from app.scenes import SCENES
from app.service.derivations import derivation_document

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



def test_the_letters_of_a_constraint_are_read_from_one_home(monkeypatch):
    # issue 40: F₁, λ₁ and 𝒞₁ were each spelled in the Symbols table, the steps of the forces of constraint and
    # the page's Results; with other letters given in notation.py, all three print those and none of the old.
    # The served document is read before the letters change, and nothing below goes through a cache.
    from app.engine import notation
    from app.engine.derive import derive, value_or
    from app.engine.report import Printer
    from app.engine.report_members import constraint_steps
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
    shown = scene_page(doc, {"title": "helix"})["summary"]["constraint_forces"]
    assert [f["symbol"] for f in shown] == ["G_{1}", "G_{2}"]
    assert all(f["latex"].startswith(f["symbol"] + " = ") for f in shown)
