"""A Jupyter notebook: the problem, each step in SymPy beside the engine's result, a simulation.

Each step is a markdown cell saying what it does, a code cell a student can
change and rerun, and a cell with the engine's own result and a check that the
two agree (at random points, so it is quick for any size).  The last cells
integrate the equations with scipy's ``solve_ivp`` and plot the motion and the
energy.  It needs ``pip install sympy scipy matplotlib`` and nothing of this project.
"""

from __future__ import annotations

# nbformat (with jsonschema, 0.1-0.2 s) is imported by the functions that write a notebook, not when
# the server starts.
import sympy as sp

from app.engine.display.forms import textbook_form
from app.engine.document import notation, report
from app.service.export.action_cells import action_cells
from app.service.export.code import (
    ACCELERATION_LINES,
    DT_LINES,
    EULER_LAGRANGE_LINES,
    Naming,
    event_lines,
    simulation_lines,
)
from app.service.export.source import Source
from app.service.export.text import markdown_text
from app.viz.names import label

SAMPLES = 1000

HELPER_LINES = [
    "import random",
    "",
    "import matplotlib.pyplot as plt",
    "import numpy as np",
    "import sympy as sp",
    "from IPython.display import Math, display",
    "from scipy.integrate import solve_ivp",
    "",
]

CHECK_LINES = [
    "",
    "",
    "def show(name, expr):",
    '    """Typeset name = expr with the dots of velocities and accelerations."""',
    "    display(Math(name + ' = ' + sp.latex(expr, symbol_names=LATEX)))",
    "",
    "",
    "def same(mine, engine, tries=4):",
    '    """True when the two agree at a few random points (a numeric check, quick for any size)."""',
    "    mine, engine = sp.Matrix([mine]), sp.Matrix([engine])",
    "    rng = random.Random(1)",
    "    symbols = sorted((mine.free_symbols | engine.free_symbols), key=str)",
    "    for _ in range(tries):",
    "        point = {s: sp.Float(rng.uniform(0.3, 1.7)) for s in symbols}",
    "        for x, y in zip(mine.xreplace(point).evalf(), engine.xreplace(point).evalf()):",
    "            if abs(complex(x) - complex(y)) > 1e-9 * (1 + abs(complex(y))):",
    "                return False",
    "    return True",
    "",
    "",
    "def show_engine(name, value):",
    '    """Typeset the result of the engine (each entry of a list)."""',
    "    for i, x in enumerate(value if isinstance(value, list) else [value]):",
    "        show(name + (f'_{{{i}}}' if isinstance(value, list) else '') + r'^{\\mathrm{engine}}', x)",
    "",
    "",
    "def check(name, mine, engine):",
    "    print(name + (': the same as the engine' if same(mine, engine) else ': DIFFERS from the engine'))",
]


def _code(*lines: str):
    from nbformat.v4 import new_code_cell

    return new_code_cell("\n".join(lines).strip("\n"))


def _md(*lines: str):
    from nbformat.v4 import new_markdown_cell

    return new_markdown_cell("\n".join(lines))


def notebook(source: Source) -> str:
    d = source.derivation
    m, eqs, en = d.mechanics, d.equations, d.energetics
    naming = Naming.of(d)
    table = d.table
    latex = {naming.renamed[s]: tex for s, tex in table.latex_names().items()}
    # the engine's results in the textbook forms the page shows (cos(θ₁ − θ₂), one quotient per acceleration)
    names = table.latex_names()

    def form(expr: sp.Expr) -> sp.Expr:
        return textbook_form(expr, names)

    latex_entries = ", ".join(f"{s.name}: {tex!r}" for s, tex in latex.items())
    cells = [_md(*_problem(source))]

    cells.append(
        _md("## Symbols", "Each coordinate, its velocity and acceleration, and each parameter is a real SymPy symbol.")
    )
    cells.append(
        _code(*HELPER_LINES, *naming.symbol_lines(), f"LATEX = {{{latex_entries}}}", "", "", *DT_LINES, *CHECK_LINES)
    )

    if m.positions or m.bodies:
        cells.append(
            _md(
                "## Positions, velocities and kinetic energy",
                "Each mass in Cartesian coordinates; its velocity is the total time derivative of its position, "
                "and T = Σ ½ m v²"
                + (
                    "; each rigid body adds ½ M v_cm² for its centre and ½ I_cm θ̇² for its turning about the "
                    "centre, θ̇ the time derivative of its turning angle."
                    if m.bodies
                    else "."
                ),
            )
        )
        lines = [f"masses = {naming.code_list(m.masses)}", "r = ["]
        lines += [f"    sp.Matrix({naming.code_list(r)})," for r in m.positions]
        lines += ["]", "velocities = [ri.applyfunc(dt) for ri in r]"]
        lines += ["T = sum(mi * vi.dot(vi) for mi, vi in zip(masses, velocities)) / 2"]
        if m.bodies:
            # (mass, centre, I_cm, turning angle) of each rigid body
            lines += ["bodies = ["]
            lines += [
                f"    ({naming.code(b.mass)}, sp.Matrix({naming.code_list(b.centre)}), {naming.code(b.inertia)}, "
                f"{naming.code(b.angle)}),"
                for b in m.bodies
            ]
            lines += [
                "]",
                "T += sum(Mb * rb.applyfunc(dt).dot(rb.applyfunc(dt)) / 2 + Ib * dt(ab) ** 2 / 2 "
                "for Mb, rb, Ib, ab in bodies)",
            ]
        lines += [f"U = {naming.code(m.U)}", "show('T', T)", "show('U', U)"]
        cells.append(_code(*lines))
    elif m.T is not None:
        cells.append(_md("## Kinetic and potential energy", "T and U as declared."))
        cells.append(_code(f"T = {naming.code(m.T)}", f"U = {naming.code(m.U)}", "show('T', T)", "show('U', U)"))
    if m.T is not None:
        cells.append(_engine("T", naming.code(form(m.T)), "T"))
        cells.append(_md("## Lagrangian", "L = T − U."))
        cells.append(_code("L = T - U", "show('L', L)"))
    else:
        cells.append(_md("## Lagrangian", "L as declared."))
        cells.append(_code(f"L = {naming.code(m.L)}", "show('L', L)"))
    cells.append(_engine("L", naming.code(form(m.L)), "L"))

    cells.append(
        _md(
            "## Euler–Lagrange equations",
            "Q holds the generalized forces that no potential describes; each equation "
            "d/dt ∂L/∂q̇ − ∂L/∂q − Q = 0 holds along the motion.",
        )
    )
    cells.append(
        _code(
            f"Q = {naming.code_list(m.Q)}",
            *EULER_LAGRANGE_LINES,
            "for k_, e in enumerate(EL):",
            "    show(f'EL_{k_}', e)",
        )
    )
    cells.append(_engine("EL", naming.code_list(map(form, eqs.residuals)), "EL"))

    # the page's letter for the mass matrix (ℳ: a body's mass may be M), the code's variable M
    mass = notation.text("mass_matrix", d)
    cells.append(
        _md(
            "## Accelerations",
            f"The equations are linear in the accelerations: {mass} q̈ = f, with {mass} the mass matrix (M in the "
            "code) and f the rest of each equation taken to the right. Solving it gives the accelerations.",
        )
    )
    cells.append(
        _code(*ACCELERATION_LINES, "for ak, x in zip(a, acc):", "    show(sp.latex(ak, symbol_names=LATEX), x)")
    )
    cells.append(_engine("accelerations", naming.code_list(map(form, eqs.accelerations)), "acc"))

    cells.append(_md("## Generalized momenta", "p = ∂L/∂q̇ for each coordinate."))
    # each momentum named after its coordinate, as on the page: p_θ₁ (not after the velocity)
    cells.append(_code("for qk, pk in zip(q, p):", "    show('p_{' + sp.latex(qk, symbol_names=LATEX) + '}', pk)"))
    # grouped by velocity as the page prints them ((M + m)Ẋ + mḊ cos α): one rule (report.momentum), so that a
    # notebook made in a worker and one made in this process print the same momenta
    cells.append(_engine("momenta", naming.code_list(report.momentum(d, k) for k in range(len(eqs.momenta))), "p"))

    energy_lines = ["h = sum(pk * vk for pk, vk in zip(p, v)) - L", "show('h', h)"]
    if m.T is not None:
        energy_lines += ["E = T + U", "show('E', E)"]
    cells.append(_md("## Energy function and energy", "h = Σ p q̇ − L" + (", and E = T + U." if m.T is not None else ".")))
    cells.append(_code(*energy_lines))
    cells.append(_engine("h", naming.code(form(en.hamiltonian)), "h"))
    if m.T is not None:
        cells.append(_engine("E", naming.code(form(en.energy)), "E"))
    cells.append(_md(*_conserved(source)))

    cells += _simulation(source, naming, "E" if m.T is not None else "h")
    cells += action_cells(source, _code, _md)  # S(ε) (app/service/export/action_cells.py)
    import nbformat
    from nbformat.v4 import new_notebook

    for i, cell in enumerate(cells):
        cell.id = f"cell-{i}"  # fixed ids: the same derivation always gives the same file
    book = new_notebook(
        cells=cells,
        metadata={
            "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
            "language_info": {"name": "python"},
        },
    )
    nbformat.validate(book)
    return nbformat.writes(book)


def _engine(name: str, code: str, mine: str):
    """A cell with the engine's result, typeset and compared with the student's."""
    lines = [
        f"{mine}_engine = {code}",
        f"show_engine({mine!r}, {mine}_engine)",
        f"check({name!r}, {mine}, {mine}_engine)",
    ]
    return _code(*lines)


def _problem(source: Source) -> list[str]:
    lines = [f"# {markdown_text(source.title)}"]
    if source.section:
        lines.append(f"*Section {markdown_text(source.section)} of the chapter, exported by Lagrange.*")
    lines += ["", markdown_text(source.statement)]
    if source.figure:
        lines += ["", markdown_text(source.figure)]
    if source.parameters:
        lines += ["", "| parameter | meaning | value | unit |", "|---|---|---|---|"]
        for p in source.parameters:
            lines.append(
                f"| {markdown_text(label(p.name))} | {markdown_text(p.description)} | {p.default!r} | {markdown_text(p.unit)} |"
            )
    names = [*source.derivation.table.names, *(f"{q}_dot" for q in source.derivation.table.names)]
    start = ", ".join(f"{markdown_text(label(n))} = {x!r}" for n, x in zip(names, source.initial, strict=True))
    lines += ["", f"The simulation starts from {start} and runs to t = {source.t_end!r} s."]
    lines += [
        "",
        "Run the cells from the top. Change a cell (a position, a potential, a parameter) and run the cells below it "
        "again: each step is checked against what the engine derived.",
    ]
    return lines


def _conserved(source: Source) -> list[str]:
    doc = source.document
    lines = ["### What is conserved"]
    for c in doc.conserved:
        lines.append(f"- ${c.latex_name} = {c.latex}$: {markdown_text(c.reason)}")
    if not doc.conserved:
        lines.append("Nothing: no coordinate is cyclic and h changes (forces or an explicit time dependence).")
    lines += ["", f"**h and E.** {markdown_text(doc.hamiltonian_energy_reason)}"]
    return lines


def _simulation(source: Source, naming: Naming, energy: str) -> list:
    names = [*source.derivation.table.names]
    labels = [label(n) for n in names]
    plot = [
        f"t_samples = np.linspace(0.0, t_end, {SAMPLES})",
        "sol = solve_ivp(rhs, (0.0, t_end), y0, method='DOP853', rtol=1e-10, atol=1e-12, t_eval=t_samples, events=events)",
        "print(sol.message)",
        f"energy = sp.lambdify((t, q, v, k), {energy}, modules='math', dummify=True)",
        f"n = {naming.n}",
        "E_t = np.array([energy(ti, yi[:n], yi[n:], k_values) for ti, yi in zip(sol.t, sol.y.T)])",
        "",
        "fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))",
        f"for i, name in enumerate({labels!r}):",
        "    top.plot(sol.t, sol.y[i], label=name)",
        "top.set_ylabel('coordinates')",
        "top.legend()",
        f"bottom.plot(sol.t, E_t - E_t[0], label={energy + '(t) − ' + energy + '(0)'!r})",
        "bottom.set_xlabel('t (s)')",
        f"bottom.set_ylabel('change of {energy}')",
        "bottom.legend()",
        "plt.show()",
        "print('end state:', dict(zip(" + repr([*names, *(f"{q}_dot" for q in names)]) + ", sol.y[:, -1].tolist())))",
    ]
    return [
        _md(
            "## Simulation",
            "The accelerations above, integrated with scipy's DOP853 (rtol 1e-10, atol 1e-12) from the start "
            "given in the problem; then the coordinates and the change of "
            + ("the energy E" if energy == "E" else "the energy function h")
            + " against time.",
        ),
        _code(
            *simulation_lines(naming, [p.default for p in source.parameters], source.initial, source.t_end),
            *event_lines(naming, source.derivation, source.events),
        ),
        _code(*plot),
    ]
