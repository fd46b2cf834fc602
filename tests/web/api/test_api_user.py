"""POST /api/derive: systems users declare, derived in the worker pool."""

import json

import pytest
import sympy as sp

from app.main import app
from app.service.runtime.fairness import COOKIE
from app.service.users import user_checks
from app.service.users.user_systems import UserSystems
from app.settings import Settings
from app.web.api import examples_user
from app.web.api.deps import user_systems_service
from app.web.api.examples_user import DOUBLE_PENDULUM, FORCED_SPRING, REFUSED_REQUESTS, SPINNING_HOOP
from tests.reference import numerically_equal, reference_accelerations

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def symbols_of(doc):
    names = {"t": sp.Symbol("t", real=True)}
    for q in doc["coordinates"]:
        for suffix in ("", "_dot", "_ddot"):
            names[q + suffix] = sp.Symbol(q + suffix, real=True)
    for p in doc["parameters"]:
        names[p] = sp.Symbol(p, real=True)
    return names


def derive(client, body):
    response = client.post("/api/derive", json=body)
    assert response.status_code == 200, response.text
    return response.json()


@pytest.mark.parametrize("name", ["double-pendulum", "forced-spring"])
def test_systems_outside_the_chapter_match_lagranges_method(client, name):
    spec = {"double-pendulum": DOUBLE_PENDULUM, "forced-spring": FORCED_SPRING}[name]
    doc = derive(client, spec)
    names = symbols_of(doc)
    ours = [sp.sympify(doc["accelerations"][q]["sympy"], locals=names) for q in doc["coordinates"]]
    system = user_checks.checked(_spec(spec)).system()
    theirs, _ = reference_accelerations(system)
    symbols = sorted(set(names.values()), key=str)
    for a, b in zip(ours, theirs, strict=True):
        assert numerically_equal(a, b, symbols), (name, a, b)
    # every served equation of motion vanishes on the served accelerations
    on_motion = {names[f"{q}_ddot"]: a for q, a in zip(doc["coordinates"], ours, strict=True)}
    for eq in doc["equations_of_motion"]:
        residual = sp.sympify(eq["sympy"], locals=names).xreplace(on_motion)
        assert numerically_equal(residual, sp.Integer(0), symbols)


def _spec(body):
    from app.web.schemas.user import SystemSpec

    return SystemSpec.model_validate(body).to_spec()


def test_forced_spring_reports_the_force_and_no_conserved_energy(client):
    doc = derive(client, FORCED_SPRING)
    names = symbols_of(doc)
    assert set(doc["generalized_forces"]) == {"x"}
    force = sp.sympify(doc["generalized_forces"]["x"]["sympy"], locals=names)
    assert sp.expand(force - (names["F"] * sp.cos(names["w"] * names["t"]) - names["b"] * names["x_dot"])) == 0
    # a driven, damped oscillator conserves neither E nor h
    assert doc["conserved"] == []
    assert any(s["title"] == "Generalized forces" for s in doc["steps"])


def test_lagrangian_form_and_same_contract_as_scenes(client):
    doc = derive(client, SPINNING_HOOP)
    names = symbols_of(doc)
    for key in ("lagrangian", "hamiltonian", "energy"):
        sp.sympify(doc[key]["sympy"], locals=names)
    assert [e["coordinate"] for e in doc["equations_of_motion"]] == ["theta"]
    assert doc["steps"] and all(set(s) == {"key", "title", "latex", "sympy", "explanation"} for s in doc["steps"])
    assert r"\dot{\theta}" in doc["lagrangian"]["latex"]
    # the bead's angular acceleration, checked against LagrangesMethod
    theirs, _ = reference_accelerations(user_checks.checked(_spec(SPINNING_HOOP)).system())
    ours = sp.sympify(doc["accelerations"]["theta"]["sympy"], locals=names)
    assert numerically_equal(ours, theirs[0], sorted(names.values(), key=str))


def test_user_documents_carry_hamiltons_equations_and_normal_modes(client):
    doc = derive(client, DOUBLE_PENDULUM)
    names = symbols_of(doc)
    names |= {f"p_{q}": sp.Symbol(f"p_{q}", real=True) for q in doc["coordinates"]}
    sp.sympify(doc["hamilton"]["hamiltonian"]["sympy"], locals=names)
    assert [e["coordinate"] for e in doc["hamilton"]["equations"]] == doc["coordinates"]
    # four equilibria of a double pendulum, only the hanging one stable
    assert sorted(e["kind"] for e in doc["normal_modes"]) == ["stable", "unstable", "unstable", "unstable"]
    titles = [s["title"] for s in doc["steps"]]
    assert "Hamilton's equations" in titles and "Equilibria" in titles


def test_parameters_given_by_name_default_to_one(client):
    doc = derive(client, {**SPINNING_HOOP, "parameters": ["m", "R", "g", "w"]})
    assert doc["parameters"]["m"]["default"] == 1.0


def test_the_hoop_example_is_dimensioned_and_off_its_bifurcation(client):
    # prof-g 53: the shipped example had m, R, g, w all 1 with no units, exactly at R w² = g
    doc = derive(client, SPINNING_HOOP)
    units = {name: p["unit"] for name, p in doc["parameters"].items()}
    assert units == {"m": "kg", "R": "m", "g": "m/s^2", "w": "rad/s"}
    values = {name: p["default"] for name, p in doc["parameters"].items()}
    assert values["R"] * values["w"] ** 2 > 1.5 * values["g"]


def test_the_hoop_equilibria_say_where_they_exist_and_when_they_are_stable(client):
    # prof-g 55: "θ = 2π − acos(g/(Rw²))" with no statement that it exists only when R w² > g, and no verdict
    red = derive(client, SPINNING_HOOP)["effective_potential"]
    by_position = {e["position"]["sympy"]: e for e in red["equilibria"]}
    assert set(by_position) == {"0", "pi", "acos(g/(R*w**2))", "-acos(g/(R*w**2))"}
    for tilted in ("acos(g/(R*w**2))", "-acos(g/(R*w**2))"):
        e = by_position[tilted]
        assert r"\arccos" in e["position"]["latex"] and "acos" not in e["position"]["latex"]
        assert e["exists"]["latex"] == "R w^{2} > g" and e["stable"] is True
    # the bottom: ω² = g/R − w², stable below the bifurcation only; the top never
    bottom = by_position["0"]
    assert bottom["stable"] is None and bottom["stable_when"]["latex"] == "g > R w^{2}" and bottom["exists"] is None
    assert by_position["pi"]["stable"] is False



def test_the_hoops_inertia_is_served_as_a_moment_of_inertia(client):
    # prof-n 5: θ is an angle, so its inertia m R² is the effective moment of inertia I_eff, never m_eff
    red = derive(client, SPINNING_HOOP)["effective_potential"]
    assert red["inertia"] == {"latex": r"I_\text{eff}", "unicode": "I_eff"}
    assert red["mass"]["sympy"] == "R**2*m"


@pytest.mark.usefixtures("fresh_mint_budget")
def test_a_session_cookie_is_issued_and_kept(client):
    client.cookies.clear()
    first = client.post("/api/derive", json=SPINNING_HOOP)
    assert COOKIE in first.cookies
    second = client.post("/api/derive", json=SPINNING_HOOP)
    assert COOKIE not in second.cookies  # the client already holds one


@pytest.mark.parametrize("name", sorted(REFUSED_REQUESTS))
def test_documented_refusals_are_what_the_api_answers(client, name):
    response = client.post("/api/derive", json=REFUSED_REQUESTS[name]["value"])
    assert response.status_code == 422
    assert response.json() == examples_user.ERROR_EXAMPLES[422][name]["response"], (
        "stale example: run python scripts/record_examples.py"
    )


def test_documented_derivation_is_what_the_api_answers(client):
    """The documented answer has the served keys and the same mathematics (step wording may evolve)."""
    served, documented = derive(client, FORCED_SPRING), examples_user.DERIVE_RESPONSE
    stale = "stale example: run python scripts/record_examples.py"
    assert {k: v for k, v in served.items() if k != "steps"} == {k: v for k, v in documented.items() if k != "steps"}, (
        stale
    )
    assert [(s["title"], s["sympy"]) for s in served["steps"]] == [
        (s["title"], s["sympy"]) for s in documented["steps"]
    ], stale


def test_other_documented_errors_are_what_the_api_answers(client):
    from app.web.api.user import MAX_BODY_BYTES

    documented = examples_user.ERROR_EXAMPLES
    unreadable = client.post("/api/derive", content=examples_user.UNREADABLE, headers=examples_user.JSON)
    assert (unreadable.status_code, unreadable.json()) == (400, documented[400]["unreadable"]["response"])
    big = client.post("/api/derive", content=b" " * (MAX_BODY_BYTES + 1), headers=examples_user.JSON)
    assert (big.status_code, big.json()) == (413, documented[413]["too-large"]["response"])


@pytest.mark.slow  # derives the double pendulum afresh in the worker pool
def test_a_job_over_the_time_limit_is_stopped_and_the_pool_recovers(client, services):
    # a service of its own with the recorded example's short limit (and so no cached answer), on the app's pool
    short = UserSystems(services.pool, config=Settings(derive_seconds=examples_user.TIMEOUT_SECONDS))
    app.dependency_overrides[user_systems_service] = lambda: short
    try:
        answer = client.post("/api/derive", json=examples_user.LONG_CHAIN).json()
    finally:
        app.dependency_overrides.clear()
    assert answer == examples_user.ERROR_EXAMPLES[422]["timeout"]["response"]
    # the pool replaced the killed worker: the next job runs normally
    assert client.get("/healthz").json() == {"status": "ok"}
    assert derive(client, SPINNING_HOOP)["coordinates"] == ["theta"]


# one job per session and the same system asked twice at once: tests/web/api/test_api_user_fairness.py


def test_busy_server_answers_503_with_retry_after(client, services):
    gate = services.users.gate
    tickets = [gate.admit(f"other{i}", f"10.0.0.{i}") for i in range(gate.capacity)]
    try:
        client.cookies.clear()
        response = client.post("/api/derive", json={"coordinates": ["q"], "lagrangian": "q_dot**2 - q**4"})
        assert response.status_code == 503
        assert int(response.headers["Retry-After"]) >= 1
        assert response.json()["detail"] == examples_user.ERROR_EXAMPLES[503]["busy"]["response"]["detail"]
    finally:
        for ticket in tickets:
            ticket.release()


@pytest.mark.parametrize("path", ["/api/derive", "/api/simulate"])
def test_openapi_documents_every_answer(client, path):
    schema = client.get("/openapi.json").json()
    operation = schema["paths"][path]["post"]
    assert set(operation["responses"]) == {"200", "400", "413", "415", "422", "429", "503"}
    for status, response in operation["responses"].items():
        # an error is an RFC 9457 problem (app/web/api/errors.py)
        content = response["content"]["application/json" if status == "200" else "application/problem+json"]
        assert "schema" in content and ("example" in content or "examples" in content), status
        assert content.get("example", True) is not None, f"{status}: the recorded example is missing"
    for status in ("429", "503"):
        assert "Retry-After" in operation["responses"][status]["headers"]
    examples = operation["requestBody"]["content"]["application/json"]["examples"]
    assert {"double-pendulum", "forced-spring"} <= set(examples)
    json.dumps(schema)


@pytest.mark.parametrize(
    "spec",
    [DOUBLE_PENDULUM, FORCED_SPRING, SPINNING_HOOP, examples_user.RELATIVISTIC_OSCILLATOR],
    ids=["double-pendulum", "forced-spring", "spinning-hoop", "relativistic"],
)
def test_each_examples_answer_is_the_document_model_byte_for_byte(client, spec):
    """The answer has exactly the shape of app.engine.document.model.Document (extra keys forbidden), and the model's
    JSON is the answer's bytes: the OpenAPI's response_model describes what is sent."""
    import orjson

    from app.engine.document.model import Document

    response = client.post("/api/derive", json=spec)
    assert response.status_code == 200, response.text
    document = Document.model_validate_json(response.content)
    assert orjson.dumps(document.as_json()) == response.content
