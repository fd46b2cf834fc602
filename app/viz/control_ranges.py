"""Slider ranges and marks for a page's controls, computed from the derivation document.

A parameter's allowed range (what the API accepts) is often far wider than what is useful to
drag through: the slider covers a useful range inside it (a decade or so about the default,
widened to hold the marks), on a log scale when that range spans decades, while the number
field still takes any allowed value.  Marks sit at values where the motion changes kind, found
numerically from the engine's expressions at the default parameters:

* critical damping of a drag Q = −c q̇ about a stable equilibrium: c = 2 M ω (M the mass-matrix
  entry there, ω² the engine's normal-mode ω²);
* a parameter at which an equilibrium of the reduction changes stability (its ω² changes sign),
  such as the rotating wire's ω² = 2 g α;
* for the initial rate of a one-coordinate system with an unstable equilibrium, the rate whose
  conserved energy function h just reaches its value there (the separatrix):
  q̇₀ = ±√(2 (U_eff(q_top) − U_eff(q₀)) / M(q₀)), U_eff = h at rest (= U where no constraint moves).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from app.engine.display.names import unicode
from app.engine.document.model import Document, NormalModesAt, Root
from app.engine.document.trees import Tree, TreeError, of_text
from app.viz.exprtree import Expression, document_tree, evaluate, leaves
from app.viz.units import coordinate_units

DECADE = 10.0  # the useful range reaches this factor either side of a positive default
LOG_SPAN = 50.0  # a useful range wider than this factor moves on a log scale
SCAN = 240  # points of the scan for a change of stability


def formula(pair: Root) -> str:
    """A document expression as a label's text: the engine's running-text form (app/engine/report.Printer.text),
    its factors in the order of the LaTeX beside it (2gα − ω², as 2 g α − ω² reads)."""
    return pair.unicode


def _env(doc: Document, **extra: float) -> dict[str, float]:
    env = {k: float(v.default) for k, v in doc.parameters.items()}
    env.update(t=0.0, **{q: 0.0 for q in doc.coordinates}, **{f"{q}_dot": 0.0 for q in doc.coordinates})
    env.update(extra)
    return env


def _names(doc: Document) -> list[str]:
    q = doc.coordinates
    return [*q, *(f"{c}_dot" for c in q), *doc.parameters, "t"]


def _value(pair: Expression | None, doc: Document, env: dict[str, float]) -> float | None:
    """A document expression's value at ``env`` (None when it has no tree or no finite value there)."""
    node = document_tree(pair, _names(doc))
    if node is None:
        return None
    try:
        v = evaluate(node, env)
    except (ArithmeticError, ValueError, TypeError):
        return None
    return v if math.isfinite(v) else None


def _stable_modes(doc: Document) -> list[NormalModesAt]:
    return [e for e in doc.normal_modes if e.kind == "stable" and e.modes]


def drag_coefficient(tree: Tree | None, q: str) -> str | None:
    """c when the tree is the drag −c q̇ (c a single name), else None."""
    if not (isinstance(tree, list) and len(tree) == 2 and tree[0] == "neg"):
        return None
    product = tree[1]
    if not (isinstance(product, list) and len(product) == 3 and product[0] == "*"):
        return None
    factors = product[1:]
    rate = f"{q}_dot"
    if rate not in factors:
        return None
    (c,) = [f for f in factors if f != rate] or [None]
    return c if isinstance(c, str) else None


def damping_marks(doc: Document) -> dict[str, list[dict[str, Any]]]:
    """Critical damping of each drag force Q_q = −c q̇ whose c is a single parameter."""
    marks: dict[str, list[dict[str, Any]]] = {}
    stable = _stable_modes(doc)
    names = doc.coordinates
    for q, force in doc.generalized_forces.items():
        c = drag_coefficient(document_tree(force), q)
        if c is None or c not in doc.parameters or not stable:
            continue
        e = stable[0]
        k = names.index(q)
        env = _env(doc, **{c: float(v) for c, v in e.equilibrium.items()})
        mass = _value(doc.mass_matrix[k][k], doc, env)
        w2 = e.modes[0].omega_squared if len(e.modes) == 1 else None
        if mass and w2 and w2 > 0:
            value = 2 * mass * math.sqrt(w2)
            # critical for the equation linearised about the equilibrium: the full pendulum has no sharp threshold
            marks.setdefault(c, []).append({"value": value, "label": "critical damping of the linearised motion"})
    return marks


def stability_marks(doc: Document, ranges: dict[str, tuple[float, float]]) -> dict[str, list[dict[str, Any]]]:
    """Parameter values at which an equilibrium of the reduction changes stability (its ω² changes sign)."""
    red = doc.effective_potential
    marks: dict[str, list[dict[str, Any]]] = {}
    if red is None:
        return marks
    coordinate = red.coordinate
    for e in red.equilibria:
        w2_pair, where = e.omega_squared, e.position
        if not w2_pair.sympy:
            continue
        tree = document_tree(w2_pair)
        for p, (lo, hi) in ranges.items():
            if tree is None or p not in leaves(tree):
                continue  # omega^2 does not depend on this parameter
            grid = _grid(lo, hi)
            signs = [_value(w2_pair, doc, _env(doc, **{p: x})) for x in grid]
            for a, b, fa, fb in zip(grid, grid[1:], signs, signs[1:], strict=False):
                if fa is not None and fb is not None and fa * fb < 0:
                    value = _bisect(lambda x, p=p, w=w2_pair: _value(w, doc, _env(doc, **{p: x})) or 0.0, a, b)
                    label = f"{formula(w2_pair)} = 0: {unicode(coordinate)} = {formula(where)} changes stability"
                    marks.setdefault(p, []).append({"value": value, "label": label})
    return marks


START = "{start}"  # where a separatrix label names the starting value (filled here, and by static/js/separatrix.js)


def separatrix_spec(doc: Document) -> dict[str, Any] | None:
    """What fixes the separatrix marks of a one-coordinate system's initial rate, as trees the browser can evaluate
    again when the start or a parameter changes (static/js/separatrix.js); None where nothing is conserved.

    The level that parts the motions is one of the conserved quantity, the energy function h = Σ q̇ ∂L/∂q̇ − L,
    which is E = T + U only when no constraint moves; at rest h is U_eff = −L|_{q̇=0}, so
    h = ½ M(q) q̇² + U_eff(q).  Where h is not conserved (L depends on t, or a force does work) there is no level
    to reach, and no mark."""
    if len(doc.coordinates) != 1 or not doc.hamiltonian_conserved or doc.generalized_forces:
        return None
    q = doc.coordinates[0]
    h, mass = document_tree(doc.hamiltonian, _names(doc)), document_tree(doc.mass_matrix[0][0], _names(doc))
    red = doc.effective_potential
    if h is None or mass is None or red is None or red.coordinate != q:
        return None
    unit = coordinate_units(doc, scene=True)["units"].get(q, "")
    # the rate depends on where the run starts: the mark says which start it is for, and by which quantity
    # which quantity, where it is not E: h ≠ E on a moving constraint; with L alone E is not defined (None)
    equal = doc.hamiltonian_equals_energy
    by = "" if equal else (", by h (conserved here, not E)" if equal is False else ", by h (conserved here)")
    tops = []
    for e in red.equilibria:
        position, w2 = document_tree(e.position, _names(doc)), document_tree(e.omega_squared, _names(doc))
        if position is None or w2 is None:
            continue
        where = f"{unicode(q)} = {formula(e.position)}"
        label = f"separatrix from {unicode(q)}(0) = {START}{f' {unit}' if unit else ''}{by}: just reaches {where}"
        tops.append({"position": position, "omega_squared": w2, "label": label})
    return {"coordinate": q, "h": h, "mass": mass, "tops": tops} if tops else None


def separatrix_marks(
    doc: Document, initial: dict[str, float], parameters: dict[str, float] | None = None
) -> dict[str, list[dict[str, Any]]]:
    """The initial rates whose h just reaches an unstable equilibrium, for a one-coordinate system, from the
    start ``initial`` at the ``parameters`` (the defaults where not given)."""
    spec = separatrix_spec(doc)
    if spec is None:
        return {}
    q = spec["coordinate"]
    q0 = float(initial.get(q, 0.0))
    at = dict(parameters or {})
    try:
        start = _env(doc, **at, **{q: q0})
        # h at rest, U_eff(q₀), and the inertia M(q₀)
        h0, mass = evaluate(spec["h"], start), evaluate(spec["mass"], start)
    except (ArithmeticError, ValueError, TypeError):
        return {}
    marks = []
    for top in spec["tops"]:
        try:
            where = evaluate(top["position"], _env(doc, **at))
            w2 = evaluate(top["omega_squared"], _env(doc, **at))
            level = evaluate(spec["h"], _env(doc, **at, **{q: where}))
        except (ArithmeticError, ValueError, TypeError):
            continue  # arccos(g/(R w²)) where R w² < g: no such equilibrium at these parameters
        if not all(map(math.isfinite, (where, w2, level, h0, mass))) or w2 >= 0 or mass <= 0 or level <= h0:
            continue
        # h(q₀, q̇₀) = ½ M(q₀) q̇₀² + U_eff(q₀) = U_eff(q_top)
        rate = math.sqrt(2 * (level - h0) / mass)
        # h is that quadratic in q̇ only where M does not depend on q̇: checked, else no mark
        if not math.isclose(evaluate(spec["h"], {**start, f"{q}_dot": rate}), level, rel_tol=1e-9, abs_tol=1e-12):
            continue
        label = top["label"].replace(START, f"{q0:.4g}")
        marks += [{"value": rate, "label": label}, {"value": -rate, "label": label}]
    return {f"{q}_dot": marks} if marks else {}


def held_span(doc: Document, expression: str, q: str, value: float, lo: float, hi: float) -> tuple[float, float]:
    """The part of [lo, hi] about ``value`` where a set-up's event g (positive while the set-up holds: the bead
    still on its wire, g = R² − ρ²) is not negative, as a function of the coordinate ``q`` at the default
    parameters with every rate zero; [lo, hi] itself where g does not hold at ``value`` or has no tree."""
    try:
        node = of_text(expression)
    except TreeError:
        return lo, hi

    def g(x: float) -> float | None:
        try:
            v = evaluate(node, _env(doc, **{q: x}))
        except (ArithmeticError, ValueError, TypeError):
            return None
        return v if math.isfinite(v) else None

    at = g(value)
    if at is None or at < 0:
        return lo, hi
    grid = _grid(lo, hi)
    ends = []
    for side in (-1, 1):
        # from the value outward, the first grid point where g falls below zero: the end lies between it and
        # the point before, found by bisection
        inner = value
        for x in grid if side > 0 else grid[::-1]:
            if side * (x - value) <= 0:
                continue
            gx = g(x)
            if gx is not None and gx < 0:
                ends.append(_bisect(lambda y: g(y) or 0.0, inner, x))
                break
            inner = x
        else:
            ends.append(lo if side < 0 else hi)
    return ends[0], ends[1]


def _grid(lo: float, hi: float) -> list[float]:
    if lo > 0 and hi / lo > LOG_SPAN:
        return [lo * (hi / lo) ** (i / (SCAN - 1)) for i in range(SCAN)]
    return [lo + (hi - lo) * i / (SCAN - 1) for i in range(SCAN)]


def _bisect(f, a: float, b: float) -> float:
    fa = f(a)
    for _ in range(60):
        m = 0.5 * (a + b)
        fm = f(m)
        if (fm < 0) == (fa < 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


def useful_range(
    default: float, low: float, high: float, marks: Sequence[dict[str, Any]] = ()
) -> tuple[float, float, bool]:
    """(slider low, slider high, log scale) inside the allowed [low, high], holding the default and the marks."""
    values = [default, *(m["value"] for m in marks if m["value"] > 0)]
    if default > 0 and low >= 0:
        # a decade either side of the default, and room beyond the marks (three times the largest)
        lo = max(low, min(values) / DECADE)
        hi = min(high, max(default * DECADE, 3 * max(values)))
        return lo, hi, hi / lo >= LOG_SPAN
    return low, high, False


def ticks(doc: Document, initial: dict[str, float]) -> dict[str, list[dict[str, Any]]]:
    """Every mark for every control, by control name."""
    allowed = {
        p: (float(info.min), float(info.max))
        for p, info in doc.parameters.items()
        if info.min is not None and info.max is not None
    }
    marks = damping_marks(doc)
    for name, found in stability_marks(doc, allowed).items():
        marks.setdefault(name, []).extend(found)
    marks.update(separatrix_marks(doc, initial))
    return marks
