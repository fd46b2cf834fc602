"""The numerical search for equilibria: the one-coordinate scan's grid evaluated in one call."""

import numpy as np
import pytest
import sympy as sp

from app.engine.equilibria import roots
from app.engine.equilibria.equilibrium import function

q, k = sp.symbols("q k")


def _pointwise(g, grid):
    return np.array([float(g(np.array([x]))[0]) for x in grid])


def _scalar(expr):
    f = function([expr], [q, k])
    return lambda x: np.asarray(f(*x, 2.0), dtype=float).ravel()


@pytest.mark.slow
def test_the_grid_in_one_call_is_the_grid_point_by_point():
    grid = np.linspace(-np.pi - 0.05, np.pi + 0.05, roots.SCAN_POINTS)
    for expr in (
        k * sp.sin(q),
        sp.sin(q) * (1 + k * sp.cos(q)),
        sp.Abs(q) - k / 3,  # a kink, lambdified with NumPy's abs
        1 / (q - 1),  # a pole: inf and nan where the points fall on it
        sp.Piecewise((q, q < 0), (q**2, True)),
    ):
        g = _scalar(expr)
        # the same numbers, up to the last bit of a power NumPy takes on an array rather than on one number
        assert np.allclose(roots._on_grid(g, grid), _pointwise(g, grid), rtol=1e-15, atol=0, equal_nan=True), expr


def test_an_expression_free_of_the_coordinate_gives_one_value_per_point():
    grid = np.linspace(-1.0, 1.0, 11)
    g = _scalar(k + 0 * q)
    assert np.array_equal(roots._on_grid(g, grid), np.full(11, 2.0))


def test_the_scan_finds_what_it_found_point_by_point(monkeypatch):
    g = _scalar(k * sp.sin(q) * (1 + sp.cos(q) / 2))
    found = roots._scan_1d(g, -np.pi - 0.05, np.pi + 0.05)
    # the pendulum's two equilibria, π found twice (the search merges them)
    assert np.allclose(sorted(found), [-np.pi, 0.0, np.pi, np.pi], atol=1e-12)
    monkeypatch.setattr(roots, "_on_grid", _pointwise)
    assert roots._scan_1d(g, -np.pi - 0.05, np.pi + 0.05) == found


def test_a_root_where_brents_method_stalls_is_still_found():
    # 8 (q + 1)⁷, the push of a user's L = ẋ² + (x + ẋ + 1)⁸: about its sevenfold root g is below 10⁻²⁰ and
    # Brent's method could not meet its tolerance (a RuntimeError, and the system refused as a failure)
    g = _scalar(8 * (q + 1) ** 7)
    found = roots._scan_1d(g, -3.0, 3.0)
    assert found and all(abs(x + 1) < 0.05 for x in found), found
