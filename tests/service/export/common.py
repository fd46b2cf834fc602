"""What the export tests export: every scene, two user systems and a hostile one, and the app's own runs."""

from __future__ import annotations

from functools import cache
from types import SimpleNamespace
from typing import Any

from app.engine.derivation.derive import Derivation, derive
from app.engine.document.contract import printed_document
from app.scenes import SCENES
from app.service.chapter import derivations
from app.service.export import exporting
from app.service.users import user_jobs
from app.service.users.user_checks import checked
from app.web.api.examples_user import DOUBLE_PENDULUM, FORCED_SPRING
from app.web.schemas.user import SystemSpec
from tests.served import derivation_run, scene_run

RTOL, ATOL = 1e-10, 1e-12

# Legal names chosen to collide with what generated code uses (exec, print, sp, q0), one that SymPy
# typesets with a command amsmath lacks (xscr), and prose (units, descriptions) that tries to
# become LaTeX, markdown, HTML or code.
HOSTILE = {
    "coordinates": ["exec", "sp"],
    "parameters": [
        {
            "name": "print",
            "value": 2.0,
            "unit": "$\\input{/etc/passwd}$",
            "description": "<script>alert(1)</script> \\end{document} [x](javascript:alert(1))\n# import os",
        },
        {"name": "xscr", "value": 1.0, "unit": "%\\write18{rm}", "description": "```\nimport os\nos.system('rm')\n```"},
        {"name": "q0", "value": 1.5, "unit": "}{\\def", "description": "$$\\begin{document}$$ ~^_&#|<>"},
    ],
    "kinetic": "print*exec_dot**2/2 + print*sp_dot**2/2",
    "potential": "xscr*exec**2/2 + q0*sp**2/2 + exec*sp/4",
}
HOSTILE_TEXT = ("passwd", "script>", "javascript", "write18", "import os", "os.system", "\\def", "begin{document}$")

# name -> (request body of POST /api/derive, initial state, t_end)
USER_SYSTEMS: dict[str, tuple[dict[str, Any], dict[str, float], float]] = {
    # a user system, not the scene of the same name: the key differs so the two never mix
    "user-double-pendulum": (DOUBLE_PENDULUM, {"theta1": 1.0, "theta2": 0.0}, 10.0),
    "forced-spring": (FORCED_SPRING, {"x": 1.0}, 5.0),
    "hostile": (HOSTILE, {"exec": 0.5, "sp_dot": 0.3}, 3.0),
}
CASES = [*SCENES, *USER_SYSTEMS]


def spec_of(body: dict[str, Any]) -> dict[str, Any]:
    return SystemSpec.model_validate(body).to_spec()


@cache
def user_derivation(name: str) -> Derivation:
    return derive(user_jobs.build_system(checked(spec_of(USER_SYSTEMS[name][0]))))


@cache
def exported(case: str, fmt: str) -> str:
    """The file for a scene (as the scene route serves it) or a user system (as the worker job makes it)."""
    if case in SCENES:
        return exporting.scene_export(case, fmt, derivations.scene_document).content.decode()
    _, initial, t_end = USER_SYSTEMS[case]
    d = user_derivation(case)
    return exporting.system_export(d, printed_document(d), fmt, initial, t_end)["content"]


def app_end_state(case: str) -> tuple[float, dict[str, float]]:
    """The app's own simulation with scipy's DOP853 at the script's tolerances: (t_end, last state)."""
    request = SimpleNamespace(parameters={}, initial={}, t_end=None, method="DOP853", rtol=RTOL, atol=ATOL, samples=2)
    if case in SCENES:
        doc = scene_run(case, request)
    else:
        _, initial, t_end = USER_SYSTEMS[case]
        request.initial, request.t_end = initial, t_end
        doc = derivation_run(user_derivation(case), request)
    return doc["t"][-1], {name: values[-1] for name, values in doc["state"].items()}
