"""Write an explicit pair's stages as straight-line numba code, the tableau's nonzero entries as literals.

A loop over a compressed tableau reads each coefficient and column index from memory and cannot be
unrolled by the compiler; written out, each stage is one loop over the components with its few
constants in the instructions.  The output is an ordinary module in the repository (cached by numba on
disk like any other, and readable); tests/numerics/test_unroll.py checks that it matches the tableau.

    .venv/bin/python -m app.numerics.kernels.unroll     (rewrites app/numerics/kernels/vern8_stages.py)

Generated for a tableau module with A, C, B, E, N_STEP and N_ALL (row N_STEP is f(t + h, y_new)):

* ``stages(f, k, t, h, y, K, ys, ks)``: K_s = f(t + c_s h, y + h sum_j a_sj K_j) for s = 1 .. N_STEP - 1,
  into the rows of K; each f writes into ks, copied into its row while the next stage's state is summed;
  ys is left holding the last stage's state and ks its slope.
* ``combine(h, y, K, ks, y_new, atol, rtol)``: the last slope into its row, y_new = y + h sum_j b_j K_j,
  and the error sum, sum_i (h^-1 err_i / (atol_i + rtol max(|y_i|, |y_new_i|)))^2 with
  err_i = sum_j e_j K_ji (the caller multiplies by h and takes the root mean).
* ``extra(f, k, t, h, y, K, ys, ks)``: the stages N_STEP + 1 .. N_ALL - 1 of the interpolant.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

import numpy as np

from app.numerics.kernels import vern8_tableau

TARGET = Path(__file__).with_name("vern8_stages.py")


def _literal(x: float) -> str:
    return repr(float(x))


def _sum(weights: np.ndarray, row_of: dict[int, str]) -> str:
    """'w_0 * K[0, i] + w_5 * K[5, i] + ...' over the nonzero weights (a row given in ``row_of`` by another name)."""
    terms = []
    for j in np.flatnonzero(weights):
        slope = row_of.get(int(j), f"K[{j}, i]")
        terms.append(f"{_literal(weights[j])} * {slope}")
    return " + ".join(terms) if terms else "0.0"


def _stage_block(tab: ModuleType, s: int, previous: int | None) -> list[str]:
    """The loop that stores the previous stage's slope (from ks) and sums stage s's state, then the call."""
    row_of = {previous: "ks[i]"} if previous is not None else {}
    lines = [f"    # stage {s}: c = {_literal(tab.C[s])}", "    for i in range(n):"]
    if previous is not None:
        lines.append(f"        K[{previous}, i] = ks[i]")
    lines.append(f"        ys[i] = y[i] + h * ({_sum(tab.A[s], row_of)})")
    lines.append(f"    f(t + {_literal(tab.C[s])} * h, address(ys), address(k), address(ks))")
    return lines


def source(tab: ModuleType = vern8_tableau) -> str:
    head = [
        f'"""{tab.__name__.rsplit(".", 1)[-1]} written out by app.numerics.kernels.unroll: do not edit, re-run it."""',
        "",
        "from numba import njit",
        "",
        "from app.numerics.kernels.common import address",
        "",
        "",
        '@njit(inline="always")',
        "def stages(f, k, t, h, y, K, ys, ks):",
        "    n = y.size",
    ]
    body = []
    for s in range(1, tab.N_STEP):
        body += _stage_block(tab, s, s - 1 if s > 1 else None)
    last = tab.N_STEP - 1
    combine = [
        "",
        "",
        '@njit(inline="always")',
        "def combine(h, y, K, ks, y_new, atol, rtol):",
        "    n = y.size",
        "    err = 0.0",
        "    for i in range(n):",
        f"        K[{last}, i] = ks[i]",
        f"        y_new[i] = y[i] + h * ({_sum(tab.B, {})})",
        f"        e = {_sum(tab.E, {})}",
        "        scale = atol[i] + max(abs(y[i]), abs(y_new[i])) * rtol",
        "        err += (e / scale) ** 2",
        "    return err",
    ]
    extra = ["", "", '@njit(inline="always")', "def extra(f, k, t, h, y, K, ys, ks):", "    n = y.size"]
    for s in range(tab.N_STEP + 1, tab.N_ALL):
        extra += _stage_block(tab, s, s - 1 if s > tab.N_STEP + 1 else None)
    extra += ["    for i in range(n):", f"        K[{tab.N_ALL - 1}, i] = ks[i]"]
    return "\n".join(head + body + combine + extra) + "\n"


def main() -> None:
    TARGET.write_text(source())
    print(f"wrote {TARGET}")


if __name__ == "__main__":
    main()
