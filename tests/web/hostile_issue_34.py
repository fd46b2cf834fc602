"""The hostile corpus's probes from issue 34 (tests/web/test_hostile_corpus.py runs them with its ``Probe``)."""

from __future__ import annotations

from typing import Any
from urllib.parse import quote

from app.web.api.limits import MAX_BODY_BYTES, MAX_JSON_DEPTH


def issue_34_probes(Probe: Any, json_headers: list[tuple[bytes, bytes]]) -> list[Any]:  # noqa: N803
    """Lone surrogates in echoed text, nesting hidden by an encoding, and refusals that must name their cause."""
    probes = []
    surrogate = "\\ud800"  # a JSON escape: json.loads makes it a lone surrogate
    for where, system in {
        "L": '{"coordinates": ["x"], "lagrangian": "x_dot**2/2 - x**2/2%s"}',
        "coordinate": '{"coordinates": ["x%s"], "lagrangian": "x_dot**2"}',
        "unit": '{"coordinates": ["x"], "lagrangian": "x_dot**2", "parameters": [{"name": "a", "unit": "%s"}]}',
        "force": '{"coordinates": ["x"], "lagrangian": "x_dot**2", "forces": {"x": "%s"}}',
    }.items():
        text = system % surrogate
        probes.append(
            Probe(f"surrogate-{where}-playground", "GET", "/playground?system=" + quote(text), (422,), says="surrogate")
        )
        probes.append(
            Probe(f"surrogate-{where}-api", "POST", "/api/derive", (422,), content=text.encode(), headers=json_headers)
        )
    # U+2200 holds a quote's byte in UTF-16 and UTF-32: a scan of the raw bytes lost track of the nesting
    for encoding in ("utf-16", "utf-16-be", "utf-32"):
        for levels in (MAX_JSON_DEPTH + 1, 900, 5000):
            body = ('{"\u2200": 1, "coordinates": ' + "[" * levels + "]" * levels + "}").encode(encoding)
            if len(body) > MAX_BODY_BYTES:
                continue
            for path in ("/api/derive", "/api/simulate"):
                probes.append(
                    Probe(
                        f"deep-{encoding}-{levels}{path}", "POST", path, (400,), content=body,
                        headers=json_headers, says="nested deeper",
                    )
                )  # fmt: skip
    refusals = {
        "zero-mass": (
            {"coordinates": ["x"], "parameters": [{"name": "m", "value": 0}], "kinetic": "m*x_dot**2/2",
             "potential": "x**2/2", "initial": {"x": 1}},
            "m = 0",
        ),
        "acos-outside-domain": (
            {"coordinates": ["x"], "kinetic": "x_dot**2/2", "potential": "acos(x)", "initial": {"x": 2}},
            "acos(x) is not defined at x = 2",
        ),
        "exp-overflow": (
            {"coordinates": ["x"], "kinetic": "x_dot**2/2", "potential": "exp(exp(exp(exp(x))))", "initial": {"x": 5}},
            "overflows at x = 5",
        ),
        "divide-at-start": (
            {"coordinates": ["r"], "kinetic": "r_dot**2/2", "potential": "1/r", "initial": {"r": 0}},
            "1/r divides by zero at r = 0",
        ),
    }  # fmt: skip
    for name, (body, words) in refusals.items():
        probes.append(Probe(f"start-{name}", "POST", "/api/simulate", (422,), json=body, says=words))
    return probes
