/**
 * poincare.js — the Poincaré-section panel (two conservative degrees of freedom).
 *
 *   new PoincarePanel(section, data, urls)   the plots.js interface: draw(run), cursor(i, run)
 *
 * urls.poincare(run) resolves to the server's section (app/service/simulations/poincare.py) on the energy
 * surface of the run's initial state, at the run's parameters: several orbits, each a set of
 * points (q, p) of one coordinate where the other crosses its plane upward (θ₂ = 0 with θ̇₂ > 0).  Computed on the
 * server (seconds, off the event loop) for the server's run only, and only once the panel is
 * in view; answers are kept per request so a repeated run costs nothing.
 */
import { axis, drawWhenVisible, layout, momentumUnit, PALETTE, PALETTE_NAMES, parts, react } from "./plotkit.js";
import { wrap } from "./phase.js";
import { fmt, table } from "./summaries.js";

export class PoincarePanel {
  static needsUrls = true;

  constructor(section, data, urls = {}) {
    this.section = section; this.data = data; this.urls = urls; Object.assign(this, parts(section));
    this.preview = false; // the section belongs to a server run (same energy, same parameters)
    this.answers = new Map();
    drawWhenVisible(this, section);
  }

  async draw(run) {
    this.run = run;
    if (!this.urls.poincare) return;
    if (!this.visible) { this.readout.textContent = "The chart is drawn when you scroll to it."; return; }
    const request = { parameters: run.request.parameters || {}, initial: run.request.initial || {} };
    const key = JSON.stringify(request);
    this.section.setAttribute("aria-busy", "true");
    this.readout.textContent = "Computing the section (several orbits on this run's energy surface)…";
    let answer = this.answers.get(key);
    try {
      if (!answer) {
        answer = this.urls.poincare(request);
        this.answers.set(key, answer);
      }
      answer = await answer;
    } catch (err) {
      this.answers.delete(key);
      if (this.run === run) {
        this.readout.textContent = `No section: ${err.message}`;
        this.section.setAttribute("aria-busy", "false");
      }
      return;
    }
    if (this.run !== run) return; // a newer run is being drawn
    this.plotSection(answer);
    this.section.setAttribute("aria-busy", "false");
  }

  plotSection(s) {
    const labels = this.data.labels, units = this.data.units;
    const q = s.axes.q, angle = units[q] === "rad";
    const traces = s.orbits.map((o, k) => ({
      type: "scatter", mode: "markers", name: `orbit ${k + 1}`,
      x: angle ? o.q.map(wrap) : o.q, y: o.p,
      marker: { size: 4, color: PALETTE[k % PALETTE.length] },
    }));
    const lq = labels[q] || q, lc = labels[s.coordinate] || s.coordinate;
    react(this, traces, layout({
      hovermode: "closest", height: 360,
      xaxis: axis(`${lq} (${units[q] || ""})`, angle ? { range: [-Math.PI, Math.PI] } : {}),
      // the momentum named as the page prints it, p_θ₁ (subscript set by axis), in its own unit
      yaxis: axis(`${labels[`p_${q}`] || `p_${lq}`} (${(this.data.momentum_units || {})[q] || momentumUnit(units[q])})`),
    }));
    const points = s.orbits.reduce((a, o) => a + o.q.length, 0);
    this.section.dataset.points = String(points);
    // the plane and the side it is crossed from, as a textbook writes it: θ₂ = 0 with θ̇₂ > 0, not
    // "crossing upward"
    const rate = labels[`${s.coordinate}_dot`] || `d${lc}/dt`;
    const cut = `${lc} = ${fmt(s.value)} with ${rate} ${s.direction > 0 ? ">" : "<"} 0`;
    // the orbits the server stopped before their full time, named as the legend and the table name them
    const named = (k) => `${k + 1} (${PALETTE_NAMES[k % PALETTE_NAMES.length]})`;
    const short = s.orbits.map((o, k) => (o.complete ? null : named(k))).filter((x) => x);
    const list = short.length > 1 ? `${short.slice(0, -1).join(", ")} and ${short.at(-1)}` : short[0];
    this.readout.textContent = `${s.orbits.length} orbits with h = ${fmt(s.energy)} J, ${points} points where ${cut}. `
      + "Points of one colour on a closed curve mean a regular orbit; a colour spread over an area means chaos."
      + (short.length
        ? ` ${short.length === s.orbits.length ? "All the orbits were" : short.length === 1 ? `Orbit ${list} was` : `Orbits ${list} were`}`
          + ` stopped before ${short.length === 1 ? "its" : "their"} full time (the server spends only a few seconds on one section),`
          + ` so the table marks ${short.length === 1 ? "it" : "them"} “stopped early” and ${short.length === 1 ? "it shows" : "they show"} fewer points.`
        : "");
    table(this.summary, `Poincaré section at ${cut}`, ["orbit", "starts at", "points", "largest relative drift of h"],
      s.orbits.map((o, k) => [named(k), Object.entries(o.initial).map(([n, v]) => `${labels[n] || n} = ${fmt(v)}`).join(", "),
        o.complete ? String(o.q.length) : `${o.q.length} (stopped early)`, fmt(o.energy_drift)]));
  }

  cursor() {}
}
