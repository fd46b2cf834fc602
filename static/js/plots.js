/**
 * plots.js — the scene's plot panels, each drawn with Plotly into a <section data-panel>.
 *
 *   const panel = createPanel(kind, section, data);  // kind from the panels vocabulary
 *   panel.draw(run);        // run from simulation.js prepareRun()
 *   panel.cursor(i, run);   // move the time cursor (or the current-state marker) to sample i:
 *                           // an SVG overlay (plotkit.js Overlay), never a Plotly relayout
 *   panel.preview           // false for panels that need the server's run (forces, error report)
 *
 * Panels (their names, titles and availability: app/viz/panels.py): energy, h-vs-e, momenta,
 * constraint-force (time plots with a cursor line), phase (phase.js), effective-potential and
 * small-oscillations (reduction.js), modes (modes.js), poincare (poincare.js), and work-precision
 * (drawn from GET /api/scenes/{id}/work-precision plus the current run's error estimate).
 * Each panel writes a text alternative (a data table) into its .data-summary and
 * a one-line reading into its .readout.
 */
import { fetchJSON } from "./api.js";
import { ActionPanel } from "./action.js";
import { axis, capital, COLORS, CONFIG, diff, drawWhenVisible, finite, layout, line, momentumUnit, PALETTE, parts, PreviewPanel, react } from "./plotkit.js";
import { ModesPanel } from "./modes.js";
import { PhasePanel } from "./phase.js";
import { PoincarePanel } from "./poincare.js";
import { EffectivePotentialPanel, SmallOscillationsPanel } from "./reduction.js";
import { constantOrRange, fmt, magnitude, median, percent, relativeFloor, seriesTable, sharedUnit, table } from "./summaries.js";

/** A panel of quantities against time, with a second row for their change since t = 0. */
class TimePanel extends PreviewPanel {
  drawSeries(run, top, bottom, yTitle, bottomTitle, extra = {}) {
    const traces = top.map((s) => line(run.t, s.values, s.name, s.color, s.dash));
    for (const s of bottom || []) traces.push({ ...line(run.t, s.values, s.name, s.color, s.dash), yaxis: "y2", showlegend: false });
    const grid = bottom
      ? { yaxis: axis(yTitle, { domain: [0.42, 1], ...(extra.yaxis || {}) }), yaxis2: axis(bottomTitle, { domain: [0, 0.3], nticks: 3 }), xaxis: axis("t (s)", { anchor: "y2" }), height: 380 }
      : { yaxis: axis(yTitle), xaxis: axis("t (s)") };
    react(this, traces, layout({ ...grid, shapes: extra.shapes || [] }));
  }

  cursor(i, run) {
    this.overlay.cursor(run.t[i]);
  }
}

class EnergyPanel extends TimePanel {
  draw(run) {
    // only L given (h_equals_e null): T and U cannot be told apart, so E = T + U is not defined; h alone is drawn
    const undecided = run.data.h_equals_e === null || run.data.h_equals_e === undefined;
    const top = [];
    if (run.T) top.push({ name: "T", values: run.T, color: COLORS.T });
    if (run.U) top.push({ name: "U", values: run.U, color: COLORS.U });
    if (!undecided) top.push({ name: "E = T + U", values: run.energy, color: COLORS.E });
    top.push({ name: "h", values: run.hamiltonian, color: COLORS.h, dash: "dash" });
    const dE = diff(run.energy), dh = diff(run.hamiltonian);
    const bottom = [{ name: "h − h(0)", values: dh, color: COLORS.h, dash: "dash" }];
    if (!undecided) bottom.unshift({ name: "E − E(0)", values: dE, color: COLORS.E });
    this.drawSeries(run, top, bottom, "energy (J)", "change (J)");
    // relative to the run's energy scale (E itself may be zero, as when U is measured from the start)
    const scale = Math.max(...finite([...run.energy, ...(run.T || []), ...(run.U || [])]).map(Math.abs), 1e-300);
    let what = { true: "h = E here.", false: "h and E differ here." }[run.data.h_equals_e]
      ?? "Only L was given, so T and U cannot be told apart and the energy E = T + U is not defined here: h is drawn alone.";
    if (run.data.forced) what += " A non-conservative generalized force acts, so the change is physical, not numerical.";
    // a change within the run's energy resolution is the integration's error, not a number to read
    // each change named with its unit, and as a share of the run's largest energy (so 0.9 reads as 90 %)
    const change = (d) => {
      const big = Math.max(...finite(d).map(Math.abs));
      if (big <= run.resolution) return "≈ 0 (within the integration's error)";
      const share = big / scale;
      return `${fmt(big)} J (${share >= 0.01 ? percent(share) : `${fmt(share)}`} of the largest energy in the run, ${fmt(scale)} J)`;
    };
    const changes = undecided ? `h changed by ${change(dh)}` : `E changed by ${change(dE)}; h changed by ${change(dh)}`;
    this.readout.textContent = `Largest change since t = 0: ${changes}. ${what}`;
    seriesTable(this.summary, "Energies over the run (J)", run.t, [...top, ...bottom], relativeFloor(run));
  }
}

class HvsEPanel extends TimePanel {
  draw(run) {
    const gap = Array.from(run.energy, (e, i) => e - run.hamiltonian[i]);
    const top = [{ name: "E = T + U", values: run.energy, color: COLORS.E }, { name: "h", values: run.hamiltonian, color: COLORS.h }];
    this.drawSeries(run, top, [{ name: "E − h", values: gap, color: COLORS.a }], "energy (J)", "E − h (J)");
    const span = (a) => Math.max(...finite(a)) - Math.min(...finite(a));
    this.readout.textContent = `Over the run E varies by ${fmt(span(run.energy))} J while h varies by ${fmt(span(run.hamiltonian))} J.`;
    seriesTable(this.summary, "h and E over the run (J)", run.t, [...top, { name: "E − h", values: gap }], relativeFloor(run));
  }
}

class MomentaPanel extends TimePanel {
  draw(run) {
    const names = Object.keys(run.momenta);
    const top = names.map((n, k) => ({ name: run.data.labels[n] || n, values: run.momenta[n], color: PALETTE[k % PALETTE.length] }));
    const bottom = names.map((n, k) => ({ name: `${run.data.labels[n] || n} − initial`, values: diff(run.momenta[n]), color: PALETTE[k % PALETTE.length] }));
    // a conserved quantity should look flat: centre the upper axis on the values with a margin
    // of 5 % of their size (or 5 times their drift, if larger), not on the noise
    const all = finite(top.flatMap((s) => Array.from(s.values)));
    const drift = Math.max(...finite(bottom.flatMap((s) => Array.from(s.values))).map(Math.abs), 0);
    const lo = Math.min(...all), hi = Math.max(...all);
    const pad = Math.max(0.05 * Math.max(Math.abs(lo), Math.abs(hi)), 5 * drift, 1e-12);
    // a rotation's J of coordinates in m is in kg·m²/s; a momentum has its coordinate's unit
    const lengths = Object.values(run.data.units).every((u) => u === "m");
    // a sum of momenta (p_x1 + p_x2) has its terms' unit, the first term's coordinate's
    const coordinate = (n) => n.split(" + ")[0].slice(2);
    const unitOf = (n) => n.startsWith("J")
      ? (lengths ? momentumUnit("rad") : "SI units")
      : (run.data.momentum_units && run.data.momentum_units[coordinate(n)]) || momentumUnit(run.data.units[coordinate(n)]);
    const units = [...new Set(names.map(unitOf))];
    // one unit names the axis; a mixed set (kg·m/s beside kg·m²/s) names each momentum's in the legend
    const unit = units.length === 1 ? units[0] : null;
    const legend = (series) => (unit ? series : series.map((s, k) => ({ ...s, name: `${s.name} (${unitOf(names[k])})` })));
    this.drawSeries(run, legend(top), legend(bottom), unit ? `momentum (${unit})` : "momentum (unit in the legend)", unit ? `change (${unit})` : "change (unit in the legend)", { yaxis: { range: [lo - pad, hi + pad] } });
    // each momentum with its own unit: "p_θ stays at 1 kg·m²/s within 7.6 × 10⁻⁹ kg·m²/s"
    const said = (x, n) => `${fmt(x)}${unitOf(n) && !unitOf(n).includes("SI") ? ` ${unitOf(n)}` : ""}`;
    this.readout.textContent = top.map((s, k) => `${s.name} stays at ${said(s.values[0], names[k])} within ${said(Math.max(...finite(bottom[k].values).map(Math.abs)), names[k])}.`).join(" ");
    seriesTable(this.summary, "Conserved momenta over the run", run.t, [...top, ...bottom], relativeFloor(run));
  }
}

class ConstraintForcePanel extends TimePanel {
  constructor(section, data) { super(section, data); this.preview = false; } // the forces come from the server's run

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
          notes.push(`${capital(c.label)} goes negative (the constraint would have to push, so it goes slack) first at t = ${fmt(first)} s, for ${percent(count / values.length)} of the run.`);
        } else notes.push(`${capital(c.label)} stays positive: the constraint holds throughout.`);
      }
    });
    this.drawSeries(run, top, null, "force (N)", null,
      { shapes: [{ type: "line", xref: "paper", x0: 0, x1: 1, y0: 0, y1: 0, line: { color: "#57606a", width: 1 } }] });
    const ranges = top.filter((s) => !s.name.includes("slack")).map((s) => `${capital(s.name)} ${constantOrRange(s.values, "N")}.`);
    this.readout.textContent = [...notes, ...ranges].join(" ");
    seriesTable(this.summary, "Constraint forces over the run (N)", run.t, top.filter((s) => !s.name.includes("slack")), relativeFloor(run));
  }
}

const REPEATS = 3;
const SLOW_MS = 4000; // a work-precision report still loading after this long is being measured
const errorUnit = (data) => [...new Set(data.coordinates.map((q) => data.units[q]))].join(" or ");

class WorkPrecisionPanel {
  // The report is measured once per scene on the server and can take seconds the first time,
  // so it is fetched only when the panel scrolls into view.
  constructor(section, data, urls = {}) {
    this.section = section; this.data = data; this.url = urls.workPrecision; this.simulateUrl = urls.simulate;
    Object.assign(this, parts(section));
    this.timings = new Map(); // request -> run times of that same request (s)
    this.preview = false; // the report and the star belong to the server's run
    drawWhenVisible(this, section);
  }

  async report() {
    if (!this.pending) {
      this.pending = fetchJSON(this.url);
      this.pending.catch(() => { this.pending = null; });
    }
    return this.pending;
  }

  /**
   * The run time of this run's request as the median of a few runs (one timing is noise at a
   * millisecond): the server's run, plus up to REPEATS − 1 more of the same request.
   */
  async medianTime(run) {
    const key = JSON.stringify(run.request);
    const times = this.timings.get(key) || [];
    if (!this.timings.has(key)) { this.timings.clear(); this.timings.set(key, times); }
    if (Number.isFinite(run.stats.wall_time_s) && times.length < REPEATS) times.push(run.stats.wall_time_s);
    while (this.simulateUrl && times.length < REPEATS && this.run === run) {
      // a repeat is a measurement, not a need: one try, nothing when the server is busy
      const body = await fetchJSON(this.simulateUrl, { body: run.request, tries: 1 }).catch(() => null);
      if (!body || !Number.isFinite(body.stats?.wall_time_s)) break;
      times.push(body.stats.wall_time_s);
    }
    return { time: median(times), count: times.length };
  }

  async draw(run) {
    this.run = run;
    const stats = run.stats;
    // what the error is of and in which unit; the run's time is the chart's axis, not a sentence
    const unit = sharedUnit(this.data);
    const here = `This run: ${this.data.method_labels?.[stats.method] || stats.method}, largest estimated error in the coordinates ${fmt(stats.error_estimate)}${unit ? ` ${unit}` : " (in each coordinate's unit)"}.`;
    if (!this.visible) { this.readout.textContent = `${here} The chart is drawn when you scroll to it.`; return; }
    this.readout.textContent = `${here} Loading the error-against-run-time chart…`;
    this.section.setAttribute("aria-busy", "true");
    // the report is measured once per engine version (at the server's warm-up, else on the first request): a reader
    // who waits longer than a moment is told what is being done, not left with "Loading…"
    const slow = setTimeout(() => {
      if (this.run === run && this.section.getAttribute("aria-busy") === "true") {
        this.readout.textContent = `${here} This chart is being measured on the server: every method at each tolerance, `
          + "each run timed several times. It is measured once for each version of the book and then kept for every "
          + "reader; the chart appears here when it is done.";
      }
    }, SLOW_MS);
    let report;
    try {
      report = await this.report();
    } catch (err) {
      clearTimeout(slow);
      this.readout.textContent = `${here} ${err.message}`;
      this.section.setAttribute("aria-busy", "false");
      return;
    }
    clearTimeout(slow);
    const methods = [...new Set(report.runs.map((r) => r.method))];
    const methodLabel = (m) => this.data.method_labels?.[m] || m;
    const traces = methods.map((m, k) => {
      const runs = report.runs.filter((r) => r.method === m && r.error > 0 && r.wall_time_s > 0);
      return { type: "scatter", mode: "lines+markers", name: methodLabel(m), x: runs.map((r) => r.wall_time_s), y: runs.map((r) => r.error),
        text: runs.map((r) => `rtol ${r.rtol}`), line: { color: PALETTE[k % PALETTE.length] }, marker: { size: 7 } };
    });
    const timed = await this.medianTime(run);
    if (this.run !== run) return; // a newer run is being drawn
    if (stats.error_estimate > 0 && timed.time > 0) {
      const name = timed.count > 1 ? `this run (estimate; median time of ${timed.count} runs)` : "this run (estimate)";
      traces.push({ type: "scatter", mode: "markers", name, x: [timed.time], y: [stats.error_estimate],
        marker: { symbol: "star", size: 16, color: "#c62828", line: { color: "#1b1f24", width: 1 } } });
    }
    Plotly.react(this.plot, traces, layout({ hovermode: "closest", height: 360, xaxis: axis("run time (s)", { type: "log" }), yaxis: axis(`error at t_end (${errorUnit(run.data)})`, { type: "log" }) }), CONFIG);
    if (this.run !== run) return; // a newer run is being drawn
    const moved = Object.entries(run.data.parameters).filter(([p, v]) => run.params[p] !== v).map(([p, v]) => `${run.data.labels[p] || p} = ${fmt(v)}`);
    const at = moved.length ? ` The chart is for the default values (${moved.join(", ")}), not this run's; the star is this run.` : "";
    this.readout.textContent = `${here} Reference: ${report.reference}${at}`;
    // the methods by their names in words, each tolerance as a power of ten, and why a row has no figures
    table(this.summary, "Error against run time", ["method", "relative tolerance", "error", "run time (s)", "evaluations of the equations", "note"],
      report.runs.map((r) => [methodLabel(r.method), magnitude(r.rtol), r.error, r.wall_time_s, String(r.rhs_evaluations ?? "–"), r.note || ""]));
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
  modes: ModesPanel,
  poincare: PoincarePanel,
  action: ActionPanel,
};

export function createPanel(kind, section, data, urls = {}) {
  const Kind = KINDS[kind];
  if (!Kind) return null;
  return Kind.needsUrls || kind === "work-precision" ? new Kind(section, data, urls) : new Kind(section, data);
}
