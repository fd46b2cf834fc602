"""The default path's shortcuts around the kernel give the general path's numbers: the samples' times and
the spectrum of the start as numpy computes them, the kernel called with its right-hand side's address
as with the right-hand side itself."""

import importlib
import math

import numpy as np
import pytest

from app.numerics.choose import eigenvalues
from app.numerics.kernels.common import DONE, RUNNING
from app.numerics.simulate import sample_times
from tests.numerics.extreme_cases import system_for


@pytest.mark.parametrize("t_end", [329.5939, 50.0, 1e5, 1e-3, 1.0 / 3.0, 7.123456789])
@pytest.mark.parametrize("samples", [2, 3, 7, 1000, 1001, 20000])
def test_sample_times_are_linspaces_bits(t_end, samples):
    assert sample_times(t_end, samples).tobytes() == np.linspace(0.0, t_end, samples).tobytes()


def test_sample_times_at_random_are_linspaces_bits():
    rng = np.random.default_rng(3)
    for _ in range(500):
        t_end, samples = float(10 ** rng.uniform(-3, 5)), int(rng.integers(2, 20001))
        assert sample_times(t_end, samples).tobytes() == np.linspace(0.0, t_end, samples).tobytes()


@pytest.mark.parametrize("m", [2, 4, 6, 12])
def test_eigenvalues_are_numpys(m):
    rng = np.random.default_rng(m)
    for _ in range(200):
        J = rng.normal(size=(m, m)) * rng.uniform(0.1, 1e3)
        assert eigenvalues(J) == np.linalg.eigvals(J).astype(complex).tolist()
    # a real spectrum, and a defective one (a cyclic angle's doubled zero)
    for J in (np.diag([1.0, -2.0, 3.0, 0.5]), np.array([[0.0, 1.0], [0.0, 0.0]])):
        assert eigenvalues(J) == np.linalg.eigvals(J).astype(complex).tolist()


@pytest.mark.parametrize("bad", [math.inf, -math.inf, math.nan])
def test_eigenvalues_refuse_what_numpy_refuses(bad):
    J = np.array([[0.0, 1.0], [bad, 0.0]])
    with pytest.raises(np.linalg.LinAlgError):
        np.linalg.eigvals(J)
    with pytest.raises(np.linalg.LinAlgError):
        eigenvalues(J)


@pytest.mark.parametrize("kernel_name", ["vern8", "dop853"])
@pytest.mark.parametrize(
    ("key", "k", "y0", "t_end", "samples"),
    [
        ("simple-pendulum", [1.0, 9.81, 1.0], [2.5, 0.0], 30.0, 2),
        ("simple-pendulum", [1.0, 9.81, 1.0], [3.1, 0.0], 20.0, 1001),
        ("double-pendulum", [1.0, 1.0, 1.0, 1.0, 9.81], [1.0, 0.0, 0.0, 0.0], 20.0, 777),
    ],
)
def test_the_kernel_by_address_is_the_kernel_by_bound(kernel_name, key, k, y0, t_end, samples):
    """``run_at`` (the right-hand side by its address, what the default path calls) fills the same samples
    and ends in the same state, bit for bit, as ``run`` with the ``Bound`` itself, chunk after chunk."""
    kernel = importlib.import_module(f"app.numerics.kernels.{kernel_name}")
    system = system_for(key)
    rhs = system.bound("rhs")
    k, y0 = np.array(k), np.array(y0)
    t = np.linspace(0.0, t_end, samples)
    atol, bound = np.full(y0.size, 1e-10), np.full(y0.size, 1e8)

    def chunks(call):
        y, fy, st, Y = y0.copy(), np.empty(y0.size), np.zeros(kernel.STATE_SIZE), np.full((samples, y0.size), np.nan)
        statuses = [call(k, t, 1e-8, atol, bound, 1, 40, y, fy, st, Y) for _ in range(200)]
        return Y.tobytes(), y.tobytes(), st.tobytes(), statuses

    general = chunks(lambda *args: kernel.run(rhs, *args))
    fast = chunks(lambda *args: kernel.run_at(rhs.address, *args))
    assert general[3].count(RUNNING) >= 3 and general[3][-1] == DONE
    assert fast == general
