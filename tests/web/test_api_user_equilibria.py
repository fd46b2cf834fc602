"""POST /api/derive: the Equilibria step of a typed system states what it found as a textbook does (issue 40):
every configuration (V ≡ 0), a family, none, isolated points in closed form, each once."""

from __future__ import annotations


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
    assert titles == ["Normal modes about θ = 0", "Normal modes about θ = π"]
    # the letters of the page, each once, served with the document
    letters = [row["unicode"] for row in doc["notation"]]
    assert len(letters) == len(set(letters)) and {"θ", "m", "g", "l", "M", "K", "ω"} <= set(letters)


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
