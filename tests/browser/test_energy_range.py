"""The energies' line under the bars gives each range's ends to the figures that mean something against the range's
size (prof-n 11): the simple pendulum's least U, 0 at the bottom of the swing, passed between two samples."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'


def test_the_pendulums_least_potential_energy_reads_zero_not_the_nearest_samples(page):
    # "U from 1.391 × 10⁻⁵ to 4.51 J" before: the sample nearest the bottom, a few millionths of the range's size
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(DONE, state="attached")
    energies = page.inner_text(".energy-bars .ebar-range")
    print(energies)
    assert " U from ≈ 0 to " in energies and "10⁻" not in energies, energies
    assert page.console_errors == []
