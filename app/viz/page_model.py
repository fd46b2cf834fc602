"""Everything a scene page shows, built once per scene from the derivation JSON.

``scene_page(doc, scene, particles, methods)`` returns a plain dict: the
steps (long ones flagged for collapsing), the summary box, the controls with
units and ranges, the panels to draw, the diagram, and ``client`` -- the
compact data the browser modules need (expression trees, not code).
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping, Sequence
from typing import Any

from app.engine.derivation.dimensions import kind_of_unit
from app.engine.display.names import MASS_MATRIX, latex, prose, unicode
from app.engine.document import notation
from app.engine.document.model import Document, EffectivePotential, FirstStage, ParameterInfo
from app.engine.document.notation import printed
from app.engine.document.report import CORE_STEPS
from app.engine.document.trees import TreeError, maybe_of_text, of_text
from app.limits import DEFAULT_T_END
from app.numerics import limits
from app.numerics.methods import LABELS
from app.viz.control_ranges import held_span, separatrix_spec, ticks, useful_range
from app.viz.diagrams import diagram
from app.viz.exprtree import Expression, document_tree, leaves
from app.viz.mechanism import mechanism
from app.viz.names import label
from app.viz.panels import Facts, folded, oscillating_equilibria, shown, texts
from app.viz.units import coordinate_units, rate_unit

LONG_STEP = 160  # characters a reader sees (not LaTeX's) beyond which a step's math starts collapsed
LONG_ROWS = 6  # lines of a display beyond which it starts collapsed, however short each line
SLIDER_STEPS = 1000  # positions of a control's slider (the page's range inputs; static/js/controls.js reads them)
# the page's menu of tolerances, written as powers of ten (1e-8)
RTOLS = tuple(f"1e{round(math.log10(r))}" for r in limits.RTOL_MENU)
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def power_of_ten(value: str) -> str:
    """A tolerance as a reader writes it: 1e-8 → 10⁻⁸ (the menu's value stays 1e-8)."""
    return "10" + value.partition("e")[2].translate(_SUPERSCRIPT)


DEFAULT_RTOL = f"1e{round(math.log10(limits.RTOL_DEFAULT))}"


def _names(doc: Document, extra: Sequence[str] = ()) -> list[str]:
    q = doc.coordinates
    return [*q, *(f"{c}_dot" for c in q), *doc.parameters, "t", *extra]


def _pair_tree(pair: Expression | None, names: Sequence[str]) -> Any:
    return document_tree(pair, names)


# LaTeX that prints nothing a reader counts: sizing, environments, spacing and the bracing of groups
_SILENT = re.compile(
    r"\\(?:left|right|begin\{\w+\}|end\{\w+\}|mathrm|text|quad|qquad|tfrac|frac|dfrac|[,;:! ])|[{}&\s^_]"
)


def shown_length(tex: str) -> tuple[int, int]:
    """How long a display is as a reader sees it: its lines, and its characters (a command such as
    ``\\omega`` one character, markup none)."""
    # a matrix's rows (a mode's column of amplitudes too) are one line
    rows = re.sub(r"\\begin\{([pbv]?matrix)\}.*?\\end\{\1\}", "", tex).count("\\\\") + 1
    return rows, len(_SILENT.sub("", re.sub(r"\\[A-Za-z]+", "x", _SILENT.sub("", tex))))


def _steps(doc: Document) -> list[dict[str, Any]]:
    out = []
    for i, s in enumerate(doc.steps):
        rows, chars = shown_length(s.latex)
        out.append(
            {
                "number": i + 1,
                "title": s.title,
                "latex": s.latex,
                "explanation": s.explanation,
                # folded only when long as read (two short lines never hide behind a button); a core step (L, the
                # equations, the accelerations) is never folded: long ones are broken across lines
                "long": (chars > LONG_STEP or rows > LONG_ROWS) and s.key not in CORE_STEPS,
                "rows": rows,
                "core": s.key in CORE_STEPS,
            }
        )
    return out


def letter_of(doc: Document | FirstStage, meaning: str, default: str, form: str = "latex") -> str:
    """The document's letter for a derived quantity (``form`` "latex" or "unicode"), from its Symbols table
    (app/engine/document/notation.py)."""
    return next(
        (getattr(r, form) for r in doc.notation or () if r.kind == "derived" and r.meaning.startswith(meaning)),
        default,
    )


def depends_on_time(doc: Document) -> bool:
    """Whether L depends explicitly on time (∂L/∂t ≠ 0): then h changes along a run and has no level sets to follow."""
    return doc.explicit_time_derivative.sympy != "0"


def nothing_conserved(doc: Document) -> str:
    """Why nothing is conserved, naming only the causes this system has: L depends on time, a force does work."""
    causes = []
    if depends_on_time(doc):
        causes.append("L depends explicitly on time (∂L/∂t ≠ 0)")
    if doc.generalized_forces:
        on = ", ".join(unicode(q) for q in doc.generalized_forces)
        causes.append(f"a generalized force that no potential describes acts on {on} and does work")
    if not causes:
        return "Nothing is conserved here: no coordinate is cyclic and no symmetry of L was found."
    return f"Nothing is conserved here: {' and '.join(causes)}, so h changes, and no momentum stays constant."


def _answers(doc: Document) -> list[dict[str, Any]]:
    """The steps that answer the scene's question (``Scene.answers``, by key as the reasons go: ``normal-modes``
    is every ``normal-modes:N``), for the Results box; an explanation already given above is not repeated."""
    keys = doc.scene.answers if doc.scene else []
    said: set[str] = set()
    out = []
    for s in doc.steps:
        if any(s.key == k or s.key.startswith(k + ":") for k in keys):
            out.append(
                {
                    "title": s.title,
                    "latex": s.latex,
                    "explanation": "" if s.explanation in said else s.explanation,
                }
            )
            said.add(s.explanation)
    return out


def _summary(doc: Document) -> dict[str, Any]:
    q = doc.coordinates
    conserved = [{"latex": f"{c.latex_name or c.name} = {c.latex}", "reason": c.reason} for c in doc.conserved]
    ddot = {c: latex(f"{c}_ddot") for c in q}
    return {
        # what the statement asks, stated first (never only behind "Show all steps")
        "answers": _answers(doc),
        "equations": [e.latex for e in doc.equations_of_motion],
        # none in closed form for a large system (listed in "skipped"): M⁻¹f
        # the coordinates' accelerations, then those of the positions they fix (the pulley's middle mass, Ÿ)
        "accelerations": [f"{ddot[c]} = {doc.accelerations[c].latex}" for c in q]
        + [f"{latex(n + '_ddot')} = {e.latex}" for n, e in doc.dependent_accelerations.items()]
        if doc.accelerations
        else [rf"\ddot{{q}} = {letter_of(doc, 'mass matrix', MASS_MATRIX[0])}^{{-1}} f"],
        "momenta": [f"{latex('p_' + c)} = {doc.momenta[c].latex}" for c in q],
        # members of the document left out within their own bounds, each with its reason
        "skipped": [s.reason for s in doc.skipped],
        "conserved": conserved,
        "nothing_conserved": nothing_conserved(doc),
        "h_equals_e": doc.hamiltonian_equals_energy,
        "h_reason": doc.hamiltonian_energy_reason,
        "h_conserved": doc.hamiltonian_conserved,
        "h_conserved_reason": doc.hamiltonian_conserved_reason,
        "hamiltonian": "h = " + doc.hamiltonian.latex,
        "energy_minus_h": doc.energy_minus_hamiltonian.latex,
        "effective_potential": (
            {
                **doc.effective_potential.model_dump(),
                "coordinate_latex": latex(doc.effective_potential.coordinate) + " = ",
                "root_latex": latex(doc.effective_potential.coordinate) + "_0",
                "frequency_latex": letter_of(doc, "angular frequency", r"\omega"),
                # the inertia's letter as the steps print it: I_eff for an angle, m_eff for a length
                "inertia_latex": _inertia(doc.effective_potential, "latex"),
            }
            if doc.effective_potential
            else None
        ),
        # each force with its letter, F₁ = …, as the Symbols table defines it (app/engine/document/notation.py)
        "constraint_forces": [
            {**c.model_dump(), "symbol": notation.force(k)[0], "latex": f"{notation.force(k)[0]} = {c.latex}"}
            for k, c in enumerate(doc.constraint_forces, start=1)
        ],
        # every letter of the page once, with what it stands for
        "symbols": [n.model_dump() for n in doc.notation],
    }


def _transformed(doc: Document) -> list[dict[str, Any]] | None:
    """The derivation in other coordinates (the rail's centre of mass and separation), as labelled rows of LaTeX."""
    tr = doc.transformed
    if not tr:
        return None
    q = tr.coordinates
    sym = {c: latex(c) for c in q}
    rows: list[dict[str, Any]] = []

    def add(title: str, items: list[str]) -> None:
        if items:
            rows.append({"title": title, "latex": items})

    add("New coordinates", [f"{sym.get(c, c)} = {e.latex}" for c, e in tr.definitions.items()])
    add("Old coordinates in the new", [f"{latex(c)} = {e.latex}" for c, e in tr.inverse.items()])
    add("Lagrangian", [f"L = {tr.lagrangian.latex}"])
    add("Cyclic coordinates", [", ".join(sym.get(c, c) for c in tr.cyclic)] if tr.cyclic else [])
    if tr.reduced_mass is not None:
        add("Reduced mass", [rf"\mu = {tr.reduced_mass.latex}"])
    if rel := tr.relative_motion:
        # the separation moves as one body of the reduced mass: what the rail's problem asks to show
        add("Relative motion", [rel.equation, rel.frequency])
    add("Accelerations", [rf"\ddot{{{sym.get(c, c)}}} = {e.latex}" for c, e in tr.accelerations.items()])
    add("Momenta", [f"p_{{{sym.get(c, c)}}} = {e.latex}" for c, e in tr.momenta.items()])
    conserved = []
    for c in tr.conserved:
        text = f"{c.latex_name or c.name} = {c.latex}"
        if c.name.startswith("p_"):
            text += f" = {c.original.latex}"  # the same momentum in the old coordinates
        conserved.append(text)
    add("Conserved", conserved)
    return rows


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _round_reach(default: float) -> float:
    """10^(n + 1) for the smallest power of ten 10^n at or above |default| (at least 10)."""
    return 10.0 ** (max(0, math.ceil(math.log10(abs(default)))) + 1) if default else 10.0


# a lowest value this close above 0 stands for "more than 0" (a mass, a length: JUST_ABOVE_ZERO of the form)
ABOVE_ZERO = 1e-6


def allowed_text(lo: float, hi: float, unit: str) -> str:
    """The allowed range as a reader writes it: "more than 0, up to 10 kg", "−100 to 100 rad/s", numbers with a
    true minus sign and no exponent notation, the unit typeset (m/s², not m/s^2)."""
    shown = unit_text(unit)
    tail = f" {shown}" if shown else ""
    if 0 < lo <= ABOVE_ZERO:
        return f"more than 0, up to {_plain(hi)}{tail}"
    return f"{_plain(lo)} to {_plain(hi)}{tail}"


def control_hint(lo: float, hi: float, slider_lo: float, slider_hi: float, unit: str) -> str:
    """What a control's hint says: the allowed range, or, where the slider spans less than may be typed (a
    stiffness from 0.01 to 100,000,000 N/m), the slider's physical range and the wider one typing allows."""
    if slider_lo <= lo and slider_hi >= hi:
        return f"allowed: {allowed_text(lo, hi, unit)}"
    typed = allowed_text(lo, hi, unit)
    typed = typed if typed.startswith("more than") else f"from {typed}"
    return f"slider: {allowed_text(slider_lo, slider_hi, unit)}; type any value {typed}"


def _plain(x: float) -> str:
    # whole thousands with separators (10,000), smaller numbers to four figures (0.01, 2.5)
    text = f"{x:,.0f}" if abs(x) >= 1000 else f"{x:.4g}"
    return text.replace("-", "−")


def unit_text(unit: str) -> str:
    """A unit as printed: powers as superscripts (m/s^2 → m/s², kg*m^2 → kg·m²), a reciprocal as a negative power
    (1/m → m⁻¹, 1/s → s⁻¹)."""
    reciprocal = re.fullmatch(r"1/([A-Za-z]+)", unit.strip())
    if reciprocal:
        return reciprocal.group(1) + "⁻¹"
    return re.sub(
        r"\^(-?\d)", lambda m: m.group(1).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")), unit
    ).replace("*", "·")


_SUPERSCRIPTS_BACK = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def unit_latex(unit: str) -> str:
    """A unit as LaTeX after a value, upright and as printed (unit_text): "m/s²" → \\,\\mathrm{m/s^{2}}."""
    printed = re.sub(
        r"[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+", lambda m: "^{" + m.group(0).translate(_SUPERSCRIPTS_BACK) + "}", unit_text(unit)
    )
    return r"\,\mathrm{" + printed.replace("·", r"\,") + "}"


def angles(doc: Document) -> set[str]:
    """Coordinates that are angles, as the derivation document records them."""
    return set(doc.angles)


def _polar(doc: Document, q: str) -> bool:
    """Whether the angle ``q`` is a polar angle: sin²q multiplies another coordinate's entry of the mass
    matrix (m R² sin²θ for φ), so q = 0 and q = π are the poles of the coordinates."""
    rows = doc.mass_matrix
    return any(f"sin({q})**2" in rows[k][k].sympy for k, c in enumerate(doc.coordinates) if c != q and k < len(rows))


def _initial_controls(
    doc: Document,
    initial: dict[str, float],
    nonnegative: Sequence[str],
    angular: set[str],
    marks: dict[str, list[dict[str, Any]]] | None = None,
    units: dict[str, str] | None = None,
    events: Sequence[Mapping[str, Any]] = (),
) -> list[dict]:
    marks = marks or {}
    units = units or {}
    # a set-up that ends where a coordinate falls below zero (the block at the foot of its ramp) starts
    # only where it holds: that coordinate's slider begins at 0
    held = {e["expression"].strip() for e in events}
    lengths = [p.default for p in doc.parameters.values() if p.unit == "m" and p.default > 0]
    scale = max([1.0, *lengths])
    controls = []
    for q in doc.coordinates:
        angle = q in angular or units.get(q) == "rad"
        value, rate = float(initial.get(q, 0.0)), float(initial.get(f"{q}_dot", 0.0))
        if angle:
            # a polar angle (sin² of it scales another coordinate's inertia, as θ does φ's on a sphere) runs
            # from pole to pole, [0, π]; any other angle goes once round, (−π, π]
            lo, hi = (0.0 if _polar(doc, q) else -math.pi), math.pi
            lo, hi = min(lo, value), max(hi, value)
        else:
            size = 3 * max(scale, abs(value))
            lo, hi = (0.0 if q in nonnegative or q in held else -size), size
            # any other end of the set-up (the bead at an end of its finite wire, ρ² = R²) bounds the slider too
            for e in events:
                if e["expression"].strip() != q:
                    lo, hi = held_span(doc, e["expression"], q, value, lo, hi)
        found = marks.get(f"{q}_dot", [])
        reach = max([abs(m["value"]) for m in found], default=0.0)
        vmax = max(10.0, 3 * abs(rate), 1.5 * reach) if angle else max(5.0, 3 * abs(rate), math.sqrt(9.81 * scale))
        unit = units.get(q, "rad" if angle else "m")
        rates = rate_unit(unit)
        controls.append(
            {"name": q, "label": f"{label(q)}(0)", "latex": latex(q), "unit": unit,
             "min": _fmt(lo), "max": _fmt(hi), "value": _fmt(value), "log": False,
             "allowed": allowed_text(float(lo), float(hi), unit),
             "description": f"initial {'angle' if angle else 'position'} {label(q)}"}
        )  # fmt: skip
        controls.append(
            {"name": f"{q}_dot", "label": f"{label(q + '_dot')}(0)", "latex": latex(f"{q}_dot"),
             "unit": rates, "min": _fmt(-vmax), "max": _fmt(vmax), "value": _fmt(rate), "log": False,
             "allowed": allowed_text(-vmax, vmax, rates), "ticks": _marks(found, rates),
             "description": f"initial rate of change of {label(q)}"}
        )  # fmt: skip
    return controls


def _marks(found: Sequence[dict[str, Any]], unit: str) -> list[dict[str, Any]]:
    """Marks for a slider, each with a line of text; a pair ±v with the same meaning is said once."""
    out = []
    for m in found:
        value = m["value"]
        twin = any(o is not m and o["label"] == m["label"] and math.isclose(o["value"], -value) for o in found)
        size = f"±{abs(value):.4g}" if twin else f"{value:.4g}".replace("-", "−")
        text = "" if twin and value < 0 else f"{size} {unit_text(unit)} ({m['label']})".replace("  ", " ")
        out.append({"value": _fmt(value), "label": m["label"], "text": text})
    return out


def _described(info: ParameterInfo) -> str:
    """What a parameter without a description is, by its unit (so that a label never repeats the name: "m m")."""
    return info.description or kind_of_unit(info.unit) or "a parameter"


def _open_range(default: float, info: ParameterInfo) -> tuple[float, float]:
    """The range of a parameter whose declaration leaves it open: an angle between 0 and π/2 (a cone's half-angle,
    an incline's slope) stays in that quarter turn, another angle within a half turn either way; any other
    quantity ± a round power of ten (_round_reach)."""
    if info.unit.strip() == "rad":
        if 0 < default <= math.pi / 2:
            return ABOVE_ZERO / 1000, math.pi / 2
        return -math.pi, math.pi
    reach = _round_reach(default)
    return -reach, reach


def _parameter_controls(doc: Document, marks: dict[str, list[dict[str, Any]]]) -> list[dict[str, Any]]:
    controls = []
    for name, info in doc.parameters.items():
        default = float(info.default)
        # a bound the declaration leaves open is a round one, ± a power of ten at least ten times the default
        # (a mass of 1 kg: up to 10 kg; g = 9.81 m/s²: up to 100), never the default plus ten
        lo_open, hi_open = _open_range(default, info)
        lo = info.min if info.min is not None else lo_open
        hi = info.max if info.max is not None else hi_open
        found = [m for m in marks.get(name, []) if lo <= m["value"] <= hi]
        slider_lo, slider_hi, log = useful_range(default, float(lo), float(hi), found)
        unit = info.unit
        controls.append(
            {"name": name, "label": label(name), "latex": latex(name), "unit": unit,
             "min": _fmt(lo), "max": _fmt(hi), "value": _fmt(default), "log": log,
             "slider_min": _fmt(slider_lo), "slider_max": _fmt(slider_hi), "ticks": _marks(found, unit),
             "description": _described(info), "allowed": allowed_text(float(lo), float(hi), unit),
             "hint": control_hint(float(lo), float(hi), slider_lo, slider_hi, unit)}
        )  # fmt: skip
    return controls


def _inertia(red: EffectivePotential, form: str) -> str:
    """The reduced coordinate's inertia letter (``form`` "latex" or "unicode") as the document names it
    (app/engine/notation.inertia)."""
    return str(getattr(red.inertia, form))


def _reduction(doc: Document) -> dict[str, Any] | None:
    red = doc.effective_potential
    if not red:
        return None
    momenta = list(red.momenta)
    names = _names(doc, momenta)
    coordinate_of = {m: m[2:] for m in momenta if m.startswith("p_")}
    out = {
        "coordinate": red.coordinate,
        "momenta": [
            {
                "symbol": m,
                "coordinate": coordinate_of.get(m),
                "tree": _pair_tree(doc.momenta.get(coordinate_of.get(m, "")), names),
            }
            for m in momenta
        ],
        "potential": _pair_tree(red.potential, names),
        "mass": _pair_tree(red.mass, names),
        # the inertia's letter as the document prints it (I_eff for an angle, m_eff for a length: app/engine/document/notation.py)
        "inertia": _inertia(red, "unicode"),
        "condition": _pair_tree(red.condition, names),
        "omega_squared": _pair_tree(red.omega_squared, names),
        "equilibria": [
            {
                "position": _pair_tree(e.position, names),
                "omega_squared": _pair_tree(e.omega_squared, names),
                "stable": e.stable,
            }
            for e in red.equilibria
        ],  # fmt: skip
    }
    essential = [out["potential"], out["mass"], *(m["tree"] for m in out["momenta"])]
    return out if all(x is not None for x in essential) else None


def _separatrix(doc: Document, rate_units: dict[str, str]) -> dict[str, Any] | None:
    """control_ranges.separatrix_spec with the unit its note prints the rates in (static/js/separatrix.js)."""
    spec = separatrix_spec(doc)
    if spec is None:
        return None
    return {**spec, "unit": unit_text(rate_units.get(spec["coordinate"]) or rate_unit(""))}


def _focus_possible(doc: Document) -> bool:
    """The engine's verdict (app/engine/document/action_step.py); a document from before it counts as "possible"."""
    return doc.kinetic_focus_possible


def _client(doc, info, reduction, spec, methods, nonnegative, angular, scene: bool = True) -> dict[str, Any]:
    names = _names(doc)
    # rad for an angle, m where the dimensions say so, nothing where they cannot tell (app/viz/units.py)
    known = coordinate_units(doc, scene)
    units = known["units"]
    conserved = [{"name": c.name, "label": label(c.name), "tree": document_tree(c, names)} for c in doc.conserved]
    return {
        "id": doc.id,
        "coordinates": doc.coordinates,
        "labels": {n: label(n) for n in [*names, *(c.name for c in doc.conserved)] if n != "t"},
        "units": units,
        # the letter of a small-oscillation frequency on this page (Ω where ω is the parabola's turning rate)
        "frequency_letter": letter_of(doc, "angular frequency", "ω", "unicode"),
        "rate_units": known["rate_units"],
        "momentum_units": known["momentum_units"],
        "nonnegative": list(nonnegative),
        "parameters": {k: v.default for k, v in doc.parameters.items()},
        "parameter_units": {k: v.unit for k, v in doc.parameters.items()},
        "initial": info.get("initial", {}),
        "t_end": info.get("t_end", DEFAULT_T_END),
        "panels": info["panels"],
        # a frequency exact at every amplitude (the tabletop's radial motion), said in its own words
        "exact_frequency": info.get("exact_frequency", ""),
        "trees": {
            "kinetic": _pair_tree(doc.kinetic, names),
            "potential": _pair_tree(doc.potential, names),
            "hamiltonian": _pair_tree(doc.hamiltonian, names),
            "energy": _pair_tree(doc.energy, names),
            "momenta": {q: _pair_tree(doc.momenta[q], names) for q in doc.coordinates},
        },
        "cyclic": doc.cyclic,
        "conserved": conserved,
        "nothing_conserved": nothing_conserved(doc),
        "h_equals_e": doc.hamiltonian_equals_energy,
        "forced": bool(doc.generalized_forces),
        "time_dependent": depends_on_time(doc),
        # whether a true path can reach a kinetic focus (the action panel says none exists where it cannot)
        "kinetic_focus_possible": _focus_possible(doc),
        # each generalized force Q that no potential describes, by coordinate (the action panel's ∫ Q δq dt)
        "forces": {q: _pair_tree(pair, names) for q, pair in doc.generalized_forces.items()},
        "reduction": reduction,
        # what the initial rate's separatrix marks are worked out from, again in the browser as the start changes
        "separatrix": _separatrix(doc, known["rate_units"]),
        "constraint_forces": [
            {
                "name": c.name,
                "label": label(c.name),
                "convention": c.convention,
                "slack_when_negative": c.slack_when_negative,
            }
            for c in doc.constraint_forces
        ],  # fmt: skip
        "mechanism": spec,
        # where the set-up ends (the browser's preview stops there too, as the server's run does)
        "events": [
            {"name": e["name"], "message": e["message"], "tree": maybe_of_text(e["expression"], names)}
            for e in info.get("events", [])
        ],
        "methods": list(methods),
        "method_labels": {m: LABELS.get(m, m) for m in (*methods, *LABELS)},
        # equilibria at rest with an oscillating mode (numbers at the default parameters), for the modes panel
        "normal_modes": [e.model_dump() for e in oscillating_equilibria(doc)],
    }


def _panels(declared: Sequence[str], doc: Document, reduction, spec, scene: bool) -> tuple[list[str], list[str]]:
    """The panels this page shows (app/viz/panels.py): every available one, optional ones where declared; and
    those of them that sit closed under "details" (the method comparison where the method does not matter)."""
    facts = Facts(doc, reduction, spec["dim"] if spec is not None else None, scene)
    names = shown(facts, declared)
    return names, folded(facts, names)


def moves_in_3d(particles: Sequence[tuple[str, Sequence[str]]], coordinates: Sequence[str]) -> bool:
    """Some body moves along each of the three axes (so the mechanism is drawn in space)."""
    moving = set(coordinates) | {"t"}

    def moves(text: str) -> bool:
        try:
            return bool(leaves(of_text(text)) & moving)
        except TreeError:
            return False

    return all(any(moves(pos[i]) for _, pos in particles) for i in range(3))


# the summary's members that are lists of LaTeX (elsewhere a "latex" or "…_latex" key marks it)
_SUMMARY_LATEX = ("equations", "accelerations", "momenta", "hamiltonian", "energy_minus_h")


def _strings(value: Any, tex: bool = False) -> list[tuple[bool, str]]:
    """Every string in a piece of the page model, each with whether it is LaTeX (else running text or a figure)."""
    if isinstance(value, str):
        return [(tex, value)]
    if isinstance(value, Mapping):
        return [s for k, v in value.items() for s in _strings(v, tex or k == "latex" or str(k).endswith("_latex"))]
    if isinstance(value, (list, tuple)):
        return [s for v in value for s in _strings(v, tex)]
    return []


def page_symbols(model: dict[str, Any]) -> list[dict[str, Any]]:
    """The Symbols table of a page: the document's letters that the page prints somewhere else, in its statement,
    steps, results, shown panels, figures or controls (app/engine/notation.printed)."""
    shown = {k: v for k, v in model.items() if k not in ("client_json", "summary", "panel_text")}
    summary = {k: v for k, v in model["summary"].items() if k not in ("symbols", *_SUMMARY_LATEX)}
    red = summary.get("effective_potential")
    if red:
        # its letters print only beside an equilibrium ("Equilibrium at r = … with ω² = …")
        summary["effective_potential"] = {**red, "frequency_latex": red["frequency_latex"] if red["equilibria"] else ""}
    panels = [model["panel_text"].get(name, {}) for name in model["panels"]]
    listed = [model["summary"].get(k) for k in _SUMMARY_LATEX]
    found = [*_strings([shown, summary, panels]), *_strings(listed, True)]
    # a figure's words without its markup (an SVG's <text x="…"> is not the letter x)
    words = [re.sub(r"<[^>]*>", " ", s) for tex, s in found if not tex]
    return printed(model["summary"]["symbols"], [s for tex, s in found if tex], words)


def scene_page(
    doc: Document,
    info: dict[str, Any],
    particles: Sequence[tuple[str, Sequence[str]]] = (),
    methods: Sequence[str] = ("auto",),
    nonnegative: Sequence[str] = (),
    scene: bool = True,
) -> dict[str, Any]:
    """The page model of one scene; ``info`` holds title, section, summary, statement, figure, panels, initial, t_end.

    ``info["panels"]`` are the optional panels asked for; ``scene`` is False for a user's system.
    """
    declared = list(info.get("panels", ()))
    reduction = _reduction(doc)
    defaults = {k: v.default for k, v in doc.parameters.items()}
    spec = mechanism(
        info.get("family", ""),
        particles,
        doc.coordinates,
        moves_in_3d(particles, doc.coordinates),
        forces=doc.constraint_forces,
        defaults=defaults,
        proven=doc.fixed_distances,
        potential=document_tree(doc.potential),
    )
    panels, closed = _panels(declared, doc, reduction, spec, scene)
    # symbol names in the scene's prose as a reader writes them (m₁, x₂)
    info = {**info, "panels": panels, **{k: prose(info[k]) for k in ("statement", "figure", "summary") if info.get(k)}}
    angular = angles(doc)
    marks = ticks(doc, info.get("initial", {}))
    client = _client(doc, info, reduction, spec, methods, nonnegative, angular, scene)
    model: dict[str, Any] = {
        "info": info,
        "declared_panels": declared,
        "panels": panels,
        "folded_panels": closed,
        "panel_text": texts(
            bool(doc.generalized_forces),
            angles=bool(doc.angles),
            focus=_focus_possible(doc),
            several=len(doc.coordinates) > 1,
        ),
        "diagram": diagram(
            info.get("family", ""),
            f"Set-up: {info.get('title', '')}",
            info.get("figure", ""),
            defaults,
            info.get("initial", {}),
            doc.coordinates,
            particles,
            marks=info.get("marks", ()),
        ),  # fmt: skip
        # what the animation draws, in words (the set-up's figure text stays with the diagram)
        "animation_caption": spec["caption"] if spec else "",
        "animation_forces": bool(spec and spec.get("forces")),
        "animation_none": bool(spec and spec.get("none")),
        "steps": _steps(doc),
        "summary": _summary(doc),
        "errata": [{**e.model_dump(), "reason": prose(e.reason)} for e in doc.errata],
        "transformed": _transformed(doc),
        "parameters": _parameter_controls(doc, marks),
        "initial": _initial_controls(
            doc,
            info.get("initial", {}),
            nonnegative,
            angular,
            marks,
            coordinate_units(doc, scene)["units"],
            info.get("events", ()),
        ),
        "t_end": {
            "value": _fmt(info.get("t_end", DEFAULT_T_END)),
            "min": "0.5",
            "max": _fmt(max(60.0, 10 * info.get("t_end", DEFAULT_T_END))),
        },
        "methods": [{"value": m, "label": LABELS.get(m, m)} for m in methods],
        "rtols": [{"value": r, "label": power_of_ten(r)} for r in RTOLS],
        "default_rtol": DEFAULT_RTOL,
        "client_json": json.dumps(client, separators=(",", ":")).replace("<", "\\u003c"),
    }
    model["summary"]["symbols"] = page_symbols(model)
    return model
