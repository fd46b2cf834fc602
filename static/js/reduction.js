/**
 * reduction.js — panels of the one-coordinate reduction (the derivation's effective_potential).
 *
 *   new EffectivePotentialPanel(section, data)   U_eff over the run's range, the energy level
 *                                                (E_r at the cursor), turning points, the current point
 *   new SmallOscillationsPanel(section, data)    ω from the engine's ω² = U_eff''/m_eff (I_eff) at the nearest
 *                                                stable equilibrium, beside ω measured from the run
 *   reduced(run), equilibrium(run, red), measuredOmega(t, values)   the numbers behind them
 *
 * Every expression comes from the engine as a tree (expr.js); the momenta of the cyclic
 * coordinates take their values from the initial state.
 */
import { compile } from "./expr.js";
import { axis, COLORS, finite, layout, PreviewPanel, react, titled } from "./plotkit.js";
import { fmt, percent, table } from "./summaries.js";

/** The one-coordinate reduction evaluated for a run: U_eff, m_eff, the momenta's values, E_r(t). */
export function reduced(run) {
  const red = run.data.reduction;
  const env0 = run.envAt(0);
  const P = {};
  for (const m of red.momenta) P[m.symbol] = compile(m.tree)(env0);
  const U = compile(red.potential), M = compile(red.mass);
  const r = red.coordinate;
  const at = (x) => ({ ...run.params, ...P, [r]: x, t: 0 });
  const Er = Array.from({ length: run.n }, (_, i) => {
    const e = { ...run.envAt(i), ...P };
    return 0.5 * M(e) * e[`${r}_dot`] ** 2 + U(e);
  });
  // the inertia's letter as the page prints it: I_eff where r is an angle, m_eff where a length
  return { r, P, U: (x) => U(at(x)), at, Er, values: run.state[r], inertia: red.inertia };
}

function bisect(f, a, b) {
  let fa = f(a);
  for (let k = 0; k < 60; k++) {
    const m = (a + b) / 2, fm = f(m);
    if (Math.sign(fm) === Math.sign(fa)) { a = m; fa = fm; } else b = m;
  }
  return (a + b) / 2;
}

function roots(f, lo, hi, n = 400) {
  const out = [];
  let x0 = lo, f0 = f(lo);
  for (let k = 1; k <= n; k++) {
    const x1 = lo + ((hi - lo) * k) / n, f1 = f(x1);
    if (Number.isFinite(f0) && Number.isFinite(f1) && Math.sign(f0) !== Math.sign(f1)) out.push(bisect(f, x0, x1));
    x0 = x1; f0 = f1;
  }
  return out;
}

/**
 * The turning points of the current motion: where the level meets U_eff on either side of
 * the current position x, the ends of the allowed interval that holds x (f = U_eff − level
 * ≤ 0 inside).  At most one on each side, so each appears once and none lies beyond the well;
 * a side with no crossing in [lo, hi] gives none.  Returns [left, right] without the missing ones.
 */
export function turningPoints(f, lo, hi, x, n = 400) {
  const h = (hi - lo) / n;
  // a position exactly at a turning point counts as inside (rounding would put it just outside)
  const slack = 1e-9 * Math.max(1, Math.abs(f(x)), ...[lo, hi].map((v) => Math.abs(f(v))).filter(Number.isFinite));
  const g = (v) => f(v) - slack;
  if (!(g(x) <= 0)) return [];
  const side = (dir) => {
    for (let k = 1; k <= n; k++) {
      const v = x + dir * k * h;
      if (v < lo - 1e-12 || v > hi + 1e-12) return null;
      const gv = g(v);
      if (!(gv <= 0)) return Number.isFinite(gv) ? bisect(f, v - dir * h, v) : v - dir * h;
    }
    return null;
  };
  return [side(-1), side(1)].filter((v) => v !== null);
}

function window_(values, nonnegative) {
  const lo = Math.min(...values), hi = Math.max(...values);
  const pad = Math.max(0.5 * (hi - lo), 0.15 * Math.max(Math.abs(lo), Math.abs(hi), 0.2));
  return [nonnegative ? Math.max(lo - pad, 1e-3 * hi) : lo - pad, hi + pad];
}

export class EffectivePotentialPanel extends PreviewPanel {
  draw(run) {
    this.red = reduced(run);
    const { r, U, Er, values } = this.red;
    const [lo, hi] = window_(values, run.data.nonnegative.includes(r));
    this.grid = Array.from({ length: 300 }, (_, k) => lo + ((hi - lo) * k) / 299);
    const u = this.grid.map((x) => { const y = U(x); return Number.isFinite(y) ? y : null; });
    const top = Math.max(...finite(Er)), bottom = Math.min(...finite(u));
    const d = Math.max(top - bottom, 1e-9 * Math.abs(top), 1e-12);
    const lr = run.data.labels[r], unit = run.data.units[r];
    const traces = [
      { type: "scatter", mode: "lines", x: this.grid, y: u, name: "U_eff", line: { color: COLORS.U, width: 2.5 } },
    ];
    const lay = layout({ hovermode: "closest", xaxis: axis(titled(lr, unit), { range: [lo, hi] }), yaxis: axis("U_eff (J)", { range: [bottom - 0.1 * d, top + 0.6 * d] }) });
    react(this, traces, lay);
    this.turningCache = new Map();
    // a held momentum with its unit (kg·m²/s for an angle's), as every number on the page has
    const momentumUnitOf = (k) => (run.data.momentum_units && run.data.momentum_units[k.slice(2)]) || "";
    const momenta = Object.entries(this.red.P).map(([k, v]) => `${run.data.labels[k] || k} = ${fmt(v)}${momentumUnitOf(k) ? ` ${momentumUnitOf(k)}` : ""}`).join(", ");
    this.cursor(0, run);
    table(this.summary, "Effective potential on a grid (every 30th point)", [titled(lr, unit), "U_eff (J)"],
      this.grid.filter((_, k) => k % 30 === 0).map((x) => [fmt(x), U(x)]));
    this.note = momenta ? `With ${momenta} (fixed by the initial state).` : "";
  }

  cursor(i, run) {
    const { U, Er, values } = this.red;
    const level = Er[i];
    // the level (dashed), the turning points (diamonds) and the current point, drawn over the plot
    // a cached pair for this level serves only while it still brackets the current position
    let turning = this.turningCache.get(level);
    const x = values[i];
    if (!turning || (turning.length === 2 && (x < turning[0] - 1e-9 || x > turning[1] + 1e-9)) || turning.length < 2) {
      turning = turningPoints((x) => U(x) - level, this.grid[0], this.grid[this.grid.length - 1], values[i]);
      if (this.turningCache.size > 512) this.turningCache.clear();
      this.turningCache.set(level, turning);
    }
    this.overlay.level("level", level);
    // the diamonds larger than the red dot drawn over them: at a turning point (a start from rest) both show
    this.overlay.points("turning", turning.map((x) => [x, level]), { color: COLORS.a, r: 9, shape: "diamond" });
    this.overlay.points("now", [[values[i], U(values[i])]], { r: 4 });
    const lr = run.data.labels[this.red.r], unit = run.data.units[this.red.r];
    const tp = turning.length === 2
      ? `the motion turns at ${lr} = ${fmt(turning[0])} and ${fmt(turning[1])} ${unit}`
      : turning.length === 1 ? `one turning point in view, at ${lr} = ${fmt(turning[0])} ${unit}` : "no turning point in view";
    this.readout.textContent = `Energy level ${fmt(level)} J; ${tp}. ${this.note}`;
  }
}

/** The stable equilibrium nearest the motion and its ω² (from the engine's expressions). */
export function equilibrium(run, red) {
  const spec = run.data.reduction;
  const values = red.values;
  const mid = (Math.min(...values) + Math.max(...values)) / 2;
  const env = red.at(mid);
  const W = compile(spec.omega_squared);
  let candidates = spec.equilibria
    .filter((e) => e.position !== null && e.omega_squared !== null)
    .map((e) => ({ x: compile(e.position)(env), w2: compile(e.omega_squared)(env) }));
  if (!candidates.length && spec.condition !== null) {
    const C = compile(spec.condition);
    const [lo, hi] = window_(values, run.data.nonnegative.includes(red.r));
    candidates = roots((x) => C(red.at(x)), lo, hi).map((x) => ({ x, w2: W(red.at(x)) }));
  }
  const scale = Math.max(Math.max(...values) - Math.min(...values), 1e-3 * Math.abs(mid), 1e-6);
  candidates = candidates.filter((c) => Number.isFinite(c.x) && Number.isFinite(c.w2))
    .map((c) => (c.w2 > 0 ? c : degenerate(red.U, c.x, scale)))
    .filter((c) => c !== null);
  candidates.sort((a, b) => Math.abs(a.x - mid) - Math.abs(b.x - mid));
  return candidates[0] || null;
}

/**
 * An equilibrium where U_eff″ = 0 (to rounding): its verdict from the first derivative that does not vanish.
 * Near x0, U_eff(x0 + δ) − U_eff(x0) ≈ U⁽ⁿ⁾(x0) δⁿ / n!, so the order n is the slope of log ΔU against log δ,
 * and the point is a minimum (stable, though with no small-oscillation frequency) when n is even and ΔU > 0 on
 * both sides.  Returns { x, w2: 0, order } for such a minimum, null otherwise (a maximum or an inflection).
 */
export function degenerate(U, x0, scale) {
  const u0 = U(x0);
  const rise = (d) => [U(x0 + d) - u0, U(x0 - d) - u0];
  const d1 = 1e-2 * scale, d2 = 3e-2 * scale;
  const [a1, b1] = rise(d1), [a2, b2] = rise(d2);
  if (![a1, b1, a2, b2].every((v) => Number.isFinite(v) && v > 0)) return null;
  const order = Math.round(Math.log((a2 + b2) / (a1 + b1)) / Math.log(3));
  return order > 2 && order % 2 === 0 ? { x: x0, w2: 0, order } : null;
}

/** Angular frequency measured from a sampled oscillation (mean spacing of upward crossings of its midline). */
export function measuredOmega(t, values) {
  const mid = (Math.min(...values) + Math.max(...values)) / 2;
  const crossings = [];
  for (let i = 1; i < values.length; i++) {
    const a = values[i - 1] - mid, b = values[i] - mid;
    if (a < 0 && b >= 0) crossings.push(t[i - 1] + ((t[i] - t[i - 1]) * -a) / (b - a));
  }
  if (crossings.length < 2) return null;
  const period = (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
  return (2 * Math.PI) / period;
}

export class SmallOscillationsPanel extends PreviewPanel {
  draw(run) {
    const red = reduced(run);
    const eq = equilibrium(run, red);
    const { r, values } = red;
    const lr = run.data.labels[r], unit = run.data.units[r];
    const measured = measuredOmega(run.t, values);
    const traces = [{ type: "scatter", mode: "lines", x: run.t, y: values, name: `${lr} simulated`, line: { color: COLORS.T, width: 2 } }];
    if (eq && !eq.order) {
      const w = Math.sqrt(eq.w2), a = values[0] - eq.x, b = run.state[`${r}_dot`][0] / w;
      traces.push({ type: "scatter", mode: "lines", x: run.t, y: Array.from(run.t, (t) => eq.x + a * Math.cos(w * t) + b * Math.sin(w * t)), name: "small-oscillation prediction", line: { color: COLORS.U, width: 2, dash: "dash" } });
    }
    react(this, traces, layout({ xaxis: axis("t (s)"), yaxis: axis(titled(lr, unit)) }));
    const predicted = eq && !eq.order ? Math.sqrt(eq.w2) : null;
    // the page's own letter for the frequency: Ω on the rotating parabola, where ω is the wire's turning rate
    const letter = run.data.frequency_letter || "ω";
    // words, never a raw null, where there is nothing to show
    const rows = [
      [`predicted from ${letter}² = U_eff″/${red.inertia}`, predicted ?? (eq ? "none: U_eff″ = 0 at the equilibrium" : "none: no stable equilibrium"), predicted ? (2 * Math.PI) / predicted : "–"],
      ["measured from this run", measured ?? "none: no full oscillation in the run", measured ? (2 * Math.PI) / measured : "–"],
    ];
    table(this.summary, "Small-oscillation frequency", ["", `${letter} (rad/s)`, "period (s)"], rows);
    const tableEl = this.section.querySelector(".frequencies");
    if (tableEl) table(tableEl, "Frequency: prediction and measurement", ["", `${letter} (rad/s)`, "period (s)"], rows);
    const held = Object.entries(red.P).map(([k, v]) => `${run.data.labels[k] || k} = ${fmt(v)}`).join(", ");
    const ordinal = (n) => ({ 4: "fourth", 6: "sixth", 8: "eighth" })[n] || `${n}th`;
    if (eq && eq.order) this.readout.textContent = `About ${lr} = ${fmt(eq.x)}${eq.x === 0 || !unit ? "" : ` ${unit}`}: U_eff″ = 0 there, so there is no small-oscillation frequency; U_eff rises on both sides as the ${ordinal(eq.order)} power of the distance (its first derivative that does not vanish is of even order and positive), so the equilibrium is stable. A swing about it is not harmonic: its period grows as its amplitude shrinks.${measured ? ` This run's, from ${lr} = ${fmt(values[0])} ${unit}, has ${letter} = ${fmt(measured)} rad/s.` : ""}`;
    else if (!eq) this.readout.textContent = `No stable equilibrium: U_eff${held ? ` (with ${held}, from the initial state)` : ""} has no minimum near this motion, so there is no small-oscillation prediction.`;
    else if (!measured) this.readout.textContent = `Predicted ${letter} = ${fmt(predicted)} rad/s about ${lr} = ${fmt(eq.x)} ${unit}; this run is too short to measure a full oscillation.`;
    else {
      // the farthest the run gets from the equilibrium (its swing need not be symmetric about it: the readout
      // names where it starts and the two extremes, not an "amplitude")
      const amp = Math.max(...values.map((v) => Math.abs(v - eq.x)));
      // the measurement resolves the frequency to about the sampling's share of a period, and to the run's error
      const dt = run.t.length > 1 ? run.t[1] - run.t[0] : 0;
      const resolution = 100 * Math.max((measured * dt / (2 * Math.PI)) ** 2, (run.stats.error_estimate || 0) / Math.max(amp, 1e-300), 1e-9);
      this.readout.textContent = `About ${lr} = ${fmt(eq.x)} ${unit}: predicted ${letter} = ${fmt(predicted)} rad/s, measured ${fmt(measured)} rad/s (${percent((measured - predicted) / predicted, resolution / 100)}) for this run from ${lr} = ${fmt(values[0])} ${unit}, which swings between ${lr} = ${fmt(Math.min(...values))} and ${fmt(Math.max(...values))} ${unit}. ${run.data.exact_frequency || "The prediction holds as the amplitude goes to zero."}`;
    }
  }

  cursor(i, run) {
    this.overlay.cursor(run.t[i]);
  }
}

