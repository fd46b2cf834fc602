"""The simulation service: request checks with clear messages, the JSON document, work-precision data."""

import json
from contextlib import contextmanager
from types import SimpleNamespace

import numpy as np
import pytest

from app.numerics import limits
from app.numerics.errors import SimulationError, TooMuchWork
from app.scenes import SCENES
from app.service.chapter.derivations import PROCESS_SCENES, derivation
from app.service.runtime.encoding import dumps
from app.service.simulations import rounding, simulation, work_precision
from app.web.api.errors import problem
from tests.served import derivation_run, scene_run

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def request(**fields):
    base = {"parameters": {}, "initial": {}, "t_end": None, "method": "auto", "rtol": None, "atol": None, "samples": 50}
    return SimpleNamespace(**{**base, **fields})


def test_document_shape_for_a_scene():
    doc = scene_run("spherical-pendulum", request(t_end=2.0))
    assert len(doc["t"]) == 50 and doc["t"][0] == 0.0 and doc["t"][-1] == 2.0
    assert set(doc["state"]) == {"theta", "theta_dot", "phi", "phi_dot"}
    assert set(doc["conserved"]) == {"p_phi", "E"}
    assert "string tension" in doc["constraint_forces"]
    stats = doc["stats"]
    for key in ("method", "reason", "steps", "rhs_evaluations", "wall_time_s", "error_estimate", "max_energy_drift"):
        assert key in stats
    assert stats["max_hamiltonian_drift"] is not None and stats["t_end_reached"] == 2.0
    assert stats["error_estimate"] < 1e-5


def test_defaults_come_from_the_scene():
    doc = scene_run("simple-pendulum", request(samples=None))
    assert len(doc["t"]) == limits.SAMPLES_DEFAULT and doc["t"][-1] == 10.0
    assert doc["state"]["theta"][0] == 1.0


@pytest.mark.parametrize(
    "fields, message",
    [
        ({"parameters": {"mass": 1.0}}, "unknown parameter 'mass'; this system has m, g, R"),
        ({"parameters": {"m": -1.0}}, "parameters.m = -1 is outside its allowed range"),
        ({"parameters": {"R": 0.0}}, "parameters.R = 0 is outside its allowed range"),
        ({"initial": {"x": 1.0}}, "unknown initial value 'x'; allowed: theta, theta_dot"),
        ({"initial": {"theta": float("nan")}}, "initial.theta must be a finite number"),
        ({"t_end": 1e9}, "t_end = 1e+09 is outside the allowed range"),
        ({"rtol": 1e-20}, "rtol = 1e-20 is outside the allowed range"),
        ({"samples": 10**7}, "samples = 1e+07 is outside the allowed range"),
        ({"method": "Euler"}, "unknown method 'Euler'"),
    ],
)
def test_bad_requests_are_refused_with_a_message(fields, message):
    with pytest.raises(SimulationError) as info:
        scene_run("simple-pendulum", request(**fields))
    assert message in str(info.value)
    assert problem(info.value).status == 422


def test_singular_start_is_refused():
    with pytest.raises(SimulationError, match=r"mass matrix is singular at this initial state \(r = 0\)"):
        scene_run("tabletop-spring", request(initial={"r": 0.0, "theta_dot": 1.0}))


def test_method_that_does_not_apply_is_refused():
    with pytest.raises(SimulationError, match="Yoshida4 cannot integrate this system"):
        scene_run("spherical-pendulum", request(method="Yoshida4"))


def test_too_much_work_is_a_clear_refusal():
    with pytest.raises(TooMuchWork, match="too much work for RK45") as info:
        scene_run(
            "tabletop-spring",
            request(parameters={"k": 1000.0}, t_end=1000.0, method="RK45", rtol=1e-10),
            simulation.Gates(wall_seconds=0.3),  # a short time budget
        )
    assert problem(info.value).status == 422


def test_slack_string_is_flagged():
    """From near the top at rest the string tension m (R theta_dot^2 + g cos theta) starts negative."""
    doc = scene_run("simple-pendulum", request(initial={"theta": 3.0}, t_end=1.0))
    assert min(doc["constraint_forces"]["string tension"]) < 0
    assert any("string tension becomes negative" in w.lower() for w in doc["stats"]["warnings"])
    # prof-f: every warning is served as a sentence (a capital letter, a full stop), never a bare clause
    assert all(w[0].isupper() and w.endswith(".") for w in doc["stats"]["warnings"]), doc["stats"]["warnings"]


def test_user_systems_go_through_the_same_function():
    from app.engine.derivation.derive import derive
    from tests.numerics.systems import DOUBLE_PENDULUM

    doc = derivation_run(derive(DOUBLE_PENDULUM), request(initial={"a": 1.0}, t_end=3.0))
    assert set(doc["state"]) == {"a", "a_dot", "c", "c_dot"} and doc["constraint_forces"] == {}
    assert doc["stats"]["error_estimate"] is not None


def test_constraint_forces_are_the_derivations_typed_members():
    from app.engine.derivation.derive import value_or

    d = derivation("simple-pendulum")
    (force,) = value_or(d.constraint_forces, ())
    doc = derivation_run(d, request(t_end=1.0), scene_id=None)
    assert list(doc["constraint_forces"]) == [force.constraint.name]
    # the series is the engine's expression itself, evaluated along the run (no text read back)
    values = {s.name: s for s in (*d.table.q, *d.table.qd, *d.table.params)}
    at_start = {values[n]: doc["state"][n][0] for n in doc["state"]}
    at_start.update({s: p.default for s, p in zip(d.table.params, d.system.parameters, strict=True)})
    assert doc["constraint_forces"][force.constraint.name][0] == pytest.approx(float(force.force.xreplace(at_start)))
    # none asked for, none observed
    none = derivation_run(d, request(t_end=1.0), constraint_forces=(), scene_id=None)
    assert none["constraint_forces"] == {}


def test_work_precision_data():
    data = work_precision.compute(
        "simple-pendulum", sweep=[1e-4, 1e-8], methods=["DOP853-compiled", "Yoshida4", "RK45", "LSODA"]
    )
    assert "exact pendulum solution" in data["reference"]
    assert {r["method"] for r in data["runs"]} == {"DOP853-compiled", "Yoshida4", "RK45", "LSODA"}
    for run in data["runs"]:
        assert run["error"] is not None and run["wall_time_s"] > 0 and run["rhs_evaluations"] > 0
    by = {(r["method"], r["rtol"]): r["error"] for r in data["runs"]}
    assert by[("DOP853-compiled", 1e-8)] < by[("DOP853-compiled", 1e-4)]


def test_work_precision_without_an_exact_solution_checks_its_reference():
    data = work_precision.compute("tabletop-spring", sweep=[1e-6], methods=["DOP853-compiled", "Gauss-Legendre"])
    assert "no exact solution" in data["reference"] and "differ by" in data["reference"]
    assert all(r["error"] is not None and r["error"] < 1e-3 for r in data["runs"])


@pytest.mark.parametrize("scene_id", ["coupled-oscillators", "rail-two-body"])
def test_work_precision_of_a_linear_scene_measures_against_its_exact_solution(scene_id):
    data = work_precision.compute(scene_id, sweep=[1e-6, 1e-10], methods=["DOP853-compiled"])
    assert (
        data["reference"].startswith("exact solution of the linear equations") and "no exact" not in data["reference"]
    )
    by = {r["rtol"]: r["error"] for r in data["runs"]}
    # errors against the exact motion fall with the tolerance, and the tight run is far below the loose one
    assert by[1e-10] < 1e-2 * by[1e-6]


def test_work_precision_is_cached_per_scene(monkeypatch, tmp_path):
    calls = []
    monkeypatch.setattr(work_precision, "compute", lambda scene_id: calls.append(scene_id) or {"runs": []})
    cache = work_precision.report_cache(tmp_path)  # the app's is given by its services (app/service/answers.py)
    work_precision.for_scene("pulley", cache)
    work_precision.for_scene("pulley", cache)
    assert calls == ["pulley"]
    # a new process (a new cache on the same disk) reads the report instead of computing it
    assert work_precision.for_scene("pulley", work_precision.report_cache(tmp_path)) == {"runs": []}
    assert calls == ["pulley"]


def test_display_rounding_keeps_seven_significant_digits():
    import numpy as np

    x = np.array([0.0, -1.23456789e-12, 3.14159265358979, 98765.4321987, -7.0e15 / 3.0, np.nan, np.inf])
    r = rounding.display_rounded(x)
    expected = [0.0, -1.234568e-12, 3.141593, 98765.43, -2.333333e15]
    assert r[:5].tolist() == expected and [repr(v) for v in r[:5].tolist()] == [repr(v) for v in expected]
    assert np.isnan(r[5]) and r[6] == np.inf


def test_display_rounding_prints_as_seven_digits_at_every_scale():
    import numpy as np

    rng = np.random.default_rng(7)
    magnitudes = 10.0 ** rng.uniform(-250, 250, 20000)
    x = rng.choice([-1.0, 1.0], magnitudes.size) * magnitudes
    decades = 10.0 ** np.arange(-250.0, 251.0)  # the edges of the exponent's two candidates, and their neighbours
    x = np.concatenate([x, decades, np.nextafter(decades, 0.0), np.nextafter(decades, np.inf), [0.5, 1.0, 9.9999999]])
    r = rounding.display_rounded(x)
    # where 10^|s| is not exact (|s| > 22) the last bit may differ from the literal's
    assert np.allclose(r, [float(f"{v:.7g}") for v in x], rtol=4e-16, atol=0.0)
    exact = (np.abs(x) >= 1e-16) & (np.abs(x) < 1e22)
    assert exact.sum() > 1000 and r[exact].tolist() == [float(f"{v:.7g}") for v in x[exact]]


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "spherical-pendulum"])
def test_while_kernels_compile_scipy_answers_and_says_so(scene_id):
    """The server's state before its background thread has compiled anything: nothing is ready."""
    import numpy as np

    nothing_compiled = simulation.Gates(answer_while_compiling=True, compiled=lambda method, system: False)
    fallback = scene_run(scene_id, request(t_end=3.0), nothing_compiled)
    server = simulation.Gates(answer_while_compiling=True)  # the same server once compiled (what jit has loaded)
    stats = fallback["stats"]
    assert stats["path"] == "scipy-fallback" and stats["method"] == "DOP853"
    assert "still being compiled" in stats["reason"] and stats["error_reference"].startswith("DOP853 at")
    compiled = scene_run(scene_id, request(t_end=3.0), server)
    assert compiled["stats"]["path"] == "compiled"
    # the same motion within the two runs' error estimates
    bound = stats["error_estimate"] + compiled["stats"]["error_estimate"]
    for q in SCENES_COORDINATES[scene_id]:
        assert np.max(np.abs(np.asarray(fallback["state"][q]) - compiled["state"][q])) <= 2 * bound + 1e-12


SCENES_COORDINATES = {"simple-pendulum": ["theta"], "spherical-pendulum": ["theta", "phi"]}


def test_scripts_without_a_server_compile_in_line():
    assert simulation.Gates().answer_while_compiling is False  # a script's gates
    script = simulation.Gates(compiled=lambda method, system: False)  # not compiled yet: a script waits for it
    doc = scene_run("simple-pendulum", request(t_end=1.0), script)
    assert doc["stats"]["path"] == "compiled"


def test_reference_run_beside_the_run_gives_the_same_estimate(monkeypatch):
    from app.service.runtime import cores

    started = []
    original = cores.CORES.submit

    def spy(work):
        future = original(work)
        started.append(future is not None)
        return future

    monkeypatch.setattr(cores.CORES, "submit", spy)
    monkeypatch.setattr(cores.CORES, "load", lambda: 0.0)
    monkeypatch.setattr(cores.CORES, "count", 2)
    beside = scene_run("spherical-pendulum", request(t_end=3.0))
    monkeypatch.setattr(cores.CORES, "count", 1)  # no free core: the reference runs after
    after = scene_run("spherical-pendulum", request(t_end=3.0))
    assert started == [True, False]
    assert beside["stats"]["error_estimate"] == after["stats"]["error_estimate"]
    assert beside["stats"]["error_reference"] == after["stats"]["error_reference"]


@pytest.mark.parametrize(("load", "busy", "free"), [(0.0, 0, True), (1.2, 0, True), (1.6, 0, False), (0.0, 2, False)])
def test_a_reference_runs_beside_only_while_half_a_core_is_idle(load, busy, free):
    from app.service.runtime.cores import Cores

    cores = Cores(2, load=lambda: load)
    cores.busy = busy
    assert cores.take() is free
    assert cores.take(force=True) and cores.busy == busy + 1 + free  # a run's own core is always taken


@pytest.mark.parametrize("scene_id", ["double-pendulum", "incline-block"])  # the block's run ends at an event
@pytest.mark.parametrize("precision", ["full", "display"])
def test_series_made_while_the_reference_runs_are_those_of_the_final_trajectory(monkeypatch, scene_id, precision):
    original = simulation.run_served
    calls = []

    def after(*args, alongside=None, **kwargs):  # the document computes them itself
        return original(*args, **kwargs)

    def spy(*args, alongside=None, **kwargs):
        def observe(trajectory):
            calls.append(trajectory.t.size)
            return alongside(trajectory)

        return original(*args, alongside=observe, **kwargs)

    monkeypatch.setattr(simulation, "run_served", spy)
    beside = json.loads(dumps(scene_run(scene_id, request(precision=precision))))
    monkeypatch.setattr(simulation, "run_served", after)
    later = json.loads(dumps(scene_run(scene_id, request(precision=precision))))
    assert calls == [len(beside["t"])]
    for key in ("t", "energy", "hamiltonian", "conserved", "constraint_forces", "state"):
        assert beside[key] == later[key], key
    drop = {"wall_time_s", "compile_time_s"}
    assert {k: v for k, v in beside["stats"].items() if k not in drop} == {
        k: v for k, v in later["stats"].items() if k not in drop
    }


def test_auto_choosing_the_compiled_radau_does_not_wait_for_the_python_loop_slot():
    """The throttle looks at the planned method: auto resolving to the compiled Radau IIA (a stiff start)
    steps in numba, so it runs while another scipy run holds the one Python-loop slot; scipy's Radau asked
    for by name is refused as busy meanwhile."""
    from app.engine.derivation.derive import derive
    from app.errors import OverCapacity
    from app.numerics.methods import STIFF
    from tests.numerics.extreme_cases import circular_radius
    from tests.numerics.systems import STIFF_SPRING

    d = derive(STIFF_SPRING)
    initial = {"r": circular_radius(1e6, 1.0, 1.0), "theta_dot": 1.0}
    quiet = request(initial=initial, t_end=1.0, rtol=1e-6, atol=1e-8)
    # (a script's gates compile in line: a server still compiling would answer from scipy's Radau)
    gates = simulation.Gates(wall_seconds=2.0)
    assert gates.python.acquire(timeout=1.0)  # another scipy run is in progress
    try:
        doc = derivation_run(d, quiet, gates=gates)
        assert doc["stats"]["method"] == STIFF and doc["stats"]["path"] == "compiled"
        assert doc["stats"]["reason"].startswith("stiff")
        by_name = request(initial=initial, t_end=1.0, rtol=1e-6, atol=1e-8, method="Radau")
        with pytest.raises(OverCapacity, match="Python step loop"):
            derivation_run(d, by_name, gates=gates)
    finally:
        gates.python.release()


def test_auto_stiff_handover_takes_the_python_loop_slot_only_for_scipy(monkeypatch):
    """A run that meets stiffness on the way is redone with the compiled Radau IIA without the Python-loop
    slot; a server still compiling that kernel hands over to scipy's Radau, which asks for the slot then
    (without an estimate here, so that nothing else in the plan is a Python loop)."""
    from app.numerics import jit
    from app.numerics import plan as plan_module
    from app.numerics.methods import FALLBACK_STIFF, METHODS, NONSTIFF, STIFF
    from app.service.runtime.cores import Cores
    from app.service.simulations.simulation_run import run_served, steps_in_python
    from tests.numerics.extreme_cases import circular_radius, system_for

    s = system_for("stiff-spring")
    k = np.array([1.0, 1e6, 1.0])
    y0 = np.array([circular_radius(1e6, 1.0, 1.0) * (1 + 1e-9), 0.0, 0.0, 1.0])
    monkeypatch.setattr(plan_module, "choose", lambda system, analysis: (NONSTIFF, "forced for the test"))
    entered = []
    cores = Cores(1)

    @contextmanager
    def spy():
        entered.append(True)
        yield

    planned = plan_module.plan(s, k, y0, 10.0, 101, "auto", 1e-4, 1e-4, estimate=False)
    assert not steps_in_python(planned)
    outcome, _ = run_served(planned, limits.WALL_SECONDS, (), cores, throttle=spy)
    assert outcome.method == STIFF and "detected stiffness" in outcome.reason and entered == []
    serving = plan_module.plan(s, k, y0, 10.0, 101, "auto", 1e-4, 1e-4, estimate=False, wait_for_compile=False)
    ready = jit.ready
    monkeypatch.setattr(jit, "ready", lambda name: name != METHODS[STIFF].kernel_module and ready(name))
    outcome, _ = run_served(serving, limits.WALL_SECONDS, (), cores, throttle=spy)
    assert outcome.method == FALLBACK_STIFF and entered == [True]


def _same_document(a, b):
    """Two result documents equal in everything but the wall-clock times."""
    for doc in (a, b):
        doc["stats"].pop("wall_time_s")
        doc["stats"].pop("compile_time_s")
    assert a.keys() == b.keys() and a["stats"] == b["stats"]
    np.testing.assert_array_equal(a["t"], b["t"])
    for q in a["state"]:
        np.testing.assert_array_equal(a["state"][q], b["state"][q])


def test_the_apps_scene_runs_go_to_a_worker_of_their_own_never_to_the_users_pool(caplog):
    """The app's gates send a scipy method asked for by name to the scenes' worker process (warmed with
    every scene's system), off the web process's GIL: the users' pool, where derivations queue, is never
    started; the event that ends the block's run on its ramp crosses the process boundary, and the
    answer is the one in line."""
    from app.service.services import Services
    from app.settings import Settings

    services = Services.start(Settings(memory_budget_mb=4000, warm=False), PROCESS_SCENES)
    sent = []
    to_worker = services.gates.offload

    def spy(job, *args, timeout):
        sent.append(job.__name__)
        return to_worker(job, *args, timeout=timeout)

    services.gates.offload = spy
    try:
        services.warm().join()
        assert "could not be warmed" not in caplog.text
        asked = request(method="RK45", t_end=5.0)
        away = scene_run("incline-block", asked, services.gates)
        assert sent == ["run_scene_plan"] and to_worker.__self__ is services.scenes
        assert services.pool._pool is None  # noqa: SLF001 - the users' pool never started
    finally:
        services.stop()
    assert away["stats"]["event"] is not None and away["stats"]["method"] == "RK45"
    _same_document(away, scene_run("incline-block", asked))


def test_a_compiled_run_stays_in_the_web_process():
    def offload(job, *args, timeout):
        raise AssertionError("a compiled run was sent to a worker")

    doc = scene_run("simple-pendulum", request(t_end=2.0), simulation.Gates(offload=offload))
    assert doc["stats"]["path"] == "compiled"


def test_the_stiff_hand_over_is_run_elsewhere_as_a_stiff_plan(monkeypatch):
    """The plan a run hands over to scipy's Radau (a server still compiling the compiled one) travels
    (``portable``, pickled) and is rebuilt on the system; its outcome, pickled back, is what the run in
    line gives.  A hand-over to the compiled Radau IIA stays in line."""
    import pickle

    from app.numerics import jit
    from app.numerics import plan as plan_module
    from app.numerics.methods import FALLBACK_STIFF, METHODS, NONSTIFF, STIFF
    from app.numerics.plan import Plan
    from app.numerics.simulate import run
    from app.service.runtime.cores import Cores
    from app.service.simulations.simulation_run import run_served, steps_in_python
    from tests.numerics.extreme_cases import circular_radius, system_for

    s = system_for("stiff-spring")
    k = np.array([1.0, 1e6, 1.0])
    y0 = np.array([circular_radius(1e6, 1.0, 1.0) * (1 + 1e-9), 0.0, 0.0, 1.0])
    monkeypatch.setattr(plan_module, "choose", lambda system, analysis: (NONSTIFF, "forced for the test"))
    sent = []

    def elsewhere(handed, wall_seconds):
        sent.append(handed)
        rebuilt = Plan.rebuilt(s, pickle.loads(pickle.dumps(handed.portable())))
        return pickle.loads(pickle.dumps(run(rebuilt, wall_seconds)))

    cores = Cores(1)
    planned = plan_module.plan(s, k, y0, 10.0, 101, "auto", 1e-4, 1e-4)
    away, _ = run_served(planned, limits.WALL_SECONDS, (), cores, elsewhere=elsewhere)
    assert sent == [] and away.method == STIFF and away.path == "compiled"
    # a server still compiling the Radau kernel: the explicit run is compiled and stays, what it hands over goes
    ready = jit.ready
    monkeypatch.setattr(jit, "ready", lambda name: name != METHODS[STIFF].kernel_module and ready(name))
    planned = plan_module.plan(s, k, y0, 10.0, 101, "auto", 1e-4, 1e-4, estimate=False, wait_for_compile=False)
    assert planned.path == "compiled"  # Vern8 loaded by the run above
    (away, _), here = run_served(planned, limits.WALL_SECONDS, (), cores, elsewhere=elsewhere), run(planned)
    assert [p.name for p in sent] == [FALLBACK_STIFF] and sent[0].stiff and steps_in_python(sent[0])
    assert away.method == here.method == FALLBACK_STIFF and "detected stiffness" in away.reason
    assert away.reason == here.reason
    np.testing.assert_array_equal(away.trajectory.y, here.trajectory.y)


@pytest.mark.slow
@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_every_default_run_meets_its_own_tolerance(scene_id):
    """prof-f 22, 18: the double pendulum's default run missed its tolerance 450 times, the parabola's 1.7 times."""
    doc = scene_run(scene_id, request())
    assert not [w for w in doc["stats"]["warnings"] if "times the tolerance" in w], doc["stats"]["warnings"]
