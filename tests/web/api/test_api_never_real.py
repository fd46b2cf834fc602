"""POST /api/derive refuses an energy that is real nowhere with a 422 naming it (issue 32); L = U - T derives."""

import pytest

NEVER_REAL = ["sqrt(-1 - x**2)", "log(-1 - x**2)", "acos(2 + x**2)", "asin(2 + cos(x))", "(-1 - x**2)**(1/3)"]


@pytest.mark.parametrize("potential", NEVER_REAL)
def test_a_potential_real_nowhere_is_a_422_naming_it(client, potential):
    body = {"coordinates": ["x"], "parameters": ["k"], "kinetic": "x_dot**2/2", "potential": potential}
    response = client.post("/api/derive", json=body)
    assert response.status_code == 422, response.text
    text = response.text
    assert "not a real number anywhere" in text and "at x = " in text and "potential" in text


@pytest.mark.slow
def test_l_equal_to_u_minus_t_derives_with_its_equilibrium(client):
    body = {"coordinates": ["x"], "parameters": ["m", "k"], "lagrangian": "k*x**2/2 - m*x_dot**2/2"}
    response = client.post("/api/derive", json=body)
    assert response.status_code == 200, response.text
    (e,) = response.json()["normal_modes"]
    assert e["kind"] == "stable" and e["modes"][0]["omega_squared"] == pytest.approx(1.0)
