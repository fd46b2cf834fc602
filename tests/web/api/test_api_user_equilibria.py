"""POST /api/derive: the Equilibria step of a typed system states what it found as a textbook does (issue 40):
every configuration (V ≡ 0), a family, none, isolated points in closed form, each once."""

from __future__ import annotations

import pytest
import sympy as sp

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def derive(client, body):
    response = client.post("/api/derive", json=body)
    assert response.status_code == 200, response.text
    return response.json()


# a charge e in a uniform magnetic field B along z (vector potential ½B(−y, x, 0)), no potential
CHARGE_IN_FIELD = {
    "coordinates": ["x", "y"],
    "parameters": ["m", "B", "e"],
    "lagrangian": "m*(x_dot**2 + y_dot**2)/2 + e*B*(x*y_dot - y*x_dot)/2",
}


def steps(doc, prefix):
    return [s for s in doc["steps"] if s["key"].startswith(prefix)]


def test_a_charge_in_a_uniform_magnetic_field_is_at_rest_anywhere(client):
    doc = derive(client, CHARGE_IN_FIELD)
    (eq,) = steps(doc, "equilibria")
    assert r"\text{every configuration is an equilibrium}" in eq["latex"]
    # not one point picked out as if it were the only one
    assert "x = 0" not in eq["latex"].replace(" ", "") and "x &= 0" not in eq["latex"]
    assert "every configuration is an equilibrium" in eq["explanation"] and "turn" in eq["explanation"]
    (modes,) = steps(doc, "normal-modes")
    assert modes["title"] == "Normal modes about any configuration"
    assert r"\text{any } x,\; y" in modes["latex"]


def test_a_charge_in_a_magnetic_field_has_its_squares_completed_and_its_potential_named_as_on_the_page(client):
    # prof-n 9: H printed (B²e²x²/4 + B²e²y²/4 + Be p_x y − Be p_y x + p_x² + p_y²)/(2m), and "V does not depend"
    # beside rows that write U_eff
    doc = derive(client, CHARGE_IN_FIELD)
    (H,) = steps(doc, "hamiltonian-pq")
    shown = H["latex"].split("=")[-1].replace(" ", "")
    assert r"\left(p_{y}-Bex/2\right)^{2}" in shown and r"\left(Bey/2+p_{x}\right)^{2}" in shown
    assert shown.endswith("{2m}") and "B^{2}" not in shown
    (eq,) = steps(doc, "equilibria")
    assert r"U_\text{eff} &= -L" in eq["latex"]
    assert "U_eff does not depend on the coordinates" in eq["explanation"] and "V " not in eq["explanation"]


def test_a_typed_spring_between_two_carts_has_a_family(client):
    doc = derive(
        client,
        {
            "coordinates": ["x1", "x2"],
            "parameters": ["m", "k", "l0"],
            "lagrangian": "m*(x1_dot**2 + x2_dot**2)/2 - k*(x2 - x1 - l0)**2/2",
        },
    )
    (eq,) = steps(doc, "equilibria")
    assert r"\text{every state with } x_{2} - x_{1} &= l_{0}" in eq["latex"]
    assert "set to 0" not in eq["explanation"] and "every state that satisfies them" in eq["explanation"]
    (modes,) = steps(doc, "normal-modes")
    assert modes["title"] == "Normal modes about the equilibria x₂ − x₁ = l₀"


def test_a_typed_block_on_a_slope_has_none(client):
    doc = derive(
        client,
        {"coordinates": ["x"], "parameters": ["m", "g", "a"], "lagrangian": "m*x_dot**2/2 - m*g*sin(a)*x"},
    )
    (eq,) = steps(doc, "equilibria")
    assert r"\neq 0" in eq["latex"] and r"\text{no equilibrium}" in eq["latex"]
    assert not steps(doc, "normal-modes")
    for s in steps(doc, "reduced-equilibria"):
        assert r"\neq 0" in s["latex"] and r"\omega^2" not in s["latex"]


def test_a_typed_pendulum_names_the_top_pi(client):
    doc = derive(
        client,
        {"coordinates": ["theta"], "parameters": ["m", "g", "l"], "lagrangian": "m*l**2*theta_dot**2/2 + m*g*l*cos(theta)"},
    )
    titles = [s["title"] for s in steps(doc, "normal-modes")]
    # one coordinate: small oscillations at the bottom, a runaway at the top (no "normal mode" of ω² < 0)
    assert titles == ["Small oscillations about θ = 0", "No oscillation about θ = π"]
    # the letters of the page, each once, served with the document
    letters = [row["unicode"] for row in doc["notation"]]
    assert len(letters) == len(set(letters)) and {"θ", "m", "g", "l", "ℳ", "K", "ω"} <= set(letters)


def test_a_typed_particle_on_a_cone_keeps_no_sin_squared_plus_cos_squared(client):
    doc = derive(
        client,
        {
            "coordinates": ["r", "phi"],
            "parameters": ["m", "g", "alpha"],
            "particles": [{"mass": "m", "position": ["r*sin(alpha)*cos(phi)", "r*sin(alpha)*sin(phi)", "r*cos(alpha)"]}],
            "potential": "m*g*r*cos(alpha)",
        },
    )
    for s in doc["steps"]:
        assert r"\sin^{2} {\alpha} + \cos^{2} {\alpha}" not in s["latex"], (s["key"], s["latex"])
    (radial,) = [e["latex"] for e in doc["equations_of_motion"] if e["coordinate"] == "r"]
    assert radial.startswith(r"\ddot{r}")


# the reviewer's cone: r the distance from the axis, the height r/tan a, r declared a distance
CONE_BY_ITS_AXIS = {
    "coordinates": ["r", "phi"],
    "parameters": [
        {"name": "m", "value": 1.0, "unit": "kg", "min": 0.0},
        {"name": "g", "value": 9.81, "unit": "m/s^2", "min": 0.0},
        {"name": "a", "value": 0.5, "unit": "rad", "min": 0.0},
    ],
    "particles": [{"mass": "m", "position": ["r*cos(phi)", "r*sin(phi)", "r/tan(a)"]}],
    "potential": "m*g*r/tan(a)",
    "nonnegative": ["r"],
}


def test_a_cone_by_its_axis_prints_its_equation_with_the_factor_cancelled(client):
    """T = ½m(ṙ²/sin²a + r²φ̇²): divided by m/sin²a, r̈ − r φ̇² sin²a + g sin a cos a = 0, with no
    (1 + 1/tan²a)/(1 + 1/tan²a)² left standing."""
    doc = derive(client, CONE_BY_ITS_AXIS)
    (eq,) = steps(doc, "euler-lagrange")
    assert r"1 / \tan^{2}" not in eq["latex"] and r"\tan" not in eq["latex"], eq["latex"]
    r, a, g, phi_dot = (sp.Symbol(n) for n in ("r", "a", "g", "phi_dot"))
    radial = sp.sympify(eq["sympy"].strip("[]").rsplit(", phi_ddot", 1)[0], locals={"r": r, "a": a, "g": g})
    textbook = sp.Symbol("r_ddot") - r * phi_dot**2 * sp.sin(a) ** 2 + g * sp.sin(a) * sp.cos(a)
    assert sp.expand(radial - textbook) == 0


def test_a_cone_by_its_axis_gives_the_steady_motion_frequency_in_terms_of_its_radius(client):
    """U_eff = p_φ²/(2mr²) + mgr/tan a: U_eff′(r₀) = 0 gives p_φ² = m²g r₀³/tan a, so
    ω² = U_eff″/m_eff = 3p_φ² sin²a/(m²r₀⁴) = 3g sin a cos a / r₀, free of p_φ."""
    doc = derive(client, CONE_BY_ITS_AXIS)
    (step,) = steps(doc, "reduced-equilibria")
    assert r"\omega^2 &= \frac{3 g \sin {a} \cos {a}}{r_{0}}" in step["latex"], step["latex"]
    assert "p_{\\phi}^{2}" not in step["latex"] and "8}{3}" not in step["latex"]
    assert "gives p_φ² in terms of r₀" in step["explanation"]


def test_where_the_numerical_search_looked_is_said_in_plain_words(client):
    """A slider on a spring carrying a pendulum: the search's range is written with the names as printed, a true
    minus sign and 'a full turn', never program text such as 'searched: x from -80 to 80, theta'."""
    doc = derive(
        client,
        {
            "coordinates": ["x", "theta"],
            "parameters": [
                {"name": "M", "value": 2.0, "unit": "kg"},
                {"name": "m", "value": 1.0, "unit": "kg"},
                {"name": "l", "value": 1.0, "unit": "m"},
                {"name": "k", "value": 20.0, "unit": "N/m"},
                {"name": "g", "value": 9.81, "unit": "m/s^2"},
            ],
            "particles": [
                {"mass": "M", "position": ["x", "0"]},
                {"mass": "m", "position": ["x + l*sin(theta)", "-l*cos(theta)"]},
            ],
            "potential": "k*x**2/2 - m*g*l*cos(theta)",
        },
    )
    (eq,) = steps(doc, "equilibria")
    words = eq["explanation"]
    assert "searched:" not in words and "theta" not in words and "-80" not in words, words
    # the bound is four times the largest parameter, k = 20 N/m
    assert "x between −80 and 80 and θ over a full turn" in words, words
    # every sentence opens with a capital letter
    for sentence in words.split(". ")[1:]:
        assert sentence[:1].isupper(), sentence


def test_a_charge_in_a_magnetic_field_counts_its_zero_exponents_and_says_where_its_frequency_comes_from(client):
    # prof-f 32, 33: "[[0, I], [−ℳ⁻¹K, −ℳ⁻¹G]]" in prose, "One is zero" beside s = 0, 0, 0 ± 2 i (m = 1, eB = 2)
    doc = derive(
        client,
        {
            "coordinates": ["x", "y"],
            "parameters": [{"name": "m", "value": 1}, {"name": "B", "value": 1}, {"name": "e", "value": 2}],
            "lagrangian": "m*(x_dot**2 + y_dot**2)/2 + e*B*(x*y_dot - y*x_dot)/2",
        },
    )
    (modes,) = steps(doc, "normal-modes")
    said = modes["explanation"]
    # the exponents λ (no constraint here, so λ is free), never r, the position, nor s, the unit (prof-h 10)
    assert "[[" not in said and "the roots of det(λ²" in said
    assert "Two are zero (free drifts), the others are ±2i (oscillations at 2 rad/s)" in said
    assert "come from the velocity terms G alone" in said and "One is zero" not in said
    assert r"\pm 2i" in modes["latex"] and r"0 \pm" not in modes["latex"]


def _typed_hoop(w: float) -> dict:
    """Prof. K's bead on a spinning hoop as typed in the playground: a particle, and m, R, g positive by their
    units (the form's lowest value just above 0), w any real number."""
    positive = {"min": 1e-9}
    return {
        "coordinates": ["theta"],
        "parameters": [
            {"name": "m", "value": 0.1, "unit": "kg", **positive},
            {"name": "R", "value": 0.5, "unit": "m", **positive},
            {"name": "g", "value": 9.81, "unit": "m/s^2", **positive},
            {"name": "w", "value": w, "unit": "rad/s"},
        ],
        "particles": [{"mass": "m", "position": ["R*sin(theta)*cos(w*t)", "R*sin(theta)*sin(w*t)", "-R*cos(theta)"]}],
        "potential": "-m*g*R*cos(theta)",
    }


def _about(doc, where):
    return next(s for s in steps(doc, "normal-modes") if s["title"].endswith(f"about {where}"))


def test_a_typed_hoops_bottom_states_when_it_is_stable_above_and_below_the_bifurcation(client):
    # prof-k 1: "ω² = (g − Rw²)/R < 0 … unstable" printed as if true for every w
    for w, sign in ((7.0, "<"), (3.0, ">")):
        bottom = _about(derive(client, _typed_hoop(w)), "θ = 0")
        assert r"\text{stable when } g > R w^{2},\quad \text{unstable when } R w^{2} > g" in bottom["latex"], w
        assert "positive, a stable equilibrium, when g > Rw², and negative, an unstable one, when Rw² > g" in bottom[
            "explanation"
        ]
        # the sign shown is the current parameters' own, and said so in the equation
        assert (r"{\;<\;0}\quad\text{atthecurrentparameters}" in bottom["latex"].replace(" ", "")) == (sign == "<"), w
        assert "at the current parameters" in bottom["explanation"]
    # the top is unstable for every w: no condition, no "at the current parameters"
    top = _about(derive(client, _typed_hoop(7.0)), "θ = π")
    assert "stable when" not in top["latex"] and "current parameters" not in top["latex"]


def test_a_typed_hoops_side_equilibria_say_where_they_exist_and_stay_listed_where_they_do_not(client):
    # prof-k 1: θ = ±arccos(g/(Rw²)) with no "exists only when Rw² > g", and gone without a word at w = 3
    spinning = derive(client, _typed_hoop(7.0))
    (eq,) = steps(spinning, "equilibria")
    side = r"\arccos {\frac{g}{R w^{2}}}\quad (\text{exists only when } R w^{2} > g)"
    assert eq["latex"].count(side) == 2
    tilted = _about(spinning, "θ = arccos(g/(Rw²))")
    assert r"\text{exists only when } R w^{2} > g,\quad \text{and there } \omega^2 > 0" in tilted["latex"]
    assert "it is stable wherever it exists" in tilted["explanation"]
    slow = derive(client, _typed_hoop(3.0))
    (eq,) = steps(slow, "equilibria")
    gone = r"\arccos {\frac{g}{R w^{2}}}\quad (\text{exists only when } R w^{2} > g) \\ &(\text{not at the current parameters})"
    assert eq["latex"].count(gone) == 2
    assert (
        "θ = −arccos(g/(Rw²)) and θ = arccos(g/(Rw²)) are equilibria only when Rw² > g, which does not hold at the "
        "current parameters" in eq["explanation"]
    )
    assert "where they exist, ω² = w² − g²/(R²w²) is positive (stable)" in eq["explanation"]
    # no small oscillations are worked out about a place that is not there
    assert [s["title"] for s in steps(slow, "normal-modes")] == [
        "Small oscillations about θ = 0",
        "No oscillation about θ = π",
    ]


def test_the_spherical_pendulums_poles_say_which_is_stable(client):
    # prof-k 4: "θ = 0 (the coordinates fail: φ has no value)" at both poles, with no stable or unstable
    response = client.get("/api/scenes/spherical-pendulum/derivation")
    assert response.status_code == 200, response.text
    (eq,) = steps(response.json(), "equilibria")
    # θ is measured from the upward vertical: U = mgR cos θ is greatest at θ = 0, least at θ = π
    assert r"\theta &= 0:\quad \text{unstable} \\ &(\text{a maximum of } U \text{ along } \theta) \\" in eq["latex"]
    assert (
        r"\theta &= \pi:\quad \text{stable},\quad \omega^2 = \frac{g}{R} \\ &(\text{a minimum of } U \text{ along } "
        r"\theta) \\" in eq["latex"]
    )
    assert eq["latex"].count(r"&(\text{the coordinates fail: } \varphi \text{ has no value})") == 2


def test_a_typed_pendulum_on_a_sliding_spring_mounted_pivot_prints_its_discriminant_as_a_square_less_a_product(client):
    # prof-k 5: "Δ = M²g² + m²g² + k²l² + 2Mmg² + 2mgkl − 2Mgkl", and "ml cos θθ̈"
    positive = {"min": 1e-9}
    doc = derive(
        client,
        {
            "coordinates": ["X", "theta"],
            "parameters": [
                {"name": "M", "value": 1.0, "unit": "kg", **positive},
                {"name": "m", "value": 0.5, "unit": "kg", **positive},
                {"name": "l", "value": 0.5, "unit": "m", **positive},
                {"name": "k", "value": 20.0, "unit": "N/m", **positive},
                {"name": "g", "value": 9.81, "unit": "m/s^2", **positive},
            ],
            "particles": [
                {"mass": "M", "position": ["X", "0", "0"]},
                {"mass": "m", "position": ["X + l*sin(theta)", "0", "-l*cos(theta)"]},
            ],
            "potential": "k*X**2/2 - m*g*l*cos(theta)",
        },
    )
    below, above = steps(doc, "normal-modes")
    assert r"\Delta &= \left[\left(M + m\right) g + k l\right]^{2} - 4 M g k l \\" in below["latex"]
    assert r"\Delta &= \left[k l - \left(M + m\right) g\right]^{2} + 4 M g k l \\" in above["latex"]
    (el,) = steps(doc, "euler-lagrange")
    assert r"m l \ddot{\theta} \cos {\theta} - m l \dot{\theta}^{2} \sin {\theta}" in el["latex"]
    assert r"l \ddot{\theta} + \ddot{X} \cos {\theta} + g \sin {\theta} = 0" in el["latex"]


def test_a_shaken_pivots_equilibria_are_printed_exactly(client):
    # prof-n 9: "θ = 3.142 (coefficients change with t)" where the time-independent equilibria print π
    doc = derive(
        client,
        {
            "coordinates": ["theta"],
            "parameters": ["m", "l", "g", "a", "w"],
            "lagrangian": "m*(l**2*theta_dot**2 + 2*l*theta_dot*a*w*sin(w*t)*sin(theta) + a**2*w**2*sin(w*t)**2)/2"
            " + m*g*(l*cos(theta) + a*cos(w*t))",
        },
    )
    (eq,) = steps(doc, "equilibria")
    assert r"\theta &= \pi\quad (\text{coefficients change with } t)" in eq["latex"]
    assert r"\theta &= 0\quad (\text{coefficients change with } t)" in eq["latex"]
    assert "3.142" not in eq["latex"]


def test_a_particle_in_a_cone_has_its_steady_motions_frequency_in_r0_alone(client):
    # prof-n 9: ω² = 3 m^{2/3} g^{4/3} p_φ²/[(1/(sin²a cos a))^{4/3} sin²a |p_φ|^{8/3}] one step after 3g cos a/r₀
    doc = derive(
        client,
        {
            "coordinates": ["r", "phi"],
            "parameters": ["m", "g", "a"],
            "lagrangian": "m*(r_dot**2 + r**2*sin(a)**2*phi_dot**2)/2 - m*g*r*cos(a)",
        },
    )
    (steady,) = steps(doc, "steady-motion")
    (rows,) = [row for row in steady["latex"].split(r"\\") if r"\omega^2" in row]
    assert r"\omega^2 &= \frac{3 g \cos {a}}{r_{0}} \approx" in rows
    assert "p_{\\varphi}" not in rows and "frac{4}{3}" not in rows
    assert "written in r₀, the steady motion's r, with p_φ eliminated by U_eff′(r₀) = 0" in steady["explanation"]
