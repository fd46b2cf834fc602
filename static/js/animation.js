/**
 * animation.js — the mechanism, animated with Plotly from a run's state arrays.
 *
 *   const player = new Player(root, spec, { onFrame });
 *   player.load(run);      // run from simulation.js prepareRun(); draws frame 0
 *   player.play(); player.pause(); player.toggle(); player.seek(i);
 *
 * root holds .plot (the Plotly div), [data-action="play"] (a button),
 * input.scrub (a range over sample indices), select.speed, output.time.
 * spec is the scene's mechanism (app/viz/mechanism.py): points, links and fixed
 * curves as expression trees in {parameters, q, q_dot, t} (curves in s and the
 * run's extent qmin_<q>, qmax_<q>).  Positions are computed once per run from
 * the compact arrays; each frame restyles only the moving traces
 * (requestAnimationFrame, at most one restyle per displayed frame).
 */
import { compile } from "./expr.js";

const MASS_COLORS = ["#0b5cad", "#b34700", "#2e7d32", "#6a1b9a"];
const TRAIL_SECONDS = 1.5;
const MAX_TRAIL = 90;

function mix(hex, amount) {
  // blend a colour toward white: amount 0 -> white, 1 -> the colour (a fading trail without alpha)
  const n = parseInt(hex.slice(1), 16);
  const c = [(n >> 16) & 255, (n >> 8) & 255, n & 255].map((v) => Math.round(255 + (v - 255) * amount));
  return `rgb(${c.join(",")})`;
}

export class Player {
  constructor(root, spec, { onFrame = () => {} } = {}) {
    this.root = root;
    this.spec = spec;
    this.onFrame = onFrame;
    this.plot = root.querySelector(".plot");
    this.button = root.querySelector('[data-action="play"]');
    this.scrub = root.querySelector("input.scrub");
    this.speedSelect = root.querySelector("select.speed");
    this.timeOut = root.querySelector("output.time");
    this.playing = false;
    this.index = 0;
    this.points = spec.points.map((p) => p.xyz.map(compile));
    this.dim = spec.dim;
    this.button?.addEventListener("click", () => this.toggle());
    this.scrub?.addEventListener("input", () => { this.pause(); this.seek(Number(this.scrub.value)); });
    this.tick = this.tick.bind(this);
  }

  positions(run) {
    // xyz[p][axis] = Float64Array over samples
    const n = run.n;
    return this.points.map((fs) => fs.map((f) => {
      const out = new Float64Array(n);
      for (let i = 0; i < n; i++) out[i] = f(run.envAt(i));
      return out;
    }));
  }

  curves(run) {
    const env = { ...run.params, ...run.extent, t: 0 };
    return this.spec.curves.map((c) => {
      const lo = compile(c.from)(env), hi = compile(c.to)(env);
      const fs = c.xyz.map(compile);
      const cols = fs.map(() => []);
      for (let k = 0; k <= 160; k++) {
        const e = { ...env, s: lo + ((hi - lo) * k) / 160 };
        fs.forEach((f, a) => cols[a].push(f(e)));
      }
      return { label: c.label, cols };
    });
  }

  load(run) {
    this.run = run;
    this.xyz = this.positions(run);
    const dt = run.n > 1 ? run.t[1] - run.t[0] : 1;
    this.trailLength = Math.max(2, Math.min(MAX_TRAIL, Math.round(TRAIL_SECONDS / dt)));
    this.masses = this.spec.points.map((p, i) => (p.mass ? i : -1)).filter((i) => i >= 0);
    const curves = this.curves(run);
    const axes = this.spec.axes;
    const type = this.dim === 3 ? "scatter3d" : "scatter";
    const traces = curves.map((c) => this.trace(type, c.cols, {
      name: c.label, mode: "lines", line: { color: "#8c959f", width: 2, dash: this.dim === 3 ? "solid" : "dot" }, hoverinfo: "skip",
    }));
    this.first = traces.length;
    traces.push(this.trace(type, this.linkCols(0), { name: "links", mode: "lines", line: { color: "#1b1f24", width: 3 }, hoverinfo: "skip" }));
    this.masses.forEach((p, k) => {
      const color = MASS_COLORS[k % MASS_COLORS.length];
      const colors = Array.from({ length: this.trailLength }, (_, j) => mix(color, 0.08 + (0.7 * j) / this.trailLength));
      traces.push(this.trace(type, this.trailCols(p, 0), {
        name: `trail of ${this.spec.points[p].label}`, mode: "markers", hoverinfo: "skip",
        marker: { color: colors, size: this.dim === 3 ? 3 : 5, line: { width: 0 } },
      }));
    });
    // one marker trace per body (named in the legend), then the fixed points (pivots, pulleys)
    this.masses.forEach((p, k) => {
      traces.push(this.trace(type, this.pointCols([p], 0), {
        name: this.spec.points[p].label, mode: "markers", showlegend: true, hoverinfo: "name",
        marker: { color: MASS_COLORS[k % MASS_COLORS.length], size: this.dim === 3 ? 9 : 16, line: { color: "#1b1f24", width: 1 } },
      }));
    });
    this.fixed = this.spec.points.map((p, i) => (p.mass ? -1 : i)).filter((i) => i >= 0);
    traces.push(this.trace(type, this.pointCols(this.fixed, 0), {
      name: "fixed points", mode: "markers", marker: { color: "#1b1f24", size: this.dim === 3 ? 4 : 7 }, hoverinfo: "skip",
    }));
    this.moving = traces.map((_, i) => i).slice(this.first);
    Plotly.react(this.plot, traces, this.layout(curves, axes), { responsive: true, displaylogo: false });
    if (this.scrub) { this.scrub.max = String(run.n - 1); this.scrub.value = "0"; }
    this.seek(0);
  }

  trace(type, cols, extra) {
    const t = { type, x: cols[0], y: cols[1], showlegend: false, ...extra };
    if (this.dim === 3) t.z = cols[2];
    return t;
  }

  linkCols(i) {
    const cols = [[], [], []];
    for (const link of this.spec.links) {
      for (const p of [link.from, link.to]) this.xyz[p].forEach((a, k) => cols[k].push(a[i]));
      cols.forEach((c) => c.push(null));
    }
    return cols;
  }

  trailCols(p, i) {
    const cols = [[], [], []];
    for (let j = i - this.trailLength + 1; j <= i; j++) {
      const s = Math.max(0, j);
      this.xyz[p].forEach((a, k) => cols[k].push(a[s]));
    }
    return cols;
  }

  pointCols(which, i) {
    const cols = [[], [], []];
    for (const p of which) this.xyz[p].forEach((a, k) => cols[k].push(a[i]));
    return cols;
  }

  layout(curves, axes) {
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    const grow = (k, v) => { if (Number.isFinite(v)) { lo[k] = Math.min(lo[k], v); hi[k] = Math.max(hi[k], v); } };
    this.xyz.forEach((a) => a.forEach((arr, k) => arr.forEach((v) => grow(k, v))));
    curves.forEach((c) => c.cols.forEach((arr, k) => arr.forEach((v) => grow(k, v))));
    const spans = lo.slice(0, this.dim).map((l, k) => Math.max(hi[k] - l, 1e-6) * 1.12);
    const span = Math.max(...spans);
    const range = (k, width) => { const mid = (lo[k] + hi[k]) / 2; return [mid - width / 2, mid + width / 2]; };
    const axis = (k, width) => ({ title: { text: `${axes[k]} (m)` }, range: range(k, width), zeroline: false, gridcolor: "#e6e8eb" });
    const base = { margin: { l: 50, r: 20, t: 20, b: 45 }, height: 420, paper_bgcolor: "#fff", plot_bgcolor: "#fff", font: { size: 13 },
      legend: { orientation: "h", x: 0, y: 1.02, yanchor: "bottom" } };
    if (this.dim === 3) {
      // true proportions, except that no axis is drawn shorter than 40 % of the longest (a tall helix stays readable)
      const ratio = spans.map((w) => Math.max(w / span, 0.4));
      return { ...base, margin: { l: 0, r: 0, t: 30, b: 0 },
        scene: { xaxis: axis(0, spans[0]), yaxis: axis(1, spans[1]), zaxis: axis(2, spans[2]), aspectmode: "manual",
          aspectratio: { x: ratio[0], y: ratio[1], z: ratio[2] }, camera: { eye: { x: 1.2, y: 1.05, z: 0.65 } } } };
    }
    return { ...base, xaxis: axis(0, span), yaxis: { ...axis(1, span), scaleanchor: "x", scaleratio: 1 } };
  }

  seek(i) {
    if (!this.run) return;
    this.index = Math.max(0, Math.min(this.run.n - 1, i));
    const cols = [
      this.linkCols(this.index),
      ...this.masses.map((p) => this.trailCols(p, this.index)),
      ...this.masses.map((p) => this.pointCols([p], this.index)),
      this.pointCols(this.fixed, this.index),
    ];
    const update = { x: cols.map((c) => c[0]), y: cols.map((c) => c[1]) };
    if (this.dim === 3) update.z = cols.map((c) => c[2]);
    Plotly.restyle(this.plot, update, this.moving);
    if (this.scrub) {
      this.scrub.value = String(this.index);
      this.scrub.setAttribute("aria-valuetext", `t = ${this.run.t[this.index].toFixed(2)} s`);
    }
    if (this.timeOut) {
      // the current state in words: a text alternative that follows the animation
      const { data, state } = this.run;
      const parts = data.coordinates.map((q) => `${data.labels[q] || q} = ${state[q][this.index].toFixed(3)} ${data.units[q] || ""}`.trim());
      this.timeOut.textContent = [`t = ${this.run.t[this.index].toFixed(2)} s`, ...parts].join(" · ");
    }
    this.onFrame(this.index);
  }

  speed() {
    return this.speedSelect ? Number(this.speedSelect.value) : 1;
  }

  play() {
    if (!this.run || this.playing) return;
    this.playing = true;
    if (this.index >= this.run.n - 1) this.index = 0;
    this.simTime = this.run.t[this.index];
    this.last = null;
    if (this.button) { this.button.textContent = "Pause"; this.button.setAttribute("aria-pressed", "true"); }
    this.root.dataset.playing = "true";
    requestAnimationFrame(this.tick);
  }

  pause() {
    this.playing = false;
    if (this.button) { this.button.textContent = "Play"; this.button.setAttribute("aria-pressed", "false"); }
    this.root.dataset.playing = "false";
  }

  toggle() {
    if (this.playing) this.pause(); else this.play();
  }

  tick(now) {
    if (!this.playing || !this.run) return;
    if (this.last !== null) this.simTime += ((now - this.last) / 1000) * this.speed();
    this.last = now;
    const t = this.run.t, end = t[t.length - 1];
    if (this.simTime > end) this.simTime = 0; // loop
    const dt = t.length > 1 ? t[1] - t[0] : 1;
    const i = Math.min(t.length - 1, Math.round(this.simTime / dt));
    if (i !== this.index) this.seek(i);
    requestAnimationFrame(this.tick);
  }
}
