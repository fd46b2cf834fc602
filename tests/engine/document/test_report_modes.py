"""The new JSON blocks and steps: ``hamilton`` and ``normal_modes`` in every derivation document."""

import math
import re

import pytest
import sympy as sp

from app.engine.document.model import Document
from app.scenes import SCENES
from app.service.chapter.derivations import derivation_document
from tests.reference import numerically_equal


def names_of(doc):
    names = {"t": sp.Symbol("t", real=True)}
    for q in doc["coordinates"]:
        for s in ("", "_dot"):
            names[q + s] = sp.Symbol(q + s, real=True)
        names[f"p_{q}"] = sp.Symbol(f"p_{q}", real=True)
    names |= {p: sp.Symbol(p, real=True) for p in doc["parameters"]}
    return names


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_hamilton_block_parses_and_its_hamiltonian_is_h(scene_id):
    doc = derivation_document(scene_id)
    Document.model_validate(doc)  # the model holds
    names = names_of(doc)
    ham = doc["hamilton"]
    assert [e["coordinate"] for e in ham["equations"]] == doc["coordinates"]
    H = sp.sympify(ham["hamiltonian"]["sympy"], locals=names)
    momenta = {names[f"p_{q}"]: sp.sympify(doc["momenta"][q]["sympy"], locals=names) for q in doc["coordinates"]}
    h = sp.sympify(doc["hamiltonian"]["sympy"], locals=names)
    symbols = sorted(set(names.values()), key=str)
    assert numerically_equal(H.xreplace(momenta), h, symbols)
    for e in ham["equations"]:
        # q_dot(q, p) evaluated at p = p(q, q_dot) is the velocity itself
        v = sp.sympify(e["q_dot"]["sympy"], locals=names).xreplace(momenta)
        assert numerically_equal(v, names[e["coordinate"] + "_dot"], symbols)
        assert e["p_dot"]["latex"] and e["q_dot"]["latex"]
    titles = [s["title"] for s in doc["steps"]]
    assert titles.index("Hamilton's equations") > titles.index("Energy function h")


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_normal_modes_block_has_numbers_at_the_defaults(scene_id):
    doc = derivation_document(scene_id)
    names = names_of(doc)
    defaults = {names[p]: v["default"] for p, v in doc["parameters"].items()}
    titles = [s["title"] for s in doc["steps"]]
    assert "Equilibria" in titles
    for entry in doc["normal_modes"]:
        assert set(entry["equilibrium"]) <= set(doc["coordinates"])
        assert entry["kind"] in ("stable", "neutral", "unstable")
        assert entry["stable"] == (entry["kind"] != "unstable")
        assert entry["stable"] == all(m["omega_squared"] > -1e-9 for m in entry["modes"])
        for m in entry["modes"]:
            assert math.isfinite(m["omega_squared"]) and set(m["shape"]) == set(entry["equilibrium"])
            if m["sympy"] is not None:
                value = sp.sympify(m["sympy"], locals=names).xreplace(defaults)
                assert float(value) == pytest.approx(m["omega_squared"], rel=1e-9, abs=1e-12)
                assert m["latex"]


def test_which_scenes_have_which_equilibria():
    kinds = {sid: [e["kind"] for e in derivation_document(sid)["normal_modes"]] for sid in SCENES}
    assert kinds["simple-pendulum"] == ["stable", "unstable"]
    assert kinds["rail-two-body"] == ["neutral"]
    assert kinds["double-pendulum"] == ["stable", "unstable", "unstable", "unstable"]
    assert kinds["coupled-oscillators"] == ["stable"]
    # the conical orbit of the spherical pendulum, at the scene's own p_phi, listed once: its mirror -theta0 is
    # the same cone described with phi + pi (the ball is at the same place), so it is not listed again
    (conical,) = derivation_document("spherical-pendulum")["normal_modes"]
    assert conical["momenta"] == {"p_phi": pytest.approx(2.0 * math.sin(2.2) ** 2)}
    assert conical["equilibrium"]["theta"] > 0
    for sid in ("helix-bead", "incline-block", "pulley", "movable-incline", "rolling-cylinder-wedge"):
        assert kinds[sid] == []


def test_a_mode_is_printed_as_its_frequency_and_a_column_of_amplitudes():
    # Taylor §11: ω₁² = k/m, a₁ = (1, 1)ᵀ as a column, the coordinates' order said once above the modes
    steps = {s["key"]: s for s in derivation_document("coupled-oscillators")["steps"]}
    served = steps["normal-modes:1"]["latex"]
    assert (
        r"\\ &\text{amplitudes of } (x_{1}, x_{2})\text{:} \\ "
        r"\omega_{1}^2 &= \frac{k}{m} \approx 10\,\mathrm{s}^{-2},\quad a_{1} = \begin{pmatrix}1\\1\end{pmatrix} \\ "
        r"\omega_{2}^2 &= \frac{k + 2 \kappa}{m} \approx 12\,\mathrm{s}^{-2},\quad a_{2} = \begin{pmatrix}1\\-1\end{pmatrix}"
        r"\end{aligned}"
    ) in served
    assert "shape" not in served and served.count("amplitudes of") == 1
    assert "in the order shown (x₁, x₂)" in steps["normal-modes:1"]["explanation"]
    # an exact component stays exact inside its column; numbers keep four figures
    rail = {s["key"]: s for s in derivation_document("rail-two-body")["steps"]}["normal-modes:1"]["latex"]
    assert r"\omega_{1}^2 &= 0,\quad a_{1} = \begin{pmatrix}1\\1\end{pmatrix}" in rail
    assert r"a_{2} = \begin{pmatrix}1\\- \frac{m_{1}}{m_{2}}\end{pmatrix}" in rail
    pendulum = {s["key"]: s for s in derivation_document("double-pendulum")["steps"]}["normal-modes:1"]["latex"]
    assert r"a_{1} = \begin{pmatrix}0.7071\\1\end{pmatrix}" in pendulum
    # the API's JSON keeps the shape as a mapping from coordinate to amplitude
    (entry,) = derivation_document("coupled-oscillators")["normal_modes"]
    assert [m["shape"] for m in entry["modes"]] == [{"x1": 1.0, "x2": 1.0}, {"x1": 1.0, "x2": -1.0}]


def test_a_long_radicand_in_omega_squared_is_named_on_a_line_of_its_own():
    # issue 40: the double pendulum's ω² was ((m₁ + m₂)(l₁ + l₂) ∓ √((m₁ + m₂)(…)))g/(2m₁l₁l₂), wider than a phone;
    # as a textbook sets it, the radicand is named Δ once and ω² is its factor before a bracket that may break
    steps = {s["key"]: s for s in derivation_document("double-pendulum")["steps"]}
    served = steps["normal-modes:1"]["latex"]
    assert (
        r"\Delta &= \left(m_{1} + m_{2}\right)^{2} \left(l_{1} - l_{2}\right)^{2} "
        r"+ 4 \left(m_{1} + m_{2}\right) m_{2} l_{1} l_{2} \\ "
    ) in served
    bracket = r"\left(m_{1} + m_{2}\right) \left(l_{1} + l_{2}\right)"
    assert (
        rf"\omega_{{1}}^2 &= \frac{{g}}{{2 m_{{1}} l_{{1}} l_{{2}}}} \Bigl[{bracket} - \sqrt{{\Delta}}\Bigr] \approx 5.747"
        in served
    )
    assert (
        rf"\omega_{{2}}^2 &= \frac{{g}}{{2 m_{{1}} l_{{1}} l_{{2}}}} \Bigl[{bracket} + \sqrt{{\Delta}}\Bigr] \approx 33.49"
        in served
    )
    assert (
        served.count(r"\sqrt") == 2
        and "Δ is the quantity under the square root" in steps["normal-modes:1"]["explanation"]
    )
    # both rods upright: a negative factor before the bracket, and the root first where the rest is negative
    top = steps["normal-modes:4"]["latex"]
    assert (
        rf"\omega_{{1}}^2 &= - \frac{{g}}{{2 m_{{1}} l_{{1}} l_{{2}}}} \Bigl[{bracket} + \sqrt{{\Delta}}\Bigr]" in top
    )
    assert rf"\Bigl[\sqrt{{\Delta}} - {bracket}\Bigr] \approx -5.747" in top
    # a short ω² keeps its form: no Δ where nothing is too wide
    coupled = {s["key"]: s for s in derivation_document("coupled-oscillators")["steps"]}["normal-modes:1"]["latex"]
    assert r"\Delta" not in coupled
    # the API's closed form of each ω² is unchanged (the root written out)
    (first, *_) = derivation_document("double-pendulum")["normal_modes"]
    assert all(r"\sqrt{\left(m_{1} + m_{2}\right)" in m["latex"] for m in first["modes"])


def test_a_runaway_rate_is_printed_over_its_whole_radicand():
    # about θ = π the physical pendulum's ω² = −3g/(2l): its rate is √(3g/(2l)), not SymPy's √6 √(g/l)/2
    doc = derivation_document("physical-pendulum")
    latex = " ".join(row for s in doc["steps"] for row in [s["latex"]] if "runs away" in s["latex"])
    assert r"\sqrt{\frac{3 g}{2 l}}" in latex and r"\sqrt{6}" not in latex


def _figures_in(number: str) -> int:
    return len(number.replace(".", "").lstrip("0"))


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_a_number_found_numerically_is_printed_to_four_figures(scene_id):
    # prof-k 13: the spherical pendulum's steady motion printed θ = 2.48602, p_φ = 1.30733 kg m² s⁻¹
    for step in derivation_document(scene_id)["steps"]:
        long = [n for n in re.findall(r"\d+\.\d+", step["latex"]) if _figures_in(n) > 4]
        assert not long, (step["key"], long)


def test_the_steady_conical_motion_reads_theta_and_its_held_momentum_to_four_figures():
    steps = {s["key"]: s["latex"] for s in derivation_document("spherical-pendulum")["steps"]}
    steady = next(latex for key, latex in steps.items() if key.startswith("steady-motion"))
    assert re.search(r"2\.486(?!\d)", steady) and re.search(r"1\.307(?!\d)", steady), steady
