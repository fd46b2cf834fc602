"""The classes' API on SQLite and on a real PostgreSQL: create, assign, join, check (recorded), summary,
students, export, delete; the 401/403 matrix; rate limits; refusals."""

from __future__ import annotations

import csv
import io

import pytest
from sqlalchemy import text

from app.main import app
from app.web.api.classes import classroom as classroom_dep
from tests.classes import classroom

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

SCENE = "simple-pendulum"
WRONG_T = "m*R**2*theta_dot**2"  # twice T: the named mistake missing_half
RIGHT_T = "m*R**2*theta_dot**2/2"


@pytest.fixture
def classes(classes_on_both):
    """Every test here on SQLite and on PostgreSQL (tests/web/conftest.py)."""
    return classes_on_both


def bearer(key: str) -> dict[str, str]:
    return {"Authorization": f"Bearer {key}"}


def new_class(client, title="Mechanics") -> tuple[str, str]:
    r = client.post("/api/classes", json={"title": title})
    assert r.status_code == 201, r.text
    return r.json()["code"], r.json()["teacher_key"]


def join(client, code: str, name: str) -> str:
    r = client.post(f"/api/classes/{code}/join", json={"name": name})
    assert r.status_code == 200, r.text
    return r.json()["student_key"]


def check(client, code, key, answer, step="kinetic", scene=SCENE, **extra):
    return client.post(
        f"/api/classes/{code}/check", json={"scene": scene, "step": step, "answer": answer, **extra}, headers=bearer(key)
    )


def test_a_class_from_creation_to_deletion(client, classes):
    code, teacher = new_class(client)
    assert len(code) == 6 and len(teacher) >= 40
    items = {"items": [{"scene": SCENE, "steps": [{"step": "kinetic"}, {"step": "potential"}], "parameters": {"g": 9.81}}]}
    r = client.put(f"/api/classes/{code}/assignment", json=items, headers=bearer(teacher))
    assert r.status_code == 200, r.text
    joined = client.post(f"/api/classes/{code.lower()}/join", json={"name": "Ada"}).json()  # a lower-case code works
    assert joined["assignment"][0]["scene"] == SCENE and joined["assignment"][0]["parameters"] == {"g": 9.81}
    ada, bo = joined["student_key"], join(client, code, "Bo")

    wrong = check(client, code, ada, WRONG_T)
    practice = client.post(f"/api/scenes/{SCENE}/check", json={"step": "kinetic", "answer": WRONG_T})
    assert wrong.status_code == 200 and wrong.json() == practice.json()  # practice mode's verdict
    assert check(client, code, ada, RIGHT_T).json()["verdict"] == "correct"
    assert check(client, code, bo, WRONG_T).json()["verdict"] == "incorrect"

    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    assert summary["students"] == 2 and summary["attempts"] == 3
    kinetic, potential = summary["steps"]
    assert kinetic == {"assignment": 1, "scene": SCENE, "step": "kinetic", "coordinate": None, "correct": 1, "incorrect": 2,
                       "not_read": 0, "students_done": 1, "students_late": 0, "students_shown": 0,
                       "students_shown_unanswered": 0, "students_right": 1, "students_wrong": 1,
                       "students_equivalent": 0, "mistakes": {"missing_half": 2},
                       "mistake_names": {"missing_half": "the ½ of ½ m v² left out"},
                       "stuck": 1, "students_stuck": ["Bo"]}  # Ada got it right after her mistake
    assert potential["correct"] == potential["incorrect"] == 0
    assert summary["mistakes"] == [{"key": "missing_half", "name": "the ½ of ½ m v² left out", "count": 2,
                                    "steps": [{"assignment": 1, "scene": SCENE, "step": "kinetic", "coordinate": None,
                                               "count": 2, "students": 2}],
                                    "students": ["Ada", "Bo"], "students_since_right": ["Ada"]}]

    rows = client.get(f"/api/classes/{code}/students", headers=bearer(teacher)).json()["students"]
    assert [(s["name"], s["attempts"], s["done"], s["assigned"]) for s in rows] == [("Ada", 2, 1, 2), ("Bo", 1, 0, 2)]
    mine = client.get(f"/api/classes/{code}/me", headers=bearer(bo)).json()
    assert mine["role"] == "student" and mine["progress"]["attempts"] == 1

    export = client.get(f"/api/classes/{code}/export?format=csv", headers=bearer(teacher))
    assert export.headers["content-type"].startswith("text/csv") and export.headers["cache-control"] == "no-store"
    table = list(csv.DictReader(io.StringIO(export.content.decode("utf-8-sig"))))
    # the mistake in the tutor's words (as the student read them), the scene by its title, the assignment named
    words = summary["steps"][0]["mistake_names"]["missing_half"]
    assert words and "_" not in words
    assert [(r["student"], r["assignment"], r["item"], r["verdict"], r["mistake"], r["answer"]) for r in table] == [
        ("Ada", "1. Assignment 1", "Simple pendulum", "wrong", words, WRONG_T),
        ("Ada", "1. Assignment 1", "Simple pendulum", "right", "", RIGHT_T),
        ("Bo", "1. Assignment 1", "Simple pendulum", "wrong", words, WRONG_T)]

    assert client.delete(f"/api/classes/{code}", headers=bearer(teacher)).status_code == 204
    assert client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).status_code == 403
    assert client.post(f"/api/classes/{code}/join", json={"name": "Cy"}).status_code == 404
    with classes.db.session() as session:
        for table_name in ("classes", "students", "assignments", "attempts"):
            assert session.execute(text(f"SELECT count(*) FROM {table_name}")).scalar() == 0


TEACHER_ROUTES = [
    ("GET", "/summary", None), ("GET", "/students", None), ("GET", "/export?format=csv", None), ("GET", "/me", None),
    ("PUT", "/assignment", {"items": []}), ("DELETE", "", None),
]


def test_who_may_do_what(client, classes):
    code, teacher = new_class(client)
    other_code, other_teacher = new_class(client, "another class")
    student, other_student = join(client, code, "Ada"), join(client, other_code, "Bo")
    refused = {"no key": (None, 401), "student's key": (student, 403), "other class's key": (other_teacher, 403),
               "other class's student": (other_student, 403), "made-up key": ("x" * 43, 403)}
    for method, path, body in TEACHER_ROUTES:
        for why, (key, status) in refused.items():
            if path == "/me" and key == student:
                continue  # a student reads their own view of the class
            r = client.request(method, f"/api/classes/{code}{path}", json=body, headers=bearer(key) if key else {})
            assert r.status_code == status, (method, path, why, r.text)
            if status == 401:
                assert r.headers["www-authenticate"] == "Bearer"
    for why, key, status in [("no key", None, 401), ("instructor's key", teacher, 403),
                             ("other class's student", other_student, 403), ("made-up", "y" * 43, 403)]:
        r = client.post(f"/api/classes/{code}/check", json={"scene": SCENE, "step": "kinetic", "answer": RIGHT_T},
                        headers=bearer(key) if key else {})
        assert r.status_code == status, (why, r.text)
    # an unknown code and a wrong key: the same answer
    unknown = client.get("/api/classes/ACEFHK/summary", headers=bearer(teacher))
    wrong = client.get(f"/api/classes/{code}/summary", headers=bearer("z" * 43))
    assert unknown.status_code == wrong.status_code == 403 and unknown.json() == wrong.json()
    assert client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).status_code == 200


def test_the_database_keeps_no_key(client, classes):
    code, teacher = new_class(client)
    student = join(client, code, "Ada")
    with classes.db.session() as session:
        dumped = repr(session.execute(text("SELECT * FROM classes")).all()) + repr(
            session.execute(text("SELECT * FROM students")).all())
    assert code in dumped and teacher not in dumped and student not in dumped


def test_refusals_say_what_is_wrong(client, classes):
    code, teacher = new_class(client)
    r = client.put(f"/api/classes/{code}/assignment", json={"items": [{"scene": "no-such-scene"}]},
                   headers=bearer(teacher))
    assert r.status_code == 422 and r.json()["loc"] == ["body", "items", "0", "scene"] and "known scenes" in r.text
    r = client.put(f"/api/classes/{code}/assignment",
                   json={"items": [{"scene": SCENE, "steps": [{"step": "equation", "coordinate": "phi"}]}]},
                   headers=bearer(teacher))
    assert r.status_code == 422 and "its steps are" in r.json()["detail"]
    system = {"coordinates": ["x"], "parameters": ["m", "k"], "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}
    r = client.put(f"/api/classes/{code}/assignment", headers=bearer(teacher), json={"items": [
        {"scene": SCENE, "steps": [{"step": "kinetic"}]},
        {"system": system, "name": "spring", "steps": [{"step": "acceleration", "coordinate": "x"}],
         "setup": "x is the stretch of the spring from its natural length; U = 0 at x = 0."}]})
    assert r.status_code == 200, r.text
    ada = join(client, code, "Ada")
    assert client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).status_code == 422  # the name is taken
    assert client.post("/api/classes/ACEFHK/join", json={"name": "Bo"}).status_code == 404
    assert client.post("/api/classes/not-a-code/join", json={"name": "Bo"}).status_code == 404
    # a code with a character no code holds: the refusal names that character, the rule in words
    r = client.post("/api/classes/K34EKZ/join", json={"name": "Bo"})
    assert r.status_code == 404 and r.json()["detail"].startswith("“K34EKZ” is not a class code: “Z” is never in")
    assert r.json()["detail"].endswith("easily read as another. Check the code on the board.")  # one sentence
    assert check(client, code, ada, "m*g", scene="double-pendulum").status_code == 422  # not assigned
    assert check(client, code, ada, "m*g", step="potential").status_code == 422  # step not assigned
    r = client.post(f"/api/classes/{code}/check", headers=bearer(ada),
                    json={"system": "spring", "step": "acceleration", "coordinate": "x", "answer": "-k*x/m"})
    assert r.status_code == 200 and r.json()["verdict"] == "correct", r.text
    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    assert summary["steps"][1] | {"mistakes": None} == {"assignment": 1, "system": "spring", "step": "acceleration", "coordinate": "x",
                                                        "correct": 1, "incorrect": 0, "not_read": 0,
                                                        "students_done": 1, "students_late": 0, "students_shown": 0,
                                                        "students_shown_unanswered": 0, "students_right": 1,
                                                        "students_wrong": 0, "students_equivalent": 0,
                                                        "mistakes": None, "mistake_names": {},
                                                        "stuck": 0, "students_stuck": []}


@pytest.mark.parametrize("backend", ["sqlite"])
def test_joins_and_checks_are_rate_limited(client, services, tmp_path, backend):
    room = classroom(services.checking, backend, tmp_path, None, client_joins_per_minute=2, student_checks_per_minute=1,
                     class_joins_per_minute=4)
    app.dependency_overrides[classroom_dep] = lambda: room
    try:
        code, teacher = new_class(client)
        client.cookies.clear()
        ada = join(client, code, "Ada")  # without a cookie: counted on the address; a session cookie comes back
        join(client, code, "Bo")  # the session's first
        join(client, code, "Cy")  # and second
        r = client.post(f"/api/classes/{code}/join", json={"name": "Di"})  # the session's third this minute
        assert r.status_code == 429 and int(r.headers["retry-after"]) >= 1 and "a minute" in r.json()["detail"]
        client.cookies.clear()  # another client: the class's fourth join
        join(client, code, "Di")
        assert client.post(f"/api/classes/{code}/join", json={"name": "Ed"}).status_code == 429  # the class's fifth
        assert check(client, code, ada, RIGHT_T).status_code == 200
        assert check(client, code, ada, WRONG_T).status_code == 429
        assert client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()["attempts"] == 1
    finally:
        app.dependency_overrides.pop(classroom_dep, None)
        room.stop()
        client.cookies.clear()


def test_a_key_is_compared_as_a_digest_in_constant_time(monkeypatch, tmp_path, services):
    import hmac

    from app.service.classroom import store

    room = classroom(services.checking, "sqlite", tmp_path, None)
    code, teacher, _recovery = store.create_class(room.db, "timing")
    compared = []
    real = hmac.compare_digest
    monkeypatch.setattr(store.hmac, "compare_digest", lambda a, b: compared.append((len(a), len(b))) or real(a, b))
    for c, k in [(code, teacher), ("ACEFHK", teacher), (code, "wrong")]:
        try:
            store.access(room.db, c, k)
        except Exception:  # noqa: BLE001
            pass
    assert compared == [(64, 64)] * 3  # one comparison of two digests, whether the code exists or not
    room.stop()


def test_a_retried_check_returns_the_first_verdict_and_records_nothing_new(client, classes):
    code, teacher = new_class(client)
    ada = join(client, code, "Ada")
    first = check(client, code, ada, WRONG_T, attempt="press-0001-ada")
    assert first.status_code == 200 and first.json()["verdict"] == "incorrect"
    again = check(client, code, ada, WRONG_T, attempt="press-0001-ada")  # the page sends the same press again
    assert again.status_code == 200 and again.json() == first.json()
    other = check(client, code, ada, RIGHT_T, attempt="press-0001-ada")  # another answer under a used id
    assert other.status_code == 422 and other.json()["loc"][-1] == "attempt" and "another answer" in other.text
    assert check(client, code, ada, RIGHT_T, attempt="press-0002-ada").json()["verdict"] == "correct"
    bo = join(client, code, "Bo")  # ids are per student: Bo's press with the same id is his own
    assert check(client, code, bo, RIGHT_T, attempt="press-0001-ada").json()["verdict"] == "correct"
    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    assert summary["attempts"] == 3 and summary["steps"][0]["mistakes"] == {"missing_half": 1}
    assert check(client, code, ada, RIGHT_T, attempt="short").status_code == 422  # 8 to 64 characters
    assert check(client, code, ada, RIGHT_T, attempt="no spaces here").status_code == 422



def test_answers_that_could_not_be_read_are_counted_never_as_wrong(client, classes):
    # issue 45: a student who typed 7 answers, 4 of them not read ("Not checked"), has 7 answers on the dashboard
    code, teacher = new_class(client)
    items = {"items": [{"scene": SCENE, "steps": [{"step": "kinetic"}]}]}
    assert client.put(f"/api/classes/{code}/assignment", json=items, headers=bearer(teacher)).status_code == 200
    ada, bo = join(client, code, "Ada"), join(client, code, "Bo")
    unreadable = ["1/2m R^2 theta_dot^2", "m R^2 theta_dot^2/2)", "=m*g", "m*r**2"]
    for n, typed in enumerate(unreadable):
        refused = check(client, code, ada, typed, attempt=f"press-000{n}-ada")
        practice = client.post(f"/api/scenes/{SCENE}/check", json={"step": "kinetic", "answer": typed})
        assert refused.status_code == practice.status_code == 422 and refused.json() == practice.json(), typed
    # the page sends a press again (no verdict came back): the same refusal, nothing recorded twice
    again = check(client, code, ada, unreadable[0], attempt="press-0000-ada")
    assert again.status_code == 422 and again.json() == check(client, code, ada, unreadable[0]).json()
    assert check(client, code, ada, WRONG_T).json()["verdict"] == "incorrect"
    assert check(client, code, ada, RIGHT_T).json()["verdict"] == "correct"
    assert check(client, code, bo, "1/2m R^2 theta_dot^2").status_code == 422  # Bo: nothing judged yet

    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    (kinetic,) = summary["steps"]
    # Ada's 4 not read + the press sent again without an id (a new press) + 2 judged; Bo's 1
    assert summary["attempts"] == 8
    assert (kinetic["correct"], kinetic["incorrect"], kinetic["not_read"]) == (1, 1, 6)
    assert kinetic["mistakes"] == {"missing_half": 1} and kinetic["students_stuck"] == ["Bo"]
    rows = client.get(f"/api/classes/{code}/students", headers=bearer(teacher)).json()["students"]
    assert [(s["name"], s["attempts"], s["not_read"], s["done"]) for s in rows] == [("Ada", 7, 5, 1), ("Bo", 1, 1, 0)]
    mine = client.get(f"/api/classes/{code}/me", headers=bearer(bo)).json()
    assert mine["progress"]["attempts"] == 1 and mine["progress"]["not_read"] == 1

    table = list(csv.DictReader(io.StringIO(client.get(f"/api/classes/{code}/export", headers=bearer(teacher)).text)))
    assert [r["verdict"] for r in table] == ["could not be read"] * 5 + ["wrong", "right", "could not be read"]
    assert [r["counted"] for r in table][5:7] == ["no: wrong", "yes"] and table[0]["counted"] == "no: could not be read"
    first = table[0]
    assert first["answer"] == unreadable[0] and first["mistake"].startswith("a factor after a quotient is ambiguous")
    assert table[2]["answer"] == "'=m*g"  # not a checked expression: kept from a spreadsheet's formulas
    assert "r is not a parameter here; did you mean R?" in table[3]["mistake"]

    # the gradebook: Ada's first judged answer was wrong (not her first answer read), Bo has no score yet
    grades = {s["name"]: s["grades"][0] for s in client.get(f"/api/classes/{code}/grades",
                                                              headers=bearer(teacher)).json()["students"]}
    assert (grades["Ada"]["first_try"], grades["Ada"]["right"], grades["Ada"]["score"]) == (0, 1, 100.0)
    assert grades["Bo"]["score"] is None
