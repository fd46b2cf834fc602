"""The energies' line under the bars gives each range to the figures that mean something (prof-n 11): an
extremum reached between two samples is known only to within the samples' spacing."""

from __future__ import annotations

DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'


def test_the_pendulums_least_potential_energy_reads_zero_not_the_nearest_samples(page):
    # prof-n 11: "U from 1.391 × 10⁻⁵ to 4.51 J": the bob passes the bottom (U = 0) between two samples
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(DONE, state="attached")
    energies = page.inner_text(".energy-bars .ebar-range")
    assert " U from ≈ 0 to " in energies and "10⁻" not in energies, energies
    # a parabola sampled every 0.1 s with its least value 0 at t = 0.37 s, between two samples: its least sample
    # (0.0009 at 0.4 s) is no measurement of the least value; its greatest, at the last sample, is the run's own
    line = page.evaluate(
        """async () => {
          const { overTheRun } = await import('/static/js/energybars.js');
          const t = Array.from({ length: 11 }, (_, i) => i / 10);
          return overTheRun([{ name: 'U', values: t.map((s) => (s - 0.37) ** 2) }], t, 1e-9);
        }"""
    )
    assert line == "Over the 1 s run: U from ≈ 0 to 0.3969 J.", line
    assert page.console_errors == []
