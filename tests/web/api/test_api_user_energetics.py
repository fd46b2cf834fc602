"""The API and the pages on h = E: undecided when only L is given, and whether h is conserved (issue 19)."""

from urllib.parse import urlencode

import pytest

from app.web.pages.playground_form import form_of, query_of
from tests.engine.derivation.test_energetics import KAPITZA

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


def lagrangian_spec(lagrangian):
    return {
        "coordinates": ["theta"],
        "parameters": [{"name": n, "value": 1.0} for n in ("m", "l", "a", "omega", "g")],
        "lagrangian": lagrangian,
    }


@pytest.mark.parametrize(
    ("lagrangian", "conserved"), [(KAPITZA, False), ("m*l**2*theta_dot**2/2 + m*g*l*cos(theta)", True)]
)
def test_the_api_and_the_page_say_undecided_and_whether_h_is_conserved(client, lagrangian, conserved):
    spec = lagrangian_spec(lagrangian)
    doc = client.post("/api/derive", json=spec).json()
    assert doc["hamiltonian_equals_energy"] is None and "cannot be told apart" in doc["hamiltonian_energy_reason"]
    assert doc["hamiltonian_conserved"] is conserved
    html = client.get("/playground?" + urlencode({**query_of(form_of(spec)), "stage": "whole"}, doseq=True)).text
    assert "Whether h = E cannot be decided." in html and "h = E.<" not in html
    assert ("h is conserved." if conserved else "h is not conserved.") in html
