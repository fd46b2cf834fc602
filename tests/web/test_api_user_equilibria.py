"""POST /api/derive: the Equilibria step of a typed system states what it found as a textbook does (issue 40):
every configuration (V ≡ 0), a family, none, isolated points in closed form, each once."""

from __future__ import annotations

import sympy as sp


def derive(client, body):
    response = client.post("/api/derive", json=body)
    assert response.status_code == 200, response.text
    return response.json()


def steps(doc, prefix):
    return [s for s in doc["steps"] if s["key"].startswith(prefix)]


def test_a_charge_in_a_uniform_magnetic_field_is_at_rest_anywhere(client):
    doc = derive(
        client,
        {
            "coordinates": ["x", "y"],
            "parameters": ["m", "B", "e"],
            "lagrangian": "m*(x_dot**2 + y_dot**2)/2 + e*B*(x*y_dot - y*x_dot)/2",
        },
    )
    (eq,) = steps(doc, "equilibria")
    assert r"\text{every configuration is an equilibrium}" in eq["latex"]
    # not one point picked out as if it were the only one
    assert "x = 0" not in eq["latex"].replace(" ", "") and "x &= 0" not in eq["latex"]
    assert "every configuration is an equilibrium" in eq["explanation"] and "turn" in eq["explanation"]
    (modes,) = steps(doc, "normal-modes")
    assert modes["title"] == "Normal modes about any configuration"
    assert r"\text{any } x,\; y" in modes["latex"]


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
    assert len(letters) == len(set(letters)) and {"θ", "m", "g", "l", "𝓜", "K", "ω"} <= set(letters)


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
    # prof-f 32, 33: "[[0, I], [−𝓜⁻¹K, −𝓜⁻¹G]]" in prose, "One is zero" beside s = 0, 0, 0 ± 2 i (m = 1, eB = 2)
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
