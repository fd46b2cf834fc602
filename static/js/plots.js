/**
 * plots.js — the scene's plot panels, each drawn with Plotly into a <section data-panel>.
 *
 *   const panel = createPanel(kind, section, data);  // kind from the panels vocabulary
 *   panel.draw(run);        // run from simulation.js prepareRun()
 *   panel.cursor(i, run);   // move the time cursor (or the current-state marker) to sample i
 *
 * Panels: energy, h-vs-e, momenta, phase, effective-potential, small-oscillations,
 * constraint-force (time plots with a cursor line), and work-precision (drawn from
 * GET /api/scenes/{id}/work-precision plus the current run's error estimate).
 * Each panel writes a text alternative (a data table) into its .data-summary and
 * a one-line reading into its .readout.
 */
import { compile } from "./expr.js";
import { fmt, seriesTable, table } from "./summaries.js";

const CONFIG = { responsive: true, displaylogo: false };
const COLORS = { T: "#0b5cad", U: "#b34700", E: "#1b1f24", h: "#2e7d32", a: "#6a1b9a", b: "#00838f" };
const PALETTE = ["#0b5cad", "#b34700", "#2e7d32", "#6a1b9a", "#00838f", "#8d6e00"];

function layout(extra = {}) {
  return {
    margin: { l: 64, r: 16, t: 24, b: 44 }, height: 340, font: { size: 13 },
    paper_bgcolor: "#fff", plot_bgcolor: "#fff", legend: { orientation: "h", x: 0, y: 1.02, yanchor: "bottom" },
    hovermode: "x unified", ...extra,
  };
}

const axis = (text, extra = {}) => ({ title: { text }, gridcolor: "#e6e8eb", zerolinecolor: "#b8bec5", ...extra });
const cursorShape = (t) => ({ type: "line", xref: "x", yref: "paper", x0: t, x1: t, y0: 0, y1: 1, line: { color: "#57606a", width: 1.5, dash: "dot" } });
const line = (x, y, name, color, dash = "solid") => ({ type: "scatter", mode: "lines", x, y, name, line: { color, width: 2, dash } });
const diff = (arr) => Array.from(arr, (v) => v - arr[0]);
const finite = (arr) => arr.filter((v) => Number.isFinite(v));
const capital = (text) => text.charAt(0).toUpperCase() + text.slice(1);

function parts(section) {
  return {
    plot: section.querySelector(".plot"),
    summary: section.querySelector(".data-summary .table"),
    readout: section.querySelector(".readout"),
    tools: section.querySelector(".panel-tools"),
  };
}

/** A panel of quantities against time, with a second row for their change since t = 0. */
class TimePanel {
  constructor(section, data) { this.section = section; this.data = data; Object.assign(this, parts(section)); }

  series(run) { return []; } // [{name, values, color, dash}]

  drawSeries(run, top, bottom, yTitle, bottomTitle) {
    const traces = top.map((s) => line(run.t, s.values, s.name, s.color, s.dash));
    for (const s of bottom || []) traces.push({ ...line(run.t, s.values, s.name, s.color, s.dash), yaxis: "y2", showlegend: false });
    const grid = bottom
      ? { yaxis: axis(yTitle, { domain: [0.42, 1] }), yaxis2: axis(bottomTitle, { domain: [0, 0.3], exponentformat: "e" }), xaxis: axis("t (s)", { anchor: "y2" }), height: 400 }
      : { yaxis: axis(yTitle), xaxis: axis("t (s)") };
    Plotly.react(this.plot, traces, layout({ ...grid, shapes: [cursorShape(run.t[0])] }), CONFIG);
  }

  cursor(i, run) {
    Plotly.relayout(this.plot, { "shapes[0].x0": run.t[i], "shapes[0].x1": run.t[i] });
  }
}

class EnergyPanel extends TimePanel {
  draw(run) {
    const top = [];
    if (run.T) top.push({ name: "T", values: run.T, color: COLORS.T });
    if (run.U) top.push({ name: "U", values: run.U, color: COLORS.U });
    top.push({ name: "E = T + U", values: run.energy, color: COLORS.E });
    top.push({ name: "h", values: run.hamiltonian, color: COLORS.h, dash: "dash" });
    const dE = diff(run.energy), dh = diff(run.hamiltonian);
    const bottom = [{ name: "E − E(0)", values: dE, color: COLORS.E }, { name: "h − h(0)", values: dh, color: COLORS.h, dash: "dash" }];
    this.drawSeries(run, top, bottom, "energy (J)", "change");
    // relative to the run's energy scale (E itself may be zero, as when U is measured from the start)
    const scale = Math.max(...finite([...run.energy, ...(run.T || []), ...(run.U || [])]).map(Math.abs), 1e-300);
    const rel = (d) => Math.max(...finite(d).map(Math.abs)) / scale;
    let what = run.data.h_equals_e ? "h = E here." : "h and E differ here.";
    if (run.data.forced) what += " A non-conservative generalized force acts, so the change is physical, not numerical.";
    this.readout.textContent = `Largest change since t = 0, relative to the energy scale ${fmt(scale)} J: E by ${fmt(rel(dE))}, h by ${fmt(rel(dh))}. ${what}`;
    seriesTable(this.summary, "Energies over the run (J)", run.t, [...top, ...bottom]);
  }
}

class HvsEPanel extends TimePanel {
  draw(run) {
    const gap = Array.from(run.energy, (e, i) => e - run.hamiltonian[i]);
    const top = [{ name: "E = T + U", values: run.energy, color: COLORS.E }, { name: "h", values: run.hamiltonian, color: COLORS.h }];
    this.drawSeries(run, top, [{ name: "E − h", values: gap, color: COLORS.a }], "energy (J)", "E − h (J)");
    const span = (a) => Math.max(...finite(a)) - Math.min(...finite(a));
    this.readout.textContent = `Over the run E varies by ${fmt(span(run.energy))} J while h varies by ${fmt(span(run.hamiltonian))} J.`;
    seriesTable(this.summary, "h and E over the run (J)", run.t, [...top, { name: "E − h", values: gap }]);
  }
}

class MomentaPanel extends TimePanel {
  draw(run) {
    const names = Object.keys(run.momenta);
    const top = names.map((n, k) => ({ name: run.data.labels[n] || n, values: run.momenta[n], color: PALETTE[k % PALETTE.length] }));
    const bottom = names.map((n, k) => ({ name: `${run.data.labels[n] || n} − initial`, values: diff(run.momenta[n]), color: PALETTE[k % PALETTE.length] }));
    this.drawSeries(run, top, bottom, "momentum", "change");
    // a conserved quantity should look flat: centre the upper axis on the values with a margin
    // of 5 % of their size (or 5 times their drift, if larger), not on the noise
    const all = finite(top.flatMap((s) => Array.from(s.values)));
    const drift = Math.max(...finite(bottom.flatMap((s) => Array.from(s.values))).map(Math.abs), 0);
    const lo = Math.min(...all), hi = Math.max(...all);
    const pad = Math.max(0.05 * Math.max(Math.abs(lo), Math.abs(hi)), 5 * drift, 1e-12);
    Plotly.relayout(this.plot, { "yaxis.range": [lo - pad, hi + pad] });
    this.readout.textContent = top.map((s, k) => `${s.name} stays at ${fmt(s.values[0])} within ${fmt(Math.max(...finite(bottom[k].values).map(Math.abs)))}.`).join(" ");
    seriesTable(this.summary, "Conserved momenta over the run", run.t, [...top, ...bottom]);
  }
}

class ConstraintForcePanel extends TimePanel {
  draw(run) {
    const top = [];
    const notes = [];
    run.data.constraint_forces.forEach((c, k) => {
      const values = run.forces[c.name];
      if (!values) return;
      top.push({ name: c.label, values, color: PALETTE[k % PALETTE.length] });
      if (c.slack_when_negative) {
        const slack = Array.from(values, (v) => (v < 0 ? v : null));
        const count = slack.filter((v) => v !== null).length;
        if (count) {
          top.push({ name: `${c.label} < 0: slack`, values: slack, color: "#c62828" });
          const first = run.t[slack.findIndex((v) => v !== null)];
          notes.push(`${capital(c.label)} goes negative (the constraint would have to push, so it goes slack) first at t = ${fmt(first)} s, for ${fmt((100 * count) / values.length)} % of the run.`);
        } else notes.push(`${capital(c.label)} stays positive: the constraint holds throughout.`);
      }
    });
    this.drawSeries(run, top, null, "force (N)");
    Plotly.relayout(this.plot, { "shapes[1]": { type: "line", xref: "paper", x0: 0, x1: 1, y0: 0, y1: 0, line: { color: "#57606a", width: 1 } } });
    const ranges = top.filter((s) => !s.name.includes("slack")).map((s) => `${capital(s.name)} ranges from ${fmt(Math.min(...finite(s.values)))} to ${fmt(Math.max(...finite(s.values)))} N.`);
    this.readout.textContent = [...notes, ...ranges].join(" ");
    seriesTable(this.summary, "Constraint forces over the run (N)", run.t, top.filter((s) => !s.name.includes("slack")));
  }
}

class PhasePanel {
  constructor(section, data) {
    this.section = section; this.data = data; Object.assign(this, parts(section));
    this.q = data.coordinates[0];
    if (data.coordinates.length > 1 && this.tools) {
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
    const q = run.state[this.q], v = run.state[`${this.q}_dot`];
    const lq = run.data.labels[this.q], unit = run.data.units[this.q];
    const traces = [
      { type: "scatter", mode: "lines", x: q, y: v, name: "trajectory", line: { color: COLORS.T, width: 1.5 } },
      { type: "scatter", mode: "markers", x: [q[0]], y: [v[0]], name: "now", marker: { color: "#c62828", size: 11 } },
    ];
    Plotly.react(this.plot, traces, layout({ hovermode: "closest", xaxis: axis(`${lq} (${unit})`), yaxis: axis(`${run.data.labels[this.q + "_dot"]} (${unit}/s)`) }), CONFIG);
    this.readout.textContent = `${lq} ranges over [${fmt(Math.min(...q))}, ${fmt(Math.max(...q))}] ${unit}; its rate over [${fmt(Math.min(...v))}, ${fmt(Math.max(...v))}] ${unit}/s.`;
    seriesTable(this.summary, `Phase portrait of ${lq}`, run.t, [{ name: lq, values: q }, { name: run.data.labels[this.q + "_dot"], values: v }]);
  }

  cursor(i, run) {
    Plotly.restyle(this.plot, { x: [[run.state[this.q][i]]], y: [[run.state[`${this.q}_dot`][i]]] }, [1]);
  }
}

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
  return { r, P, U: (x) => U(at(x)), at, Er, values: run.state[r] };
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

function window_(values, nonnegative) {
  const lo = Math.min(...values), hi = Math.max(...values);
  const pad = Math.max(0.5 * (hi - lo), 0.15 * Math.max(Math.abs(lo), Math.abs(hi), 0.2));
  return [nonnegative ? Math.max(lo - pad, 1e-3 * hi) : lo - pad, hi + pad];
}

class EffectivePotentialPanel {
  constructor(section, data) { this.section = section; this.data = data; Object.assign(this, parts(section)); }

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
      { type: "scatter", mode: "lines", x: [lo, hi], y: [Er[0], Er[0]], name: "energy level", line: { color: COLORS.E, dash: "dash" } },
      { type: "scatter", mode: "markers", x: [], y: [], name: "turning points", marker: { color: COLORS.a, size: 10, symbol: "diamond" } },
      { type: "scatter", mode: "markers", x: [values[0]], y: [U(values[0])], name: "now", marker: { color: "#c62828", size: 12 } },
    ];
    const lay = layout({ hovermode: "closest", xaxis: axis(`${lr} (${unit})`, { range: [lo, hi] }), yaxis: axis("U_eff (J)", { range: [bottom - 0.1 * d, top + 0.6 * d] }) });
    Plotly.react(this.plot, traces, lay, CONFIG);
    const momenta = Object.entries(this.red.P).map(([k, v]) => `${run.data.labels[k] || k} = ${fmt(v)}`).join(", ");
    this.cursor(0, run);
    table(this.summary, "Effective potential on a grid (every 30th point)", [`${lr} (${unit})`, "U_eff (J)"],
      this.grid.filter((_, k) => k % 30 === 0).map((x) => [fmt(x), U(x)]));
    this.note = momenta ? `With ${momenta} (fixed by the initial state).` : "";
  }

  cursor(i, run) {
    const { U, Er, values } = this.red;
    const level = Er[i];
    const turning = roots((x) => U(x) - level, this.grid[0], this.grid[this.grid.length - 1]);
    Plotly.restyle(this.plot, {
      x: [[this.grid[0], this.grid[this.grid.length - 1]], turning, [values[i]]],
      y: [[level, level], turning.map(() => level), [U(values[i])]],
    }, [1, 2, 3]);
    const lr = run.data.labels[this.red.r], unit = run.data.units[this.red.r];
    const tp = turning.length ? `turning points at ${lr} = ${turning.map(fmt).join(", ")} ${unit}` : "no turning point in view";
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
  candidates = candidates.filter((c) => Number.isFinite(c.x) && Number.isFinite(c.w2) && c.w2 > 0);
  candidates.sort((a, b) => Math.abs(a.x - mid) - Math.abs(b.x - mid));
  return candidates[0] || null;
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

class SmallOscillationsPanel {
  constructor(section, data) { this.section = section; this.data = data; Object.assign(this, parts(section)); }

  draw(run) {
    const red = reduced(run);
    const eq = equilibrium(run, red);
    const { r, values } = red;
    const lr = run.data.labels[r], unit = run.data.units[r];
    const measured = measuredOmega(run.t, values);
    const traces = [{ type: "scatter", mode: "lines", x: run.t, y: values, name: `${lr} simulated`, line: { color: COLORS.T, width: 2 } }];
    if (eq) {
      const w = Math.sqrt(eq.w2), a = values[0] - eq.x, b = run.state[`${r}_dot`][0] / w;
      traces.push({ type: "scatter", mode: "lines", x: run.t, y: Array.from(run.t, (t) => eq.x + a * Math.cos(w * t) + b * Math.sin(w * t)), name: "small-oscillation prediction", line: { color: COLORS.U, width: 2, dash: "dash" } });
    }
    Plotly.react(this.plot, traces, layout({ xaxis: axis("t (s)"), yaxis: axis(`${lr} (${unit})`), shapes: [cursorShape(0)] }), CONFIG);
    const predicted = eq ? Math.sqrt(eq.w2) : null;
    const rows = [
      ["predicted by the engine (ω² = U_eff''/m_eff)", predicted, predicted ? (2 * Math.PI) / predicted : null],
      ["measured from this run", measured, measured ? (2 * Math.PI) / measured : null],
    ];
    table(this.summary, "Small-oscillation frequency", ["", "ω (rad/s)", "period (s)"], rows);
    const tableEl = this.section.querySelector(".frequencies");
    if (tableEl) table(tableEl, "Frequency: prediction and measurement", ["", "ω (rad/s)", "period (s)"], rows);
    if (!eq) this.readout.textContent = "No stable equilibrium near this motion, so no small-oscillation prediction.";
    else if (!measured) this.readout.textContent = `Predicted ω = ${fmt(predicted)} rad/s about ${lr} = ${fmt(eq.x)} ${unit}; this run is too short to measure a full oscillation.`;
    else {
      const amp = Math.max(...values.map((v) => Math.abs(v - eq.x)));
      this.readout.textContent = `About ${lr} = ${fmt(eq.x)} ${unit}: predicted ω = ${fmt(predicted)} rad/s, measured ${fmt(measured)} rad/s (${fmt((100 * (measured - predicted)) / predicted)} %) at amplitude ${fmt(amp)} ${unit}. The prediction holds as the amplitude goes to zero.`;
    }
  }

  cursor(i, run) {
    Plotly.relayout(this.plot, { "shapes[0].x0": run.t[i], "shapes[0].x1": run.t[i] });
  }
}

class WorkPrecisionPanel {
  // The report is measured once per scene on the server and can take seconds the first time,
  // so it is fetched only when the panel scrolls into view.
  constructor(section, data, url) {
    this.section = section; this.data = data; this.url = url; Object.assign(this, parts(section));
    this.visible = !("IntersectionObserver" in window);
    if (!this.visible) {
      const observer = new IntersectionObserver((entries) => {
        if (!entries.some((e) => e.isIntersecting)) return;
        observer.disconnect();
        this.visible = true;
        if (this.run) this.draw(this.run);
      }, { rootMargin: "200px" });
      observer.observe(section);
    }
  }

  async report() {
    if (!this.pending) {
      this.pending = fetch(this.url, { headers: { Accept: "application/json" } }).then(async (res) => {
        const body = await res.json().catch(() => ({}));
        if (!res.ok) throw new Error(body.detail || `the work-precision report failed (${res.status})`);
        return body;
      });
      this.pending.catch(() => { this.pending = null; });
    }
    return this.pending;
  }

  async draw(run) {
    this.run = run;
    const stats = run.stats;
    const here = `This run: ${stats.method}, error estimate ${fmt(stats.error_estimate)}, run time ${fmt(stats.wall_time_s * 1000)} ms, ${stats.rhs_evaluations ?? "–"} right-hand-side evaluations.`;
    if (!this.visible) { this.readout.textContent = `${here} The chart loads when this panel is in view.`; return; }
    this.readout.textContent = `${here} Loading the error-against-run-time chart…`;
    this.section.setAttribute("aria-busy", "true");
    let report;
    try {
      report = await this.report();
    } catch (err) {
      this.readout.textContent = `${here} ${err.message}`;
      this.section.setAttribute("aria-busy", "false");
      return;
    }
    const methods = [...new Set(report.runs.map((r) => r.method))];
    const traces = methods.map((m, k) => {
      const runs = report.runs.filter((r) => r.method === m && r.error > 0 && r.wall_time_s > 0);
      return { type: "scatter", mode: "lines+markers", name: m, x: runs.map((r) => r.wall_time_s), y: runs.map((r) => r.error),
        text: runs.map((r) => `rtol ${r.rtol}`), line: { color: PALETTE[k % PALETTE.length] }, marker: { size: 7 } };
    });
    if (stats.error_estimate > 0 && stats.wall_time_s > 0) {
      traces.push({ type: "scatter", mode: "markers", name: "this run (estimate)", x: [stats.wall_time_s], y: [stats.error_estimate],
        marker: { symbol: "star", size: 16, color: "#c62828", line: { color: "#1b1f24", width: 1 } } });
    }
    Plotly.react(this.plot, traces, layout({ hovermode: "closest", height: 360, xaxis: axis("run time (s)", { type: "log", exponentformat: "power" }), yaxis: axis("error", { type: "log", exponentformat: "power" }) }), CONFIG);
    if (this.run !== run) return; // a newer run is being drawn
    this.readout.textContent = `${here} Reference: ${report.reference}`;
    table(this.summary, "Error against run time", ["method", "rtol", "error", "run time (s)", "rhs evaluations"],
      report.runs.map((r) => [r.method, String(r.rtol), r.error, r.wall_time_s, String(r.rhs_evaluations ?? "–")]));
    this.section.setAttribute("aria-busy", "false");
  }

  cursor() {}
}

const KINDS = {
  energy: EnergyPanel,
  "h-vs-e": HvsEPanel,
  momenta: MomentaPanel,
  phase: PhasePanel,
  "effective-potential": EffectivePotentialPanel,
  "small-oscillations": SmallOscillationsPanel,
  "constraint-force": ConstraintForcePanel,
  "work-precision": WorkPrecisionPanel,
};

export function createPanel(kind, section, data, urls = {}) {
  const Kind = KINDS[kind];
  if (!Kind) return null;
  return kind === "work-precision" ? new Kind(section, data, urls.workPrecision) : new Kind(section, data);
}
