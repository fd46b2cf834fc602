"""Defaults and limits defined once: every module that means the same number reads the same definition."""

import subprocess
import sys

import pytest
from pydantic import ValidationError

from app import limits as shared
from app.engine.equations import reduction, transform
from app.numerics import limits
from app.scenes import SCENES, Scene
from app.service.simulations import poincare, simulation
from app.settings import ROOT
from app.viz.page_model import DEFAULT_RTOL, RTOLS
from app.web.schemas.user import ParameterSpec


def test_the_page_offers_the_tolerances_the_api_accepts_with_its_default_chosen():
    offered = [float(r) for r in RTOLS]
    assert offered == list(limits.RTOL_MENU) == sorted(offered, reverse=True)
    assert all(limits.RTOL_MIN <= r <= limits.RTOL_MAX for r in offered)
    assert float(DEFAULT_RTOL) == limits.RTOL_DEFAULT and DEFAULT_RTOL in RTOLS


@pytest.mark.parametrize("value", [limits.VALUE_MAX, -limits.VALUE_MAX])
def test_a_declared_parameter_may_be_as_large_as_a_simulation_accepts(value):
    assert ParameterSpec(name="k", value=value, min=value, max=value).value == value


@pytest.mark.parametrize("field", ["value", "min", "max"])
def test_a_declared_parameter_beyond_the_largest_value_is_refused(field):
    with pytest.raises(ValidationError, match="less than or equal to 1000000000000|greater than or equal to -1000"):
        ParameterSpec(name="k", **{field: 10 * limits.VALUE_MAX})


def test_the_default_end_time_is_one_number():
    assert Scene.__dataclass_fields__["t_end"].default == simulation.DEFAULT_T_END == shared.DEFAULT_T_END
    assert poincare.DEFAULT_T_END == shared.POINCARE_T_END
    assert all(s.t_end > 0 for s in SCENES.values())


def test_modules_meaning_the_same_budget_share_it():
    assert reduction.SOLVE_WORK is transform.SOLVE_WORK is shared.SOLVE_WORK


def test_no_bound_inside_the_engine_reads_a_clock():
    # what a document holds must be a function of its input (issue 43): the engine's bounds count work; the one
    # clock of a request (budget.clock_limit, at the worker job's edge) refuses, and is the only reader of one
    found = subprocess.run(
        ["grep", "-rnE", r"time\.(monotonic|perf_counter|process_time|time|thread_time)\(|getitimer", "app/engine",
         "--include=*.py"], cwd=ROOT, capture_output=True, text=True,
    ).stdout.splitlines()  # fmt: skip
    assert [line for line in found if not line.startswith("app/engine/algebra/budget.py:")] == []
    budget_lines = [line for line in found if line.startswith("app/engine/algebra/budget.py:")]
    assert len(budget_lines) == 3  # clock_limit's: the outer clock, its start, the re-armed outer one


@pytest.mark.slow
def test_the_keep_alive_is_a_setting_the_server_options_pass_on():
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "LAGRANGE_KEEP_ALIVE_SECONDS": "31"}
    given = subprocess.run(
        [sys.executable, "-m", "app.web.http.server_options"], cwd=ROOT, capture_output=True, text=True, env=env, check=True
    ).stdout.split()
    assert given[given.index("--timeout-keep-alive") + 1] == "31"


def test_no_module_of_the_app_defines_a_time_bound_of_its_own():
    found = subprocess.run(
        ["grep", "-rnE", "^[A-Z_]*_SECONDS *(: *[a-z]+)? *=", "app", "--include=*.py"],
        cwd=ROOT, capture_output=True, text=True,
    ).stdout.splitlines()  # fmt: skip
    # numerics/limits.py holds the bounds of a simulation request (its WALL_SECONDS among them); the example
    # file's short limit is an example's, not the program's
    allowed = ("app/limits.py:", "app/numerics/limits.py:", "app/web/api/examples_user.py:")
    assert [line for line in found if not line.startswith(allowed)] == []


def test_a_changed_limit_changes_the_caches_fingerprint(monkeypatch, tmp_path):
    from app.service.runtime import cache

    (tmp_path / "engine").mkdir()
    (tmp_path / "engine" / "a.py").write_text("X = 1\n")
    (tmp_path / "limits.py").write_text("SOLVE_WORK = 40_000\n")
    monkeypatch.setattr(cache, "APP_SOURCE", tmp_path)
    before = cache.source_fingerprint("engine")
    (tmp_path / "limits.py").write_text("SOLVE_WORK = 50_000\n")
    assert cache.source_fingerprint("engine") != before


@pytest.mark.parametrize("name", ["t_end", "rtol", "atol", "samples"])
def test_the_api_documents_the_range_the_service_holds_a_request_to(name):
    """One table of a simulation request's ranges (limits.RANGES): the schema's documented bounds are those the
    service names when it refuses a request that did not pass through the schema (a worker's, a script's)."""
    from types import SimpleNamespace

    from app.numerics.errors import SimulationError
    from app.web.schemas.simulate import SimulateRequest
    from tests.served import scene_run

    documented = SimulateRequest.model_json_schema()["properties"][name]["anyOf"][0]
    low, high = documented["minimum"], documented["maximum"]
    asked = {"parameters": {}, "initial": {}, "t_end": None, "method": "auto", "rtol": None, "atol": None}
    for beyond in (low / 10, high * 10):
        request = SimpleNamespace(**{**asked, "samples": None, name: beyond})
        with pytest.raises(SimulationError, match=rf"\[{low:g}, {high:g}\]"):
            scene_run("simple-pendulum", request)
        with pytest.raises(ValidationError):
            SimulateRequest(initial={}, **{name: beyond})
