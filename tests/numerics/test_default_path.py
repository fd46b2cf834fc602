"""The default path's shortcuts around the kernel give numpy's own numbers: the samples' times and the
spectrum of the start."""

import math

import numpy as np
import pytest

from app.numerics.choose import eigenvalues
from app.numerics.simulate import sample_times


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
