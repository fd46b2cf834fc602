"""The measured frequency of an oscillation from its upward zero crossings."""

import numpy as np
import pytest

from app.numerics.frequency import measured_omega


@pytest.mark.parametrize("omega", [0.7, 3.0, 41.0])
def test_a_cosine_is_measured_at_its_frequency(omega):
    t = np.linspace(0, 20 * 2 * np.pi / omega, 4001)
    assert measured_omega(t, 0.3 * np.cos(omega * t + 0.4)) == pytest.approx(omega, rel=1e-4)


def test_too_few_crossings_give_nothing():
    t = np.linspace(0, 1, 100)
    assert measured_omega(t, np.cos(2 * t)) is None  # less than one period
    assert measured_omega(t, np.ones_like(t)) is None
