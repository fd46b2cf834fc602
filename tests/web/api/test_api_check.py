"""POST /api/scenes/{id}/check and POST /api/check: students' steps judged in the worker pool."""

from __future__ import annotations

import os

import pytest

from app.engine.tutor.mistakes import RULES
from app.main import app
from app.service.tutor import checking
from app.web.api.deps import checking_service
from tests.engine.check_corpus import CART_PENDULUM, SPRING_ROD
from tests.engine.slip_corpus import FREE_CART

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

HINTS = {rule.mistake: rule.hint for rule in RULES}


def check(client, body, scene="simple-pendulum"):
    url = f"/api/scenes/{scene}/check" if scene else "/api/check"
    return client.post(url, json=body)


def test_a_scene_answer_gets_its_verdict_difference_and_hint(client):
    wrong = check(client, {"step": "kinetic", "answer": "m*R**2*theta_dot**2"})
    assert wrong.status_code == 200, wrong.text
    body = wrong.json()
    assert set(body) == {"verdict", "message", "hint", "mistake", "partial", "follow_up", "correct_part", "reveal", "formulas"}
    assert body["verdict"] == "incorrect" and body["hint"] == HINTS["missing_half"]
    # the difference is kept for the step's reveal (the page shows it with the step), never said in the verdict
    assert "difference" not in body["message"] and body["reveal"]["piece"] == ""
    assert body["reveal"]["difference"] == {
        "sympy": "R**2*m*theta_dot**2/2",
        "latex": r"\frac{1}{2} m R^{2} \dot{\theta}^{2}",  # textbook order
        "tree": ["*", 0.5, "m", ["pow", "R", 2], ["pow", "theta_dot", 2]],  # as every expression the engine gives
    }
    right = check(client, {"step": "equation", "coordinate": "theta", "answer": "theta_ddot + g*sin(theta)/R"}).json()
    # the page's own form of the equation (divided through by m R²) is right
    assert right["verdict"] == "correct" and right["reveal"] is None and right["hint"] is None
    scene = check(client, {"step": "momentum", "coordinate": "phi", "answer": "m*R**2*phi_dot"}, "spherical-pendulum")
    assert "sin² θ" in scene.json()["hint"]


def test_a_declared_system_is_checked_like_a_scene(client):
    cross = check(
        client,
        {"system": CART_PENDULUM, "step": "kinetic", "answer": "(M + m)*x_dot**2/2 + m*l**2*phi_dot**2/2"},
        scene=None,
    )
    assert cross.status_code == 200, cross.text
    assert cross.json()["mistake"]["key"] == "kinetic.cross_term.x_dot.phi_dot"
    omega = check(client, {"system": SPRING_ROD, "step": "omega_squared", "answer": "k/m - w**2"}, scene=None)
    assert omega.status_code == 200, omega.text
    assert omega.json()["verdict"] == "correct"


@pytest.mark.parametrize(
    ("body", "loc", "detail"),
    [
        ({"step": "kinetic", "answer": "m*R**2*theta_dot**2/"}, ["body", "answer"], "ends with '/' at column 20"),
        ({"step": "kinetic", "answer": "m*v**2/2"}, ["body", "answer"], "v is not a name in this problem; the names you may use are R, g, m, t"),
        ({"step": "potential", "answer": "m*g*theta_dot"}, ["body", "answer"], "U depends on positions only"),
        ({"step": "momentum", "answer": "m*R**2*theta_dot"}, ["body", "coordinate"], "give one of: theta"),
        ({"step": "equation", "coordinate": "x", "answer": "1"}, ["body", "coordinate"], "the coordinates are: theta"),
        ({"step": "jerk", "answer": "1"}, ["body", "step"], "'kinetic', 'potential', 'lagrangian', 'momentum'"),
        ({"step": "kinetic", "answer": ""}, ["body", "answer"], "at least 1 character"),
        ({"step": "kinetic", "answer": "1", "extra": 1}, ["body", "extra"], "Extra inputs are not permitted"),
    ],
)
def test_bad_requests_are_422_naming_the_field(client, body, loc, detail):
    response = check(client, body)
    assert response.status_code == 422, response.text
    answer = response.json()
    got = answer.get("loc") or answer["errors"][0]["loc"]
    assert got == loc and detail in answer["detail"]


def test_a_step_that_does_not_apply_lists_the_steps_that_do(client):
    response = check(client, {"step": "omega_squared", "answer": "g/R"}, "damped-pendulum")
    assert response.status_code == 422
    assert response.json()["detail"].endswith(
        "the steps are: position, kinetic, potential, lagrangian, momentum, equation, acceleration, hamiltonian"
    )
    hoop = check(client, {"system": SPRING_ROD, "step": "kinetic", "answer": "1"}, scene=None)
    assert hoop.status_code == 422 and "Lagrangian alone" in hoop.json()["detail"]
    assert hoop.json()["loc"] == ["body", "step"]


def test_a_bad_declared_system_is_located_under_system(client):
    response = check(client, {"system": {**SPRING_ROD, "lagrangian": "m*q"}, "step": "lagrangian", "answer": "1"}, None)
    assert response.status_code == 422
    assert response.json()["loc"] == ["body", "system", "lagrangian"] and response.json()["part"] == "q"


class SpyPool:
    """Stands for the user systems' pool: records every job it is asked to run."""

    def __init__(self):
        self.submitted = []

    async def run_job(self, *args):
        self.submitted.append(args)
        return b"{}"


def test_code_like_answers_are_refused_before_any_job_and_run_nothing(client):
    spy = SpyPool()
    app.dependency_overrides[checking_service] = lambda: checking.Checking(users=spy)
    try:
        _send_code_like_answers(client)
    finally:
        app.dependency_overrides.clear()
    assert spy.submitted == [] and not os.path.exists("/tmp/lagrange-api-check-ran")


def _send_code_like_answers(client):
    for answer in (
        "__import__('os').system('touch /tmp/lagrange-api-check-ran')",
        "sin.__globals__",
        "(lambda: 1)()",
        "theta_dot.__class__.__mro__",
        "exp(exp(exp(exp(3))))",
    ):
        response = check(client, {"step": "kinetic", "answer": answer})
        assert response.status_code == 422 and response.json()["loc"] == ["body", "answer"], answer
        assert response.json()["part"] in answer


def test_unknown_scene_is_404_listing_the_known_ones(client):
    response = check(client, {"step": "kinetic", "answer": "1"}, "nope")
    assert response.status_code == 404 and "simple-pendulum" in response.json()["detail"]


def test_practice_lists_each_step_with_the_engines_answer(client):
    doc = client.get("/api/scenes/pulley/practice").json()
    steps = [(e["step"], e["coordinate"]) for e in doc["exercises"]]
    # the positions first, one box per moving component of each body (x and z, numbered by body), then T, U, L
    positions = [s for s in steps if s[0] == "position"]
    assert positions and steps[: len(positions)] == positions and all(c and c[0] in "xz" for _, c in positions)
    assert steps[len(positions) : len(positions) + 3] == [("kinetic", None), ("potential", None), ("lagrangian", None)]
    assert ("equation", "y2") in steps and steps[-1] == ("hamiltonian", None)
    assert doc["symbols"]["y1_dot"] == r"\dot{y}_{1}"
    own = client.post("/api/practice", json=SPRING_ROD)
    assert own.status_code == 200, own.text
    assert [e["step"] for e in own.json()["exercises"]][-1] == "omega_squared"


def test_an_equation_is_taken_as_a_textbook_writes_it(client):
    # student-c, 5: θ̈ = −(g/R) sin θ was refused for its '='
    as_written = check(client, {"step": "equation", "coordinate": "theta", "answer": "theta_ddot = -g/R*sin(theta)"})
    assert as_written.status_code == 200 and as_written.json()["verdict"] == "correct"
    acceleration = check(client, {"step": "acceleration", "coordinate": "theta", "answer": "theta_ddot = -g/R*sin(theta)"})
    assert acceleration.status_code == 200 and acceleration.json()["verdict"] == "correct"
    wrong = check(client, {"step": "equation", "coordinate": "theta", "answer": "theta_ddot = g/R*sin(theta)"}).json()
    assert wrong["verdict"] == "incorrect"
    # a declared system's equation too
    answer = "m*r_ddot = m*w**2*r - k*(r - a)"
    system = check(client, {"system": SPRING_ROD, "step": "equation", "coordinate": "r", "answer": answer}, scene=None)
    assert system.status_code == 200 and system.json()["verdict"] == "correct"


@pytest.mark.parametrize(
    ("text", "latex"),
    [
        ("1/2 m R^2 theta_dot^2", r"\frac{1}{2} m R^{2} \dot{\theta}^{2}"),
        ("1/2 m (R θ̇)^2", r"\frac{1}{2} m \left(R \dot{\theta}\right)^{2}"),
    ],
)
def test_half_typed_as_students_type_it_is_the_pendulums_kinetic_energy(client, text, latex):
    # issue 45: a fraction of numbers before a spaced factor is a coefficient, read and typeset as ½ m R² θ̇²
    verdict = check(client, {"step": "kinetic", "answer": text})
    assert verdict.status_code == 200 and verdict.json()["verdict"] == "correct", verdict.text
    shown = client.post("/api/typeset", json={"text": text, "step": "kinetic", "scene": "simple-pendulum"})
    assert shown.status_code == 200 and shown.json() == {"latex": latex}
    # glued to the mass it reads two ways, and is said so
    glued = check(client, {"step": "kinetic", "answer": text.replace("1/2 m", "1/2m")})
    assert glued.status_code == 422 and glued.json()["readings"][1].startswith("1/(2 m")


def test_a_quotient_before_a_function_is_its_coefficient(client):
    right = check(client, {"step": "equation", "coordinate": "theta", "answer": "theta_ddot = -g/R sin(theta)"})
    assert right.status_code == 200 and right.json()["verdict"] == "correct", right.text
    spaced = check(client, {"step": "acceleration", "coordinate": "theta", "answer": "-g/R sin θ"})
    assert spaced.status_code == 200 and spaced.json()["verdict"] == "correct", spaced.text


def test_a_sign_diagnosis_quotes_only_a_term_the_student_typed(client):
    # student-e, 3: g sin θ on the right of '=' (divided through by m l) was quoted as "your term −m g l sin(θ)"
    typed = "l*theta_ddot + X_ddot*cos(theta) = g*sin(theta)"
    body = check(client, {"system": FREE_CART, "step": "equation", "coordinate": "theta", "answer": typed}, scene=None)
    assert body.status_code == 200, body.text
    said = body.json()["mistake"]["name"] + " " + body.json()["hint"]
    assert "the sign of your g sin(θ) term" in said and "m g l" not in said, said
    # student-e, 1: the wedge's recoil the wrong way; X is cyclic, so no ∂L/∂q is there to have the wrong sign
    answer = "m*g*sin(alpha)*cos(alpha)/(M + m*sin(alpha)**2)"
    wedge = check(client, {"step": "acceleration", "coordinate": "X", "answer": answer}, "movable-incline").json()
    assert wedge["mistake"]["name"] == "the sign of the whole answer" and "∂L/∂q" not in wedge["hint"], wedge


def test_a_position_typed_for_its_velocity_in_a_momentum_is_named_and_no_part_is_disowned(client):
    # student-e, 4: m R² θ was told "No part of your answer agrees", though m R² is right
    body = check(client, {"step": "momentum", "coordinate": "theta", "answer": "m*R**2*theta"}).json()
    assert body["verdict"] == "incorrect" and body["mistake"]["name"].startswith("θ where θ̇ belongs"), body
    assert body["partial"] is None and "No part" not in body["hint"], body


def test_an_equals_sign_where_the_box_names_the_left_side_is_refused_plainly(client):
    refused = check(client, {"step": "kinetic", "answer": "T = m*R**2*theta_dot**2/2"})
    assert refused.status_code == 422
    body = refused.json()
    assert body["detail"] == "answer: type only the right-hand side: the box already has the left-hand side and its '='"
    assert (body["start"], body["end"]) == (2, 3)
    lagrangian = check(client, {"step": "lagrangian", "answer": "T - U"}).json()
    assert "write T and U out in the coordinates" in lagrangian["detail"] and lagrangian["part"] == "T"


def test_a_name_typed_in_the_other_case_is_named_as_that(client):
    # student-e, 2: a capital letter for a declared one is not taken for a quantity or an unknown
    refused = check(client, {"step": "kinetic", "answer": "m*r**2*theta_dot**2/2"})
    assert refused.status_code == 422
    body = refused.json()
    assert body["detail"].startswith("answer: r is not a parameter here; did you mean R?"), body
    assert (body["start"], body["end"]) == (2, 3)


@pytest.mark.parametrize("form", ["NFC", "NFD"])
def test_an_acceleration_typed_with_a_combining_double_dot_is_checked(client, form):
    # issue 41, item 2: θ followed by U+0308 was refused on the left of an acceleration's '='
    import unicodedata

    for text in ("θ\u0308 = -g/R sin θ", "θ'' = -g/R sin θ", "θ\u0308 + g/R sin θ = 0"):
        step = "equation" if "= 0" in text else "acceleration"
        body = {"step": step, "coordinate": "theta", "answer": unicodedata.normalize(form, text)}
        response = check(client, body)
        assert response.status_code == 200, response.text
        assert response.json()["verdict"] == "correct", response.json()


def test_a_g_typed_where_the_masses_stay_level_is_refused_with_why(client):
    # issue 41, 4: "g is not a name in this problem" said why, by the check and the typeset preview alike
    body = {"step": "equation", "coordinate": "x2", "answer": "m*x2_ddot + k*x2 + kappa*(x2 - x1) = m*g"}
    refused = check(client, body, scene="coupled-oscillators")
    assert refused.status_code == 422, refused.text
    why = "g is not a name in this problem: the masses move on a horizontal line, so their heights never change"
    assert why in refused.json()["detail"], refused.json()
    shown = client.post(
        "/api/typeset",
        json={"text": body["answer"], "step": "equation", "coordinate": "x2", "scene": "coupled-oscillators"},
    )
    assert shown.status_code == 422 and shown.json()["detail"] == refused.json()["detail"], shown.text


def test_the_correct_part_comes_through_the_api_beside_the_named_slip(client):
    # review student-l 3: the pulley's ÿ₁ with a wrong denominator names it and keeps the correct one apart
    body = check(client, {"step": "acceleration", "coordinate": "y1", "answer": "g*(M - 2*m1)/(M + 4*m1 + m2)"}, "pulley")
    body = body.json()
    assert body["mistake"]["name"].startswith("the denominator M + m₂ + 4 m₁") and "correct one" not in body["mistake"]["name"]
    assert body["correct_part"]["what"] == "denominator" and body["correct_part"]["latex"], body["correct_part"]
    plain = check(client, {"step": "kinetic", "answer": "m*R**2*theta_dot**2"}).json()
    assert plain["correct_part"] is None


def test_what_the_student_typed_reaches_the_verdict_through_the_worker(client):
    # review student-m #113: two typed terms that cancel are judged apart from the same answer built without them
    # (the worker remembers verdicts by the built answer), and #24: an ω² with θ still in it is graded, not refused
    typed = "m*D_ddot + m*X_ddot*cos(alpha) - m*g*sin(alpha) + m*g*sin(alpha) = 0"
    twice = check(client, {"step": "equation", "coordinate": "D", "answer": typed}, "movable-incline")
    assert twice.status_code == 200, twice.text
    assert twice.json()["mistake"]["key"] == "equation.cancelling_terms", twice.json()
    plain = check(client, {"step": "equation", "coordinate": "D", "answer": "m*D_ddot + m*X_ddot*cos(alpha)"},
                  "movable-incline").json()  # fmt: skip
    assert plain["mistake"]["key"] != "equation.cancelling_terms", plain
    omega = check(client, {"step": "omega_squared", "answer": "g/R*cos(theta)"})
    assert omega.status_code == 200, omega.text
    assert omega.json()["mistake"]["key"] == "omega_squared.not_at_equilibrium", omega.json()
