"""The scenes API follows its contract."""

import pytest
import sympy as sp

from app.scenes import SCENES
from tests.reference import numerically_equal


def names_for(doc):
    names = {}
    for q in doc["coordinates"]:
        for suffix in ("", "_dot", "_ddot"):
            names[q + suffix] = sp.Symbol(q + suffix, real=True)
    for p in doc["parameters"]:
        names[p] = sp.Symbol(p, real=True)
    names["t"] = sp.Symbol("t", real=True)
    return names


def test_list_scenes(client):
    response = client.get("/api/scenes")
    assert response.status_code == 200
    items = response.json()
    assert {item["id"] for item in items} == set(SCENES)
    for item in items:
        assert {"id", "title", "section", "coordinates", "parameters"} <= set(item)
        for info in item["parameters"].values():
            assert {"default", "unit", "min", "max"} <= set(info)


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_derivation_contract(client, scene_id):
    response = client.get(f"/api/scenes/{scene_id}/derivation")
    assert response.status_code == 200
    doc = response.json()
    names = names_for(doc)
    for key in ("lagrangian", "hamiltonian", "energy"):
        assert set(doc[key]) >= {"sympy", "latex"}
        sp.sympify(doc[key]["sympy"], locals=names)
    assert [e["coordinate"] for e in doc["equations_of_motion"]] == doc["coordinates"]
    assert set(doc["accelerations"]) == set(doc["coordinates"]) == set(doc["momenta"])
    for c in doc["conserved"]:
        assert {"name", "sympy", "latex", "reason"} <= set(c)
    assert isinstance(doc["hamiltonian_equals_energy"], bool) and doc["hamiltonian_energy_reason"]
    assert doc["steps"] and all(set(s) == {"key", "title", "latex", "sympy", "explanation"} for s in doc["steps"])
    # velocities print with dots, never as q_dot
    assert "_dot" not in doc["lagrangian"]["latex"] and r"\dot" in doc["lagrangian"]["latex"]
    # every equation of motion, evaluated with the served accelerations, vanishes (at random states:
    # simplify cannot always prove it for the double pendulum's angle differences)
    subs = {names[f"{q}_ddot"]: sp.sympify(doc["accelerations"][q]["sympy"], locals=names) for q in doc["coordinates"]}
    symbols = sorted(names.values(), key=str)
    for eq in doc["equations_of_motion"]:
        residual = sp.sympify(eq["sympy"], locals=names).xreplace(subs)
        assert numerically_equal(residual, sp.Integer(0), symbols)


def test_unknown_scene_is_404_with_a_message(client):
    response = client.get("/api/scenes/no-such-scene/derivation")
    assert response.status_code == 404
    assert "known scenes" in response.json()["detail"]


def test_health(client):
    assert client.get("/healthz").json() == {"status": "ok"}


def test_the_openapi_describes_the_derivations_by_the_document_model(client):
    """The served documents' schema is the model they are built from (app/engine/document/model.py), closed to keys it
    does not name."""
    spec = client.get("/openapi.json").json()
    for path, method, model in (
        ("/api/scenes/{scene_id}/derivation", "get", "Document"),
        ("/api/derive", "post", "Document"),
        ("/api/derive/equations", "post", "FirstStage"),
    ):
        schema = spec["paths"][path][method]["responses"]["200"]["content"]["application/json"]["schema"]
        assert schema == {"$ref": f"#/components/schemas/{model}"}
    schemas = spec["components"]["schemas"]
    assert schemas["Document"]["additionalProperties"] is False and "DerivationDocument" not in schemas
    assert schemas["Step"]["required"] == ["key", "title", "latex", "sympy", "explanation"]
