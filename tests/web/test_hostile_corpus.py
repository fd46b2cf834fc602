"""A hostile corpus against the real server (uvicorn on a loopback port), one probe per test.

Each probe asserts its status, that the answer came well within the worker's
hard limit (a hang guard: the speed figures are benchmarks/bench_user_api.py's),
that the server is healthy afterwards, that nothing was echoed back at length,
and that a canary file the code-like payloads aim at is untouched.  The classes:
cookies, JSON nesting, expression bombs (in every field, through the API and
the playground's form), constants that are not real, names matched whole,
bodies over the cap on every POST route, echoes, static paths, methods, and
legal systems that must still work.
"""

from __future__ import annotations

import http.client
import json
import time
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import quote, urlencode

import pytest

from app.settings import settings
from app.web.api.limits import MAX_BODY_BYTES, MAX_JSON_DEPTH
from tests.browser.conftest import live_server  # noqa: F401  (the session's uvicorn server)
from tests.web.hostile_issue_34 import issue_34_probes

pytestmark = pytest.mark.slow  # every hostile probe against a live server

HANG_GUARD = settings().derive_seconds  # the worker's hard limit: an answer after it would be a hang
PARAMETERS = ["a", "b", "c", "d", "k"]


@dataclass
class Probe:
    id: str
    method: str
    path: str
    expect: tuple[int, ...]
    json: object = None
    content: bytes | None = None
    headers: list[tuple[bytes, bytes]] = field(default_factory=list)
    fresh_cookie: bool = False  # the answer must issue a new session
    says: str = ""  # words the answer must contain (a refusal that names its real cause)


def lagrangian(text: str) -> dict:
    return {"coordinates": ["x"], "parameters": PARAMETERS, "lagrangian": text}


def in_every_field(text: str) -> list[tuple[str, dict]]:
    """The same expression as L, T, U, a force, a particle's position and its mass."""
    return [
        ("L", lagrangian(f"x_dot**2/2 - ({text})")),
        ("T", {"coordinates": ["x"], "parameters": PARAMETERS, "kinetic": f"x_dot**2*({text})", "potential": "x**2"}),
        ("U", {"coordinates": ["x"], "parameters": PARAMETERS, "kinetic": "x_dot**2/2", "potential": text}),
        ("force", {**lagrangian("x_dot**2/2 - x**2/2"), "forces": {"x": text}}),
        (
            "position",
            {"coordinates": ["x"], "parameters": PARAMETERS, "particles": [{"mass": "1", "position": [text, "x"]}],
             "potential": "0"},
        ),
        (
            "mass",
            {"coordinates": ["x"], "parameters": PARAMETERS, "particles": [{"mass": text, "position": ["x", "0"]}],
             "potential": "0"},
        ),
    ]  # fmt: skip


def playground(spec: dict) -> str:
    """The playground's GET form for a system (the query string a student's link carries)."""
    names = spec.get("parameters", [])
    # every parameter with a value: a blank value is an error at its field (issue 29), never a silent 1
    query: dict[str, object] = {"q": ",".join(spec["coordinates"]), "pn": names, "pv": ["1"] * len(names)}
    if "lagrangian" in spec:
        query |= {"form": "lagrangian", "L": spec["lagrangian"]}
    elif "kinetic" in spec:
        query |= {"form": "energies", "T": spec["kinetic"], "U": spec["potential"]}
    else:
        p = spec["particles"][0]
        query |= {"form": "particles", "m": p["mass"], "x": p["position"][0], "y": p["position"][1], "U": "0"}
    if spec.get("forces"):
        query |= {"fq": list(spec["forces"]), "fQ": list(spec["forces"].values())}
    return "/playground?" + urlencode(query, doseq=True)


# Expressions that pass the character and shape checks but that SymPy cannot handle quickly
# (roots of huge integers, exponents hidden behind signs or logarithms, expansions inside
# function calls, long chains of nested functions, combined powers).
BOMBS = {
    "tower-behind-signs": "9**+-80**+-19**-33*x",
    "tower-behind-signs-2": "6**+-10**-+7**-40*x",
    "root-of-huge-index": "12**(1 - 1/3**40)*x",
    "root-index-3-17": "2**(1/3**17)*x",
    "exp-log-power": "exp(99*log(x + a + b + t))",
    "exp-log-million": "exp(1000000*log(x + 1))",
    "exp-log-huge": "exp(10**15*log(x))",
    "exp-log-in-sum": "exp(x + 80*log(x + a))",
    "expand-inside-sin": "sin((a+b+c+d+x+t)**30)",
    "expand-inside-log": "log((x+a+b+c+d+t)**40)",
    "expand-inside-sqrt": "sqrt((x+a+b+c+d+t)**24)",
    "expand-inside-cos": "cos((x+a+b+c+d+t)**25)",
    "sin-tower": "sin(" * 37 + "x" + ")" * 37,
    "combined-powers": "((x**60)**60)**60",
    "product-of-powers": "x**64*x**64*x**64*x**64*x**64",
    "tiny-exact-constant": "10**-99*10**-99*10**-99*10**-99*10**-99*x",
}
NOT_REAL = {
    "asin-2": "asin(2)*x",
    "log-minus-1": "log(-1)*x",
    "acos-1.5": "acos(1.5)*x",
    "sqrt-minus-1": "sqrt(-1)*x",
    "asin-just-above-1": "asin(1 + 1e-16)*x",
    "asin-hidden": "asin(2 + x - x)*x",
    "cube-root-of-negative": "(-8)**(1/3)*x",
    "log-hidden": "log(x - x - 1)*x",
    "acos-hidden": "acos(x/x + 1)*x",
}
BAD_NAMES = ["k\n", "x\n", "k\r\n", "k\t", " k", "k ", "k\x00", "kap\u200bpa", "\nk", "k\ndot"]
COOKIES = {
    "non-ascii": "é.abc".encode("latin-1"),
    "non-ascii-utf8": "ünïcode.sig".encode(),
    "tampered": b"abcdefghijklmnop.000000000000000000000000",
    "no-dot": b"abcdefghijklmnop",
    "many-dots": b"a.b.c.d.e",
    "long": b"a" * 5000 + b".sig",
    "empty-signature": b"abc.",
    "tab": b"ab\tcd.ef",
    "quoted": b'"abc.def"',
}
# a control byte in a header: uvicorn's HTTP parser refuses the request itself (400) before the app
RAW_COOKIES = {"control-bytes": b"ab\x01cd.ef", "delete-byte": b"ab\x7fcd.ef"}
STATIC_PATHS = [
    "/static/../app/main.py",
    "/static/%2e%2e/app/main.py",
    "/static/%2e%2e%2f%2e%2e%2fetc/passwd",
    "/static/..%2fpyproject.toml",
    "/static//etc/passwd",
    "/static/js/../../app/main.py",
]


def deep(depth: int) -> bytes:
    return b"[" * depth + b"]" * depth


def _probes() -> list[Probe]:
    probes: list[Probe] = []
    json_headers = [(b"content-type", b"application/json")]
    # cookies: ignored when malformed, and a fresh session issued with the answer
    for name, value in COOKIES.items():
        cookie = [(b"cookie", b"lagrange_session=" + value)]
        probes.append(
            Probe(
                f"cookie-{name}-derive",
                "POST",
                "/api/derive",
                (200,),
                json=lagrangian("x_dot**2/2 - k*x**2/2"),
                headers=cookie,
                fresh_cookie=True,
            )
        )
        probes.append(
            Probe(f"cookie-{name}-playground", "GET", "/playground", (200,), headers=cookie, fresh_cookie=True)
        )
    for name, value in RAW_COOKIES.items():
        cookie = [(b"cookie", b"lagrange_session=" + value)]
        for path in ("/playground", "/"):
            probes.append(Probe(f"cookie-{name}{path}", "GET", path, (200, 400), headers=cookie))
    # JSON nesting, in bodies and in the playground's ?system=
    for path in ("/api/derive", "/api/simulate", "/api/scenes/simple-pendulum/simulate"):
        for depth in (MAX_JSON_DEPTH + 1, 5000):
            probes.append(
                Probe(f"deep-json-{depth}{path}", "POST", path, (400,), content=deep(depth), headers=json_headers)
            )
        probes.append(
            Probe(
                f"deep-in-object{path}",
                "POST",
                path,
                (400,),
                content=b'{"coordinates": ' + deep(10000) + b"}",
                headers=json_headers,
            )
        )
    for depth in (MAX_JSON_DEPTH + 1, 1500, 2000):
        probes.append(Probe(f"deep-json-playground-{depth}", "GET", "/playground?system=" + quote(deep(depth)), (422,)))
    probes.append(Probe("not-json-playground", "GET", "/playground?system=" + quote("{nope"), (422,)))
    probes.append(Probe("json-list-playground", "GET", "/playground?system=" + quote("[1, 2]"), (422,)))
    probes.append(
        Probe(
            "json-wrong-shape-playground",
            "GET",
            "/playground?system=" + quote('{"parameters": [[]], "particles": [{"position": 5}]}'),
            (422,),
        )
    )
    # expression bombs, in every field, through the API and through the playground's form
    for name, text in BOMBS.items():
        for where, spec in in_every_field(text):
            probes.append(Probe(f"bomb-{name}-{where}", "POST", "/api/derive", (422,), json=spec))
        probes.append(Probe(f"bomb-{name}-playground", "GET", playground(lagrangian(text)), (422,)))
    probes.append(
        Probe(
            "bomb-simulate",
            "POST",
            "/api/simulate",
            (422,),
            json={**lagrangian(BOMBS["exp-log-power"]), "initial": {"x": 1.0}},
        )
    )
    s6 = "(x + a + b + c + d + t)**3"
    probes.append(
        Probe(
            "eight-particles-cubed-sums",
            "POST",
            "/api/derive",
            (422,),
            json={
                "coordinates": ["x"],
                "parameters": PARAMETERS,
                "potential": "0",
                "particles": [{"mass": "1", "position": [s6, s6]}] * 8,
            },
        )
    )
    # constants that are not real
    for name, text in NOT_REAL.items():
        probes.append(Probe(f"not-real-{name}", "POST", "/api/derive", (422,), json=lagrangian(f"x_dot**2/2 - {text}")))
        probes.append(
            Probe(f"not-real-{name}-playground", "GET", playground(lagrangian(f"x_dot**2/2 - {text}")), (422,))
        )
    # names are matched whole: a trailing newline is not part of a name
    for i, bad in enumerate(BAD_NAMES):
        probes.append(
            Probe(
                f"name-parameter-{i}",
                "POST",
                "/api/derive",
                (422,),
                json={"coordinates": ["x"], "parameters": [bad], "lagrangian": "x_dot**2/2"},
            )
        )
        probes.append(
            Probe(
                f"name-coordinate-{i}",
                "POST",
                "/api/derive",
                (422,),
                json={"coordinates": [bad], "lagrangian": "x_dot**2/2"},
            )
        )
    # bodies over the cap, on every POST route; lying or missing lengths
    for path in (
        "/api/derive",
        "/api/simulate",
        "/api/scenes/simple-pendulum/simulate",
        "/api/scenes/no-such-scene/simulate",
    ):
        probes.append(
            Probe(f"oversized{path}", "POST", path, (413,), content=b" " * (MAX_BODY_BYTES + 1), headers=json_headers)
        )
        probes.append(
            Probe(
                f"declared-huge{path}",
                "POST",
                path,
                (413,),
                content=b"{}",
                headers=[*json_headers, (b"content-length", b"999999999999")],
            )
        )
        probes.append(
            Probe(
                f"length-not-a-number{path}",
                "POST",
                path,
                (400,),
                content=b"{}",
                headers=[*json_headers, (b"content-length", b"12x")],
            )
        )
    # echoes: a long key or value never comes back whole
    long_key = "k" * (MAX_BODY_BYTES - 200)
    probes.append(
        Probe(
            "long-key-scene",
            "POST",
            "/api/scenes/simple-pendulum/simulate",
            (422,),
            json={"parameters": {long_key: 1.0}, "initial": {"theta": 1.0}},
        )
    )
    probes.append(
        Probe(
            "long-key-initial",
            "POST",
            "/api/scenes/simple-pendulum/simulate",
            (422,),
            json={"initial": {long_key: 1.0}},
        )
    )
    probes.append(
        Probe(
            "long-force-key",
            "POST",
            "/api/derive",
            (422,),
            json={**lagrangian("x_dot**2/2"), "forces": {long_key: "0"}},
        )
    )
    probes.append(
        Probe("long-unknown-field", "POST", "/api/derive", (422,), json={**lagrangian("x_dot**2/2"), long_key: 1})
    )
    probes.append(
        Probe(
            "long-method",
            "POST",
            "/api/scenes/simple-pendulum/simulate",
            (422,),
            json={"initial": {"theta": 1.0}, "method": long_key},
        )
    )
    # static files stay inside /static
    for i, path in enumerate(STATIC_PATHS):
        probes.append(Probe(f"static-{i}", "GET", path, (404,)))
    # methods
    for method, path in (
        ("GET", "/api/derive"),
        ("PUT", "/api/derive"),
        ("DELETE", "/api/simulate"),
        ("GET", "/api/scenes/simple-pendulum/simulate"),
        ("POST", "/playground"),
        ("PATCH", "/api/scenes/simple-pendulum/simulate"),
    ):
        probes.append(Probe(f"method-{method}{path}", method, path, (405,), content=b"{}", headers=json_headers))
    # code through every door still runs nothing
    for i, payload in enumerate(
        ["__import__('os').remove('{canary}')", "open('{canary}', 'w')", "sin.__globals__", "x_dot.__class__"]
    ):
        probes.append(Probe(f"code-{i}", "POST", "/api/derive", (422,), json=lagrangian(payload)))
        probes.append(Probe(f"code-{i}-playground", "GET", playground(lagrangian(payload)), (422,)))
    # legal systems that must still be accepted
    probes.append(
        Probe(
            "sum-of-90-terms",
            "POST",
            "/api/derive",
            (200,),
            json=lagrangian("x_dot**2/2 - (" + " + ".join(f"x**2/{i + 2}" for i in range(90)) + ")"),
        )
    )
    probes.append(Probe("abs-derives", "POST", "/api/derive", (200,), json=lagrangian("x_dot**2/2 - Abs(x)")))
    probes.append(
        Probe(
            "abs-simulates",
            "POST",
            "/api/simulate",
            (200,),
            json={**lagrangian("x_dot**2/2 - Abs(x)"), "initial": {"x": 1.0}, "t_end": 2.0},
        )
    )
    probes.append(
        Probe("exp-log-small", "POST", "/api/derive", (200,), json=lagrangian("x_dot**2/2 - exp(2*log(x**2 + 1))"))
    )
    probes.append(Probe("abs-playground", "GET", playground(lagrangian("x_dot**2/2 - Abs(x)")), (200,)))
    probes += issue_34_probes(Probe, json_headers)  # tests/web/hostile_issue_34.py
    return probes


PROBES = _probes()


@pytest.fixture(scope="module", autouse=True)
def warm_pool(live_server):  # noqa: F811
    # the first job starts the worker pool (seconds of imports): not a probe's time
    answer = send(
        live_server,
        "POST",
        "/api/derive",
        json.dumps(lagrangian("x_dot**2/2")).encode(),
        [(b"content-type", b"application/json")],
    )
    assert answer.status == 200


@pytest.fixture(scope="module")
def canary(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("canary") / "canary"
    path.write_text("untouched")
    return path


@dataclass
class Answer:
    status: int
    headers: dict[str, str]
    body: bytes
    seconds: float


def send(base: str, method: str, path: str, body: bytes | None, headers: list[tuple[bytes, bytes]]) -> Answer:
    """One request sent as given (http.client checks neither the path nor Content-Length against the body)."""
    host, port = base.removeprefix("http://").split(":")
    connection = http.client.HTTPConnection(host, int(port), timeout=120)
    started = time.monotonic()
    try:
        connection.putrequest(method, path, skip_accept_encoding=True)
        names = {k.lower() for k, _ in headers}
        for key, value in headers:
            connection.putheader(key.decode(), value)
        if body is not None and b"content-length" not in names:
            connection.putheader("Content-Length", str(len(body)))
        connection.endheaders(body)
        response = connection.getresponse()
        data = response.read()
        return Answer(
            response.status, {k.lower(): v for k, v in response.getheaders()}, data, time.monotonic() - started
        )
    finally:
        connection.close()


def test_the_corpus_is_large_and_named_once():
    assert len(PROBES) >= 150
    assert len({p.id for p in PROBES}) == len(PROBES)


# names a refusal must never show a student (a derivation may well contain a DiracDelta: that is mathematics)
INTERNAL_NAMES = ("Traceback", "RecursionError", "PrintMethodNotImplementedError", "DiracDelta", "Internal Server")


@pytest.mark.parametrize("probe", PROBES, ids=[p.id for p in PROBES])
def test_hostile_probe(live_server, canary, probe):  # noqa: F811
    before = canary.stat()
    body, headers = probe.content, list(probe.headers)
    if probe.json is not None:
        body = json.dumps(probe.json).replace("{canary}", str(canary)).encode()
        headers.append((b"content-type", b"application/json"))
    path = probe.path.replace(quote("{canary}"), quote(str(canary)))
    answer = send(live_server, probe.method, path, body, headers)
    text = answer.body.decode(errors="replace")
    assert answer.status in probe.expect, (probe.id, answer.status, text[:300])
    assert answer.seconds < HANG_GUARD, (probe.id, answer.seconds)
    # refusals say what was wrong, briefly, in the student's terms, and never repeat a big input
    if answer.status >= 400 and answer.headers.get("content-type", "").startswith(("application/json", "application/problem+json")):
        assert json.loads(answer.body)["detail"]
        assert len(answer.body) < 4000, (probe.id, len(answer.body))
    assert answer.status < 400 or not any(name in text for name in INTERNAL_NAMES), probe.id
    assert probe.says in text, (probe.id, text[:300])
    if probe.fresh_cookie:
        assert "lagrange_session=" in answer.headers.get("set-cookie", ""), probe.id
    assert send(live_server, "GET", "/healthz", None, []).status == 200
    after = canary.stat()
    assert canary.read_text() == "untouched" and after.st_mtime_ns == before.st_mtime_ns, probe.id
