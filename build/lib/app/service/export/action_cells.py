"""The notebook's cells on the action: S(ε) = ∫ L dt along the true path varied by ε sin(kπt/T).

They follow the simulation cells (which define ``rhs``, ``y0``, ``k_values``, ``t_end``, ``n`` and the
symbols) and use the notebook's own ``L``, so a student who changes L sees S change with it.
"""

from __future__ import annotations

from app.service.export.source import Source


def action_cells(source: Source, new_code_cell, new_markdown_cell) -> list:
    first = source.derivation.table.names[0]
    lines = [
        "from scipy.integrate import quad",
        "",
        "T_action = t_end / 10  # the paths run from 0 to T",
        "path = solve_ivp(rhs, (0.0, T_action), y0, method='DOP853', rtol=1e-12, atol=1e-13, dense_output=True)",
        "lagrangian = sp.lambdify((t, q, v, k), L, modules='math', dummify=True)",
        "",
        "",
        "def S(eps, shape=1, c=0):",
        '    """The action of the true path with coordinate c moved by eps * sin(shape * pi * t / T)."""',
        "    w = shape * np.pi / T_action",
        "",
        "    def integrand(ti):",
        "        y = path.sol(ti).copy()",
        "        y[c] += eps * np.sin(w * ti)",
        "        y[n + c] += eps * w * np.cos(w * ti)",
        "        return lagrangian(ti, y[:n], y[n:], k_values)",
        "",
        "    return quad(integrand, 0.0, T_action, epsabs=1e-12, epsrel=1e-10, limit=200)[0]",
        "",
        "",
        "S0 = S(0.0)",
        "print(f'S(0) = {S0:.12g}; dS/dε at 0 ≈ {(S(1e-4) - S(-1e-4)) / 2e-4:.2e}')",
        "for eps in np.linspace(-0.3, 0.3, 7):",
        "    print(f'ε = {eps:+.2f}: S(ε) − S(0) = {S(eps) - S0:+.6e}')",
    ]
    text = (
        "## The action",
        "Hamilton's principle: the true motion makes S = ∫ L dt stationary among paths with the same ends. "
        f"Here the true path on [0, T] (T = t_end / 10) is varied by ε sin(πt/T) in {first} and S is computed "
        "by quadrature for each ε: dS/dε vanishes at ε = 0 and S(ε) − S(0) grows like ε². Try `S(eps, shape=2)`, or a "
        "longer T: past the first kinetic focus S(ε) − S(0) for shape 1 turns negative, and the true path is a saddle "
        "of S.",
    )
    return [new_markdown_cell("\n".join(text)), new_code_cell("\n".join(lines))]
