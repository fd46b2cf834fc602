/**
 * phase.js — the phase portrait panel: a coordinate against its rate, with the level sets of the energy function h.
 *
 *   new PhasePanel(section, data)   panel.draw(run), panel.cursor(i, run)  (the plots.js interface)
 *   wrap(x)                         an angle into (−π, π]
 *   levelCurve(V, m, E, xs)         the level set ½ m(x) v² + V(x) = E over the grid xs, as a polyline
 *
 * With one degree of freedom, or a reduction to one (the derivation's effective_potential), the
 * Hamiltonian at fixed parameters (and fixed conserved momenta) is H(x, v) = ½ m(x) v² + V(x), so
 * each level set is explicit: v = ±√(2 (E − V(x)) / m(x)) where E ≥ V(x).  Equilibria are the
 * extremes of V on the grid (a maximum is unstable); the level of an unstable equilibrium is the
 * separatrix, which parts the orbits that swing from those that go over the top.  An angle is
 * drawn in (−π, π], the trajectory broken where it wraps.  With more coordinates and no reduction
 * the panel shows the chosen coordinate's trajectory alone.
 */
import { compile } from "./expr.js";
import { axis, COLORS, finite, layout, PreviewPanel, rateUnit, react, titled } from "./plotkit.js";
import { reduced } from "./reduction.js";
import { fmt, relativeFloor, seriesTable } from "./summaries.js";

const TAU = 2 * Math.PI;
const GRID = 481;
const SEPARATRIX = "#c62828";

/** x - 2πk in (−π, π]. */
export const wrap = (x) => x - TAU * Math.ceil((x - Math.PI) / TAU);

/** The run's coordinate and rate, wrapped when an angle, with a break (null) wherever it wraps. */
function trajectory(values, rates, angle) {
  const x = [], v = [];
  for (let i = 0; i < values.length; i++) {
    const xi = angle ? wrap(values[i]) : values[i];
    if (angle && i > 0 && Math.abs(xi - x[x.length - 1]) > Math.PI) { x.push(null); v.push(null); }
    x.push(xi); v.push(rates[i]);
  }
  return { x, v };
}

/** The curve ½ m v² + V = E over the grid: closed loops between turning points, else upper and lower branches. */
export function levelCurve(V, m, E, xs) {
  const X = [], Y = [];
  const f = V.map((v) => E - v);
  const speed = (k) => Math.sqrt(Math.max(0, (2 * f[k]) / m[k]));
  let k = 0;
  while (k < xs.length) {
    if (!(f[k] >= 0) || !(m[k] > 0)) { k++; continue; }
    const i0 = k;
    while (k + 1 < xs.length && f[k + 1] >= 0 && m[k + 1] > 0) k++;
    const i1 = k;
    // turning points (v = 0) by linear interpolation of E − V between grid points
    const cross = (a, b) => xs[a] + ((xs[b] - xs[a]) * f[a]) / (f[a] - f[b]);
    const left = i0 > 0 && Number.isFinite(f[i0 - 1]) ? cross(i0, i0 - 1) : null;
    const right = i1 < xs.length - 1 && Number.isFinite(f[i1 + 1]) ? cross(i1, i1 + 1) : null;
    if (left !== null) { X.push(left); Y.push(0); }
    for (let j = i0; j <= i1; j++) { X.push(xs[j]); Y.push(speed(j)); }
    if (right !== null) { X.push(right); Y.push(0); } else { X.push(null); Y.push(null); }
    for (let j = i1; j >= i0; j--) { X.push(xs[j]); Y.push(-speed(j)); }
    if (left !== null) { X.push(left); Y.push(0); }
    X.push(null); Y.push(null);
    k = i1 + 1;
  }
  return { x: X, y: Y };
}

/** Local minima and maxima of V on the grid (cyclic for an angle over a whole turn). */
function extremes(xs, V, Vf, cyclic) {
  const n = cyclic ? xs.length - 1 : xs.length; // the last point of a whole turn repeats the first
  const out = [];
  for (let k = 0; k < n; k++) {
    const a = cyclic ? V[(k - 1 + n) % n] : V[k - 1], b = V[k], c = cyclic ? V[(k + 1) % n] : V[k + 1];
    if (![a, b, c].every(Number.isFinite)) continue;
    // the vertex of the parabola through the three grid values, then a value within rounding of 0 is 0
    const h = xs[1] - xs[0], curve = a - 2 * b + c;
    let x = curve !== 0 ? xs[k] - (h * (c - a)) / (2 * curve) : xs[k];
    if (Math.abs(x - xs[k]) > h) x = xs[k];
    if (Math.abs(x) < 1e-3 * h) x = 0;
    // the level is U at the equilibrium itself (the grid value beside it is off by ½ U''·(x − x_k)²)
    const level = Number.isFinite(Vf(x)) ? Vf(x) : b;
    if (b < a && b <= c) out.push({ x, V: level, stable: true });
    else if (b > a && b >= c) out.push({ x, V: level, stable: false });
  }
  return out;
}

/**
 * Where U first rises above the level E on one side (dir = ±1) of x0: the turning point there, or null.
 * In one dimension the motion is bounded exactly when it has a turning point on each side.  An angle
 * that meets none within a whole turn goes round; a length goes on without bound unless U climbs back
 * above E somewhere beyond (probed out to 2⁴⁰ times the view); a length that cannot be negative
 * meets a wall at 0.  U undefined (outside the configuration space) is a wall too.  The crossing is
 * found by bisection between the last point below the level and the first above it.
 */
export function turningPoint(Vf, E, x0, dir, { angle = false, nonnegative = false, span = 1 } = {}) {
  const above = (x) => { const y = Vf(x); return !Number.isFinite(y) || y > E; };
  const refine = (a, b) => {
    for (let k = 0; k < 80; k++) { const c = (a + b) / 2; if (above(c)) b = c; else a = c; }
    return (a + b) / 2;
  };
  const first = (points) => {
    let last = x0;
    for (const x of points) { if (above(x)) return refine(last, x); last = x; }
    return null;
  };
  const dense = (reach) => Array.from({ length: 960 }, (_, k) => x0 + (dir * reach * (k + 1)) / 960);
  if (angle) return first(dense(TAU));
  if (nonnegative && dir < 0) return first(dense(x0)) ?? 0;
  return first([...dense(span), ...Array.from({ length: 41 }, (_, k) => x0 + dir * span * 2 ** k).filter((x) => dir * (x - x0) > span)]);
}

/** Whether U rises above the level E somewhere on one side (dir = ±1) of x0 (see turningPoint). */
export const turnsBack = (Vf, E, x0, dir, reach = {}) => turningPoint(Vf, E, x0, dir, reach) !== null;

/** An event's message as a clause: "The block reached the foot; the run ends there." → "the block reached the foot". */
function lower(message) {
  const what = message.replace(/[.;]? *the run ends there\.?$/i, "").replace(/\.$/, "");
  return what.charAt(0).toLowerCase() + what.slice(1);
}

/**
 * What a run on one level does when one side (dir) has no turning point, in words: where it turns first
 * (if it starts towards the other side's turning point, or at rest there), which way it then goes without
 * bound, and, when a terminal event ended the run, that event instead of a motion the run never reaches.
 */
export function unboundedFate({ x0, v0, dir, turn, event, values, tEnd, name, fmtAt }) {
  const last = values[values.length - 1];
  const towards = dir > 0 ? "grows" : "decreases";
  // at rest the run leaves the turning point it starts on; moving away from the free side it reaches it first
  const turnsFirst = turn !== null && (v0 * dir < 0 || (v0 === 0 && Math.abs(turn - x0) <= 1e-9 * Math.max(1, Math.abs(x0))));
  const start = turn === null ? ""
    : v0 === 0 && turnsFirst ? `it starts at rest at ${name} = ${fmtAt(x0)}, where the potential equals this level`
    : turnsFirst ? `it turns at ${name} = ${fmtAt(turn)}, where the potential reaches this level` : "";
  if (event) {
    // a run stopped by its event before it reached the turning point says nothing of the turn
    const reach = dir > 0 ? Math.min(...values) : Math.max(...values);
    const reached = turnsFirst && Math.abs(reach - turn) <= 1e-3 * Math.max(Math.abs(turn), Math.abs(reach - x0), 1e-9);
    if (turnsFirst && v0 !== 0 && !reached) return `the run ends at t = ${fmt(event.t)} s, before the turning point at ${name} = ${fmtAt(turn)}: ${lower(event.message)}`;
    const back = turnsFirst && v0 !== 0 ? ", and comes back" : "";
    return `${start ? `${start}${back}; ` : ""}the run ends at t = ${fmt(event.t)} s: ${lower(event.message)}`;
  }
  const then = `nothing turns it back ${dir > 0 ? "beyond" : "below"} ${start ? "there" : `${name} = ${fmtAt(x0)}`}: ${name} ${towards} without bound (the model sets no end to it; at the run's end, t = ${fmt(tEnd)} s, ${name} = ${fmtAt(last)})`;
  return start ? `${start}, then ${then}` : then;
}

function padded(values, nonnegative) {
  const fin = finite(values);
  const lo = Math.min(...fin), hi = Math.max(...fin);
  const pad = Math.max(0.3 * (hi - lo), 0.15 * Math.max(Math.abs(lo), Math.abs(hi), 0.2));
  return [nonnegative ? Math.max(lo - pad, 1e-3 * hi) : lo - pad, hi + pad];
}

/** The one-coordinate model of a run: x, V(x), m(x) on a grid, the run's rate and its level; null without one. */
function model(run) {
  const data = run.data;
  let r, Vf, Mf, level, whole, held = [];
  if (data.reduction) {
    const red = reduced(run);
    const mass = compile(data.reduction.mass);
    r = red.r;
    Vf = red.U;
    Mf = (x) => mass(red.at(x));
    level = red.Er;
    whole = !Object.keys(red.P).length; // no conserved momentum held: the coordinate is the whole system
    // each held momentum with its unit (kg·m²/s for an angle's), as every number on the page has
    const unitOf = (k) => (data.momentum_units && data.momentum_units[k.slice(2)]) || "";
    held = Object.entries(red.P).map(([k, v]) => `${data.labels[k] || k} = ${fmt(v)}${unitOf(k) ? ` ${unitOf(k)}` : ""}`);
  } else if (data.coordinates.length === 1 && data.trees.hamiltonian) {
    // h = T2 − T0 + U has no term linear in the rate: V = h(q, 0), m = h(q, 1) + h(q, −1) − 2 h(q, 0)
    r = data.coordinates[0];
    const h = compile(data.trees.hamiltonian);
    const at = (x, v) => h({ ...run.params, [r]: x, [`${r}_dot`]: v, t: 0 });
    Vf = (x) => at(x, 0);
    Mf = (x) => at(x, 1) + at(x, -1) - 2 * at(x, 0);
    level = run.hamiltonian;
    whole = true;
  } else return null;
  const angle = data.units[r] === "rad";
  const values = run.state[r], rates = run.state[`${r}_dot`];
  const turn = angle && whole;
  const [lo, hi] = turn ? [-Math.PI, Math.PI] : padded(angle ? values.map(wrap) : values, data.nonnegative.includes(r));
  const xs = Array.from({ length: GRID }, (_, k) => lo + ((hi - lo) * k) / (GRID - 1));
  const V = xs.map((x) => { const y = Vf(x); return Number.isFinite(y) ? y : NaN; });
  const m = xs.map((x) => { const y = Mf(x); return Number.isFinite(y) ? y : NaN; });
  return { r, angle, turn, xs, V, m, values, rates, level, lo, hi, held, Vf, nonnegative: data.nonnegative.includes(r) };
}

export class PhasePanel extends PreviewPanel {
  constructor(section, data) {
    super(section, data);
    this.q = data.coordinates[0];
    this.reducible = Boolean(data.reduction) || data.coordinates.length === 1;
    if (!this.reducible && this.tools) {
      const id = `${section.id}-coordinate`;
      const label = Object.assign(document.createElement("label"), { htmlFor: id, textContent: "Coordinate " });
      const select = Object.assign(document.createElement("select"), { id });
      for (const q of data.coordinates) select.append(new Option(data.labels[q] || q, q));
      select.addEventListener("change", () => { this.q = select.value; if (this.run) this.draw(this.run); });
      this.tools.replaceChildren(label, select);
    }
  }

  draw(run) {
    this.run = run;
    // with ∂L/∂t ≠ 0, h(q, q̇) changes along the run: its level sets (drawn at one instant) are followed by no orbit
    const m = this.reducible && !run.data.time_dependent ? model(run) : null;
    if (m) this.drawLevels(run, m); else this.drawProjection(run);
  }

  /** Several coordinates and no reduction: the chosen coordinate against its rate, angles wrapped. */
  drawProjection(run) {
    const q = this.q, angle = run.data.units[q] === "rad";
    const path = trajectory(run.state[q], run.state[`${q}_dot`], angle);
    this.angle = angle; this.r = q;
    const lq = run.data.labels[q], unit = run.data.units[q];
    react(this, [{ type: "scatter", mode: "lines", x: path.x, y: path.v, name: "this run", line: { color: COLORS.T, width: 1.5 } }],
      layout({ hovermode: "closest", xaxis: axis(titled(lq, unit), angle ? { range: [-Math.PI, Math.PI] } : {}), yaxis: axis(titled(run.data.labels[q + "_dot"], rateUnit(run.data, q))) }));
    this.section.dataset.separatrix = "";
    const why = run.data.time_dependent
      ? "L depends explicitly on time (∂L/∂t ≠ 0), so h is not conserved: it changes along the run, the orbit may cross itself, and no curves of constant h are drawn, since no run follows one."
      : "with more than one coordinate moving, the orbit may cross itself, and no curves of constant energy can be drawn in this plane.";
    this.readout.textContent = `${lq} against its rate, for this run: ${why}${angle ? " The angle is shown in (−π, π]." : ""}`;
    seriesTable(this.summary, `Phase portrait of ${lq}`, run.t, [{ name: lq, values: path.x.filter((x) => x !== null) }, { name: run.data.labels[q + "_dot"], values: run.state[`${q}_dot`] }], relativeFloor(run));
  }

  drawLevels(run, m) {
    const { r, angle, xs, V, lo, hi } = m;
    this.angle = angle; this.r = r;
    const path = trajectory(m.values, m.rates, angle);
    const E0 = m.level[0];
    const found = extremes(xs, V, m.Vf, m.turn);
    const saddles = found.filter((e) => !e.stable);
    // the separatrix: the level of the highest unstable equilibrium in view (where the motion changes kind)
    const Es = saddles.length ? Math.max(...saddles.map((e) => e.V)) : null;
    const Vmin = Math.min(...finite(V));
    const top = Math.max(E0, Es ?? E0, Vmin + 1e-9);
    const span = Math.max(top - Vmin, 1e-9);
    const levels = [0.12, 0.3, 0.5, 0.7, 0.88, 1.3, 1.8].map((f) => Vmin + f * span)
      .filter((E) => Math.abs(E - E0) > 0.04 * span && (Es === null || Math.abs(E - Es) > 0.04 * span));
    const join = (curves) => ({ x: curves.flatMap((c) => c.x), y: curves.flatMap((c) => c.y) });
    const grey = join(levels.map((E) => levelCurve(V, m.m, E, xs)));
    const traces = [{ type: "scatter", mode: "lines", x: grey.x, y: grey.y, name: "level sets of h", hoverinfo: "skip", line: { color: "#b8bec5", width: 1 } }];
    let sep = null;
    if (Es !== null) {
      sep = levelCurve(V, m.m, Es, xs);
      traces.push({ type: "scatter", mode: "lines", x: sep.x, y: sep.y, name: "separatrix", line: { color: SEPARATRIX, width: 2, dash: "dash" } });
    }
    traces.push({ type: "scatter", mode: "lines", x: path.x, y: path.v, name: "this run", line: { color: COLORS.T, width: 2 } });
    const vmax = 1.15 * Math.max(...finite(m.rates).map(Math.abs), ...(sep ? finite(sep.y).map(Math.abs) : []), 1e-6);
    const lr = run.data.labels[r], unit = run.data.units[r];
    react(this, traces, layout({
      hovermode: "closest",
      xaxis: axis(titled(lr, unit), { range: [lo, hi], ...(m.turn ? { tickvals: [-Math.PI, -Math.PI / 2, 0, Math.PI / 2, Math.PI], ticktext: ["−π", "−π/2", "0", "π/2", "π"] } : {}) }),
      yaxis: axis(titled(run.data.labels[r + "_dot"], rateUnit(run.data, r)), { range: [-vmax, vmax] }),
    }));
    this.equilibria = found;
    this.section.dataset.separatrix = Es === null ? "" : String(Es);
    this.section.dataset.xrange = JSON.stringify([lo, hi]);
    this.section.dataset.coordinate = r;
    // bounded or not is decided by U itself: a turning point (U > h) on each side of the start, or none on one side
    const x0 = m.values[0], reach = { angle, nonnegative: m.nonnegative, span: hi - lo };
    const turns = [-1, 1].map((dir) => turningPoint(m.Vf, E0, x0, dir, reach));
    const free = [-1, 1].filter((dir, k) => turns[k] === null);
    const v0 = m.rates[0], fmtAt = (x) => (x === 0 || !unit ? fmt(x) : `${fmt(x)} ${unit}`);
    const event = run.stats && run.stats.event;
    // both sides free: it goes the way it starts moving, with nothing to turn it on either side
    const dir = free.length === 2 ? (v0 < 0 ? -1 : 1) : free[0];
    const fate = !free.length ? "it swings back and forth"
      : angle ? "it goes over the top, round and round"
      : unboundedFate({ x0, v0, dir, turn: free.length === 2 ? null : turns[dir > 0 ? 0 : 1], event, values: m.values, tEnd: run.t[run.t.length - 1], name: lr, fmtAt });
    this.section.dataset.turning = free.length === 1 && !angle ? String(turns[free[0] > 0 ? 0 : 1]) : "";
    const relation = Es === null ? "" : ` ${E0 > Es ? "above" : "below"} the separatrix (${fmt(Es)} J)`;
    // a dissipative run has no level of its own: only the level it starts on (it then crosses the level sets)
    const kind = run.data.forced
      ? (Es === null ? "" : ` It starts on the level h = ${fmt(E0)} J,${relation}.`)
      : Es === null && !free.length ? ""
      : Es === null ? ` Its level is h = ${fmt(E0)} J: ${fate}.`
      : !free.length && E0 > Es && !m.turn ? ` Its level h = ${fmt(E0)} J lies${relation}.`
      : ` Its level h = ${fmt(E0)} J lies${relation}: ${fate}.`;
    const forced = run.data.forced ? " A non-conservative force acts, so the run crosses the level sets instead of following one." : "";
    // an angle's top is at θ = π, inside the wrapped interval (−π, π] (−π is the same point, outside it)
    // a value with its unit (0 and π need none)
    const at = (x) => (m.turn && Math.abs(Math.abs(x) - Math.PI) < 1e-6 ? "π" : x === 0 || !unit ? fmt(x) : `${fmt(x)} ${unit}`);
    const listed = found.map((e) => `${lr} = ${at(e.x)} (${e.stable ? "stable" : "unstable"})`)
      .filter((text, i, all) => all.indexOf(text) === i);
    // with cyclic coordinates held at their momenta, a rest point of this plane is a steady motion (a circular orbit,
    // a conical swing), an equilibrium of the reduced problem only: the other coordinates keep turning
    const one = m.held.length === 1;
    const others = one ? "the other coordinate keeps turning" : "the other coordinates keep turning";
    // without a rest point or a separatrix in view the caption's dots and dashed curve are absent: say so
    const eq = !listed.length
      ? (Es === null ? ` No ${m.held.length ? "steady motion" : "equilibrium"} lies in view, so there are no dots and no separatrix.` : "")
      : m.held.length
      ? ` Steady motions in view (rest points of the reduced problem in ${lr}; ${others}): ${listed.join(", ")}.`
      : ` Equilibria in view: ${listed.join(", ")}.`;
    const reduction = !m.held.length ? "" : one
      ? ` The other coordinate is cyclic: its momentum stays at ${m.held[0]} (the initial state's), which leaves h a function of ${lr} and its rate.`
      : ` The other coordinates are cyclic: their momenta stay at ${m.held.join(", ")} (the initial state's), which leaves h a function of ${lr} and its rate.`;
    this.readout.textContent = `${lr} against its rate${angle && m.turn ? ", the angle wrapped into (−π, π]" : ""}.${reduction}${kind}${eq}${forced}`;
    seriesTable(this.summary, `Phase portrait of ${lr}`, run.t, [{ name: lr, values: path.x.filter((x) => x !== null) }, { name: run.data.labels[r + "_dot"], values: m.rates }], relativeFloor(run));
    this.marks();
  }

  marks() {
    const eq = this.equilibria || [];
    const pts = (stable) => eq.filter((e) => e.stable === stable).flatMap((e) => (this.angle && Math.abs(Math.abs(e.x) - Math.PI) < 1e-6 ? [[-Math.PI, 0], [Math.PI, 0]] : [[e.x, 0]]));
    this.overlay.points("stable", pts(true), { color: "#2e7d32", r: 5 });
    this.overlay.points("unstable", pts(false), { color: SEPARATRIX, r: 7, shape: "diamond" });
  }

  cursor(i, run) {
    const x = run.state[this.r][i];
    this.overlay.points("now", [[this.angle ? wrap(x) : x, run.state[`${this.r}_dot`][i]]]);
    if (this.reducible) this.marks();
  }
}
