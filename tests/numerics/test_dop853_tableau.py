"""Our copy of DOP853's coefficients: the same doubles as scipy's, and the orders they promise."""

import numpy as np
import pytest

from app.numerics.kernels import dop853_tableau as tab
from tests.numerics.rk_trees import density, round_off, stage_weights, trees


@pytest.mark.parametrize("name", ["A", "B", "C", "E3", "E5", "D"])
def test_same_doubles_as_scipy(name):
    from scipy.integrate._ivp import dop853_coefficients as scipy_tab  # only here, to compare

    np.testing.assert_array_equal(getattr(tab, name), getattr(scipy_tab, name))
    assert (tab.N_STAGES, tab.N_EXTENDED) == (scipy_tab.N_STAGES, scipy_tab.N_STAGES_EXTENDED)


def test_eighth_order_conditions():
    """b . g(t) = 1 / gamma(t) on all 200 trees of at most 8 nodes, over the twelve stages of a step, and
    some tree of order 9 missed."""
    A, b = tab.A[: tab.N_STAGES, : tab.N_STAGES], tab.B
    for p in range(1, 9):
        for tree in trees(p):
            g = stage_weights(tree, A)
            # the coefficients are rounded doubles, and g(t) multiplies up to seven of them
            assert abs(b @ g - 1.0 / density(tree)) < round_off(b, g, 200), (p, tree)
    assert max(abs(b @ stage_weights(t, A) - 1.0 / density(t)) for t in trees(9)) > 1e-8


def test_kernel_imports_no_private_scipy_module():
    import ast
    from pathlib import Path

    from app.numerics.kernels import dop853

    imported = [
        node.module for node in ast.walk(ast.parse(Path(dop853.__file__).read_text())) if isinstance(node, ast.ImportFrom)
    ]
    assert not [m for m in imported if m and m.startswith("scipy")]
