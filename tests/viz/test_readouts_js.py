"""Readouts computed in the browser: turning points, number formats, axis formats (run with node)."""

import json
import math
import shutil
import subprocess
from pathlib import Path

import pytest

JS = Path(__file__).resolve().parents[2] / "static" / "js"

pytestmark = pytest.mark.skipif(shutil.which("node") is None, reason="node is installed with the front-end assets")


def node(module: str, body: str):
    script = f"import * as m from {json.dumps((JS / module).as_uri())}; console.log(JSON.stringify(({body})(m)));"
    run = subprocess.run(["node", "--input-type=module", "-e", script], capture_output=True, text=True, timeout=30)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


@pytest.mark.slow
def test_pendulum_turning_points_are_unique_and_bracket_the_motion():
    # released from rest at θ = 1: the level is U(1), the well is [−1, 1], and θ = 1 is both start and turning point
    pts = node(
        "reduction.js",
        "(m) => { const U = (x) => 1 - Math.cos(x), lvl = U(1); "
        "return [m.turningPoints((x) => U(x) - lvl, -1.6, 1.6, 1), m.turningPoints((x) => U(x) - lvl, -1.6, 1.6, 0.2)]; }",
    )
    for found in pts:
        assert len(found) == 2
        assert found[0] == pytest.approx(-1, abs=1e-9) and found[1] == pytest.approx(1, abs=1e-9)


def test_only_the_well_that_holds_the_motion():
    # a double well U = (x² − 4)²/16 with level 0.5: two wells; a particle at x = 2.3 turns inside the right one
    found = node(
        "reduction.js",
        "(m) => m.turningPoints((x) => (x * x - 4) ** 2 / 16 - 0.5, -4, 4, 2.3)",
    )
    inner, outer = math.sqrt(4 - math.sqrt(8)), math.sqrt(4 + math.sqrt(8))
    assert found == pytest.approx([inner, outer], abs=1e-9)


@pytest.mark.slow
def test_one_sided_and_none():
    one = node("reduction.js", "(m) => m.turningPoints((x) => x - 1, -4, 4, 0)")  # a slope: turns at x = 1 only
    assert one == pytest.approx([1], abs=1e-9)
    assert node("reduction.js", "(m) => m.turningPoints((x) => 1, -4, 4, 0)") == []  # outside every well


def test_every_axis_is_ticked_in_powers_of_ten_not_si_prefixes():
    out = node(
        "plotkit.js",
        "(m) => [m.axis('t (s)'), m.axis('error (rad)', { type: 'log' }), m.momentumUnit('rad'), m.momentumUnit('m')]",
    )
    for ax in out[:2]:
        assert ax["exponentformat"] == "power" and ax["showexponent"] == "all"
    assert out[1]["type"] == "log"
    assert out[2:] == ["kg·m²/s", "kg·m/s"]


def test_plots_build_every_axis_through_the_shared_helper():
    # no panel sets its own tick format (Plotly's default "B" format writes 1p for 10⁻¹²)
    for name in ("plots.js", "reduction.js"):
        text = (JS / name).read_text()
        assert "exponentformat" not in text, name


def test_constant_quantities_are_stated_as_constant():
    out = node(
        "summaries.js",
        "(m) => [m.constantOrRange([0.8774, 0.8774, 0.87740000001], 'N'), m.constantOrRange([1, 2, 3], 'N'),"
        " m.constantOrRange([4.85e-5, 3, 18.8], 'N'), m.constantOrRange([-2, -1e-6], 'N')]",
    )
    # a sampled minimum far below the maximum is a zero the samples straddle (issue 40: the helix's 4.85 × 10⁻⁵ N)
    assert out == ["is constant: 0.8774 N", "ranges from 1 to 3 N", "ranges from ≈ 0 to 18.8 N", "ranges from −2 to ≈ 0 N"]


def test_values_below_their_resolution_read_as_zero():
    out = node("summaries.js", "(m) => [m.fmtResolved(-2.107e-14, 1e-9), m.fmtResolved(0.25, 1e-9), m.fmt(-5e-7)]")
    assert out == ["≈ 0", "0.25", "−5 × 10⁻⁷"]


@pytest.mark.slow
def test_the_run_status_says_what_its_error_is_of_and_in_which_unit():
    # prof-e 3: "Simulated 10 s · error ≈ 10⁻⁸ · computed in 0.53 ms" named no quantity and no unit, and a run
    # time is no part of the physics
    out = node(
        "summaries.js",
        "(m) => [m.statusLine({ t_end_reached: 10, error_estimate: 4.19e-9, wall_time_s: 3.115e-4 }, 'rad'),"
        " m.statusLine({ t_end_reached: 3.21, error_estimate: 0.04, wall_time_s: 0.0123 }, ''),"
        " m.sharedUnit({ coordinates: ['x1', 'x2'], units: { x1: 'm', x2: 'm' } }),"
        " m.sharedUnit({ coordinates: ['X', 'theta'], units: { X: 'm', theta: 'rad' } }), m.magnitude(1)]",
    )
    assert out == [
        "Simulated 10 s · error in the coordinates ≈ 4 × 10⁻⁹ rad",
        "Simulated 3.2 s · error in the coordinates ≈ 0.04 (each in its unit)",
        "m",
        "",
        "1",
    ]


def test_the_run_time_shown_is_a_median():
    assert node("summaries.js", "(m) => [m.median([3, 1, 2]), m.median([4, 1, 2, 3]), m.median([])]") == [2, 2.5, None]


def test_a_number_shows_no_digit_finer_than_its_resolution_and_a_difference_three_figures():
    # prof-k 13: "−6.221 %" and θ = 2.48602: a relative difference reads to three figures, and a value known to
    # ±0.003 shows no digit below 0.001
    out = node(
        "summaries.js",
        "(m) => [m.percent(-0.062213), m.percent(-0.062213, 2e-5), m.percent(-0.062213, 3e-3), m.percent(4e-6, 1e-5),"
        " m.fmtResolved(2.486021, 0.003), m.fmtResolved(2.486021, 1e-9), m.fmt(2.486021), m.fmt(-1234567, 3)]",
    )
    assert out == ["−6.22 %", "−6.22 %", "−6.2 %", "≈ 0 %", "2.486", "2.486", "2.486", "−1.23 × 10⁶"]


@pytest.mark.slow
def test_a_box_value_that_prints_as_a_bound_is_that_bound():
    # prof-l 1: the angle slider at its end puts 3.142 in the box, which is past π; read as π, it is allowed
    found = node("controls.js", "(m) => [m.snapToBounds(3.142, -Math.PI, Math.PI), m.snapToBounds(-3.142, -Math.PI, "
                 "Math.PI), m.snapToBounds(3.15, -Math.PI, Math.PI), m.snapToBounds(1.5, -Math.PI, Math.PI)]")
    assert found == [math.pi, -math.pi, 3.15, 1.5]


@pytest.mark.slow
def test_a_ranges_ends_carry_only_the_figures_its_size_gives():
    # prof-n 11: "U from 1.391 × 10⁻⁵ to 4.51 J" on the simple pendulum, whose least U is 0, passed between samples.
    # A parabola sampled every 0.1 s with its zero at 0.31 s, between two samples: its least sample, 1.05 × 10⁻⁴, is a
    # thousandth of the span 0.4999 or less, so it reads ≈ 0; the greatest keeps its four digits
    out = node(
        "energybars.js",
        "(m) => { const t = Array.from({ length: 11 }, (_, i) => i / 10);"
        " return [m.overTheRun([{ name: 'U', values: t.map((s) => 1.05 * (s - 0.31) ** 2) }], t, 1e-9),"
        " m.overTheRun([{ name: 'U', values: t.map((s) => 1.05 * (s - 0.31) ** 2 - 0.2) }], t, 1e-9)]; }",
    )
    assert out[0] == "Over the 1 s run: U from ≈ 0 to 0.4999 J.", out
    # an end far from zero keeps its digits, however small its distance from the sample nearest it
    assert out[1] == "Over the 1 s run: U from −0.1999 to 0.2999 J.", out
    # one rule for a range's ends (summaries.js rangeEnds): both ends below a thousandth of the span read ≈ 0,
    # a resolution larger than that share wins, and an end above keeps the digits down to that share
    ends = node(
        "summaries.js",
        "(m) => [m.rangeEnds(1.391e-5, 4.51), m.rangeEnds(-2e-4, 4.51), m.rangeEnds(0.02, 4.51, 0.05),"
        " m.rangeEnds(1.0004, 1.0009)]",
    )
    assert ends == [["≈ 0", "4.51"], ["≈ 0", "4.51"], ["≈ 0", "4.51"], ["1", "1.001"]], ends
