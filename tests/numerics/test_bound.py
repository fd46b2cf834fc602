"""A compiled generated function called from Python through its C entry (raw addresses)."""

import numpy as np
import pytest

from tests.numerics.extreme_cases import system_for

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


def test_python_calls_write_what_the_python_twin_computes():
    s = system_for("double-pendulum")
    y, k = np.array([0.3, -0.2, 0.5, 0.1]), np.array([1.0, 1.3, 0.7, 1.1, 9.81])
    out = np.empty(4)
    s.bound("rhs")(0.0, y, k, out)
    twin = np.empty(4)
    s.python["rhs"](0.0, y.tolist(), k.tolist(), twin)
    np.testing.assert_allclose(out, twin, rtol=1e-13)


@pytest.mark.parametrize(
    "bad",
    [np.zeros(4, dtype=np.float32), np.zeros(8)[::2], np.zeros(4, dtype=np.int64)],
    ids=["float32", "strided", "integers"],
)
def test_arrays_a_raw_address_would_misread_are_refused(bad):
    s = system_for("double-pendulum")
    k = np.array([1.0, 1.3, 0.7, 1.1, 9.81])
    with pytest.raises(TypeError, match="contiguous float64"):
        s.bound("rhs")(0.0, bad, k, np.empty(4))
    with pytest.raises(TypeError, match="contiguous float64"):
        s.bound("rhs")(0.0, np.zeros(4), k, bad)
