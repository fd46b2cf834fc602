"""A hostile corpus against POST /api/derive: every input answered 4xx, promptly, with nothing executed.

Payloads that would run code try to create a canary file; it must never exist.
Each answer must arrive well within the worker's hard time limit (a hang guard,
not a speed target), and the server must be healthy afterwards.
"""

import json
import time

import pytest

from app.settings import settings
from app.web.api.user import MAX_BODY_BYTES

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

CANARY = "/tmp/lagrange-canary-{id}"


def sys_l(lagrangian, coordinates=("x",), parameters=()):
    return {"coordinates": list(coordinates), "parameters": list(parameters), "lagrangian": lagrangian}


def sys_tu(kinetic, potential, coordinates=("x",), parameters=("m", "k")):
    return {
        "coordinates": list(coordinates),
        "parameters": list(parameters),
        "kinetic": kinetic,
        "potential": potential,
    }


TOUCH = "__import__('os').system('touch {canary}')"

# (id, body) where body is a dict sent as JSON, or bytes sent raw
CORPUS = [
    # code execution through names, attributes, strings, lambdas and f-strings
    ("import-system", sys_l(TOUCH)),
    ("import-bare", sys_l("__import__")),
    ("dunder-globals", sys_l("sin.__globals__['__builtins__']['__import__']('os').system('touch {canary}')")),
    ("dunder-subclasses", sys_l("x.__class__.__base__.__subclasses__()")),
    ("dunder-no-quotes", sys_l("x_dot.__class__.__init__.__globals__")),
    ("eval-call", sys_l("eval(x)")),
    ("exec-call", sys_l("exec(x_dot)")),
    ("open-file", sys_l("open('{canary}', 'w')")),
    ("getattr", sys_l("getattr(sin, x)")),
    ("lambda", sys_l("(lambda: __import__('os').system('touch {canary}'))()")),
    ("f-string", sys_l("f\"{{__import__('os').system('touch {canary}')}}\"")),
    ("string-to-function", sys_l("sin(\"__import__('os').system('touch {canary}')\")")),
    ("sympify-call", sys_l("sympify('x')")),
    ("comprehension", sys_l("[c for c in ().__class__.__bases__]")),
    ("walrus", sys_l("(y := x)")),
    ("semicolon", sys_l("x_dot**2; import os")),
    ("newline-statement", sys_l("x_dot**2\nimport os")),
    ("unicode-lookalike", sys_l("ｅｖａｌ(x)")),
    ("code-in-mass", {"coordinates": ["x"], "particles": [{"mass": TOUCH, "position": ["x", "0"]}], "potential": "0"}),
    ("code-in-force", {**sys_tu("m*x_dot**2/2", "k*x**2/2"), "forces": {"x": TOUCH}}),
    # names
    ("name-dunder", sys_l("x_dot**2", coordinates=("__import__",))),
    ("name-code", sys_l("x_dot**2", coordinates=("x; import os",))),
    ("name-function", sys_tu("m*x_dot**2/2", "0", parameters=("sin",))),
    ("name-constant", sys_tu("m*x_dot**2/2", "0", parameters=("E",))),
    ("name-keyword", sys_tu("m*x_dot**2/2", "0", parameters=("lambda",))),
    ("name-time", sys_l("x_dot**2", coordinates=("t",))),
    ("name-underscore", sys_l("x_dot**2", coordinates=("x_dot",))),
    ("name-unicode", sys_l("x_dot**2", coordinates=("θ",))),
    ("name-twice", sys_tu("m*x_dot**2/2", "0", parameters=("m", "m"))),
    ("name-too-long", sys_l("x_dot**2", coordinates=("a" * 41,))),
    ("force-on-non-coordinate", {**sys_tu("m*x_dot**2/2", "k*x**2/2"), "forces": {"__class__": "0"}}),
    ("undeclared-name", sys_tu("m*x_dot**2/2", "k*y**2/2")),
    ("velocity-in-potential", sys_tu("m*x_dot**2/2", "k*x_dot**2/2")),
    ("acceleration", sys_l("x_dot**2 + x_ddot")),
    # exponent towers and huge literals
    ("tower-9", sys_l("x_dot**2 + 9**9**9**9")),
    ("tower-2", sys_l("x_dot**2 + 2**10**10")),
    ("big-exponent", sys_l("x_dot**2 + x**(10**10)")),
    ("expansion", sys_l("x_dot**2 + (x + x_dot + 1)**60")),
    ("huge-float", sys_l("x_dot**2 + 1e999999999*x")),
    ("huge-integer", sys_l("x_dot**2 + 123456789012345678901234567890*x")),
    ("factorial", sys_l("x_dot**2 + factorial(10**10)")),
    ("float-precision", sys_l("x_dot**2 + Float(1, 10**8)")),
    ("hang-evaluation", sys_l("x_dot**2 + sin(sin(3+exp(exp(exp(3)))))*x")),
    ("constant-overflow", sys_l("x_dot**2 + exp(1000)*x")),
    # nesting and length
    ("deep-parentheses", sys_l("(" * 150 + "x_dot" + ")" * 150)),
    ("deep-parentheses-overflow", sys_l("(" * 250 + "x_dot" + ")" * 250)),
    ("deep-signs", sys_l("-" * 1900 + "x_dot")),
    ("deep-calls", sys_l("sin(" * 60 + "x" + ")" * 60 + " + x_dot**2")),
    ("long-expression", sys_l("+".join(["x_dot**2"] * 300))),
    ("too-many-coordinates", sys_l("a_dot**2", coordinates=tuple("abcdefghijklm"))),
    (
        "too-many-particles",
        {"coordinates": ["x"], "particles": [{"mass": "1", "position": ["x", "0"]}] * 13, "potential": "0"},
    ),
    # singular and malformed systems
    ("no-velocity", sys_l("x**2")),
    ("linear-in-velocity", sys_l("x_dot*x - x**2/2")),
    ("cubic-in-velocity", sys_l("x_dot**3 - x**2")),
    ("missing-coordinate-in-T", sys_tu("m*x_dot**2/2", "k*x**2/2", coordinates=("x", "y"))),
    ("redundant-coordinates", sys_tu("m*(x_dot + y_dot)**2/2", "0", coordinates=("x", "y"))),
    ("two-forms", {**sys_tu("m*x_dot**2/2", "0"), "lagrangian": "x_dot**2"}),
    ("no-form", {"coordinates": ["x"]}),
    ("undefined", sys_l("x_dot**2 + 1/(x - x)")),
    ("not-real", sys_l("x_dot**2 + sqrt(-x**2)")),
    # NaN, Infinity and numbers JSON cannot hold
    ("nan-value", b'{"coordinates": ["x"], "parameters": [{"name": "k", "value": NaN}], "lagrangian": "x_dot**2"}'),
    (
        "infinity-value",
        b'{"coordinates": ["x"], "parameters": [{"name": "k", "value": Infinity}], "lagrangian": "x_dot**2"}',
    ),
    (
        "minus-infinity-min",
        b'{"coordinates": ["x"], "parameters": [{"name": "k", "min": -Infinity}], "lagrangian": "x_dot**2"}',
    ),
    (
        "overflowing-float",
        b'{"coordinates": ["x"], "parameters": [{"name": "k", "value": 1e400}], "lagrangian": "x_dot**2"}',
    ),
    ("huge-value", {"coordinates": ["x"], "parameters": [{"name": "k", "value": 1e300}], "lagrangian": "x_dot**2"}),
    (
        "many-digit-integer",
        b'{"coordinates": ["x"], "parameters": [{"name": "k", "value": 1'
        + b"0" * 6000
        + b'}], "lagrangian": "x_dot**2"}',
    ),
    (
        "value-outside-range",
        {"coordinates": ["x"], "parameters": [{"name": "k", "value": 5, "max": 1}], "lagrangian": "x_dot**2"},
    ),
    # shapes
    ("not-json", b"coordinates=x&lagrangian=x_dot**2"),
    ("json-array", b'["x"]'),
    ("json-null", b"null"),
    ("expression-not-string", {"coordinates": ["x"], "lagrangian": 5}),
    ("expression-object", {"coordinates": ["x"], "lagrangian": {"__class__": "x"}}),
    ("unknown-key", {**sys_l("x_dot**2"), "__proto__": {"admin": True}}),
    ("coordinates-string", {"coordinates": "x", "lagrangian": "x_dot**2"}),
    # oversized bodies
    ("oversized", b'{"coordinates": ["x"], "lagrangian": "' + b"x+" * MAX_BODY_BYTES + b'x"}'),
]


def _body(raw, canary):
    if isinstance(raw, bytes):
        return raw
    return json.dumps(raw).replace("{canary}", canary).encode()


@pytest.fixture(scope="module")
def canary(tmp_path_factory):
    path = tmp_path_factory.mktemp("canary") / "canary"
    yield str(path)
    assert not path.exists()


def test_corpus_is_large_enough():
    assert len(CORPUS) >= 40
    assert len({name for name, _ in CORPUS}) == len(CORPUS)


@pytest.mark.parametrize(("name", "raw"), CORPUS, ids=[name for name, _ in CORPUS])
def test_hostile_input_is_refused_promptly_and_runs_nothing(client, canary, name, raw):
    body = _body(raw, canary)
    started = time.monotonic()
    response = client.post("/api/derive", content=body, headers={"content-type": "application/json"})
    elapsed = time.monotonic() - started
    assert 400 <= response.status_code < 500, (name, response.status_code, response.text[:300])
    # a hang guard: the answer comes long before the worker's hard limit would have to act
    assert elapsed < settings().derive_seconds, (name, elapsed)
    answer = response.json()
    assert isinstance(answer["detail"], str) and answer["detail"]
    # refusals never echo big inputs back
    assert len(response.content) < 4000, (name, len(response.content))
    import os

    assert not os.path.exists(canary), name


def test_chunked_oversized_body_is_refused(client):
    def chunks():
        for _ in range(64):
            yield b" " * 1024

    response = client.post("/api/derive", content=chunks(), headers={"content-type": "application/json"})
    assert response.status_code == 413
    assert str(MAX_BODY_BYTES) in response.json()["detail"]


def test_lying_content_length_is_refused(client):
    response = client.post(
        "/api/derive", content=b"{}", headers={"content-type": "application/json", "content-length": "x"}
    )
    assert response.status_code == 400


def test_server_is_healthy_after_the_corpus(client):
    assert client.get("/healthz").json() == {"status": "ok"}
    response = client.post(
        "/api/derive", json={"coordinates": ["x"], "parameters": ["k"], "lagrangian": "x_dot**2/2 - k*x**2/2"}
    )
    assert response.status_code == 200
    assert response.json()["accelerations"]["x"]["sympy"] == "-k*x"
