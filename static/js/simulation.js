/**
 * simulation.js — run a simulation through the API and draw it into panels.
 *
 *   simulate(url, request, {signal})   POST the request; resolves to the result JSON,
 *                                      rejects with Error(message) carrying the API's
 *                                      4xx "detail" (so it can be shown in place)
 *   prepareRun(data, request, result)  the result plus what the panels derive from it
 *                                      (T and U from the engine's expressions, momenta,
 *                                      the run's extent), as plain arrays
 *   new SimulationView(root, data, urls)
 *       .draw(run)                     draw every panel found in root
 *                                      (<section data-panel="energy">, …; the animation
 *                                      in data-panel="animation-2d" or "animation-3d")
 *       .setIndex(i)                   move every time cursor to sample i
 *   connectSimulation({form, root, data, urls, status})
 *                                      bind the controls (controls.js) to re-simulate on
 *                                      change, with a progress state and errors in status;
 *                                      returns {run(request)}.
 *
 * data is the page's client JSON (app/viz/page_model.py): coordinates, labels, units,
 * parameters, trees, conserved, reduction, constraint_forces, mechanism, panels.
 */
import { Player } from "./animation.js";
import { bindControls, readRequest } from "./controls.js";
import { compile } from "./expr.js";
import { createPanel } from "./plots.js";
import { fmt } from "./summaries.js";

export async function simulate(url, request, { signal } = {}) {
  const res = await fetch(url, {
    method: "POST",
    headers: { "Content-Type": "application/json", Accept: "application/json" },
    body: JSON.stringify({ ...request, precision: "display" }),
    signal,
  });
  let body = null;
  try { body = await res.json(); } catch { body = null; }
  if (!res.ok) {
    const detail = body && body.detail ? body.detail : `the server answered ${res.status}`;
    const error = new Error(typeof detail === "string" ? detail : JSON.stringify(detail));
    error.status = res.status;
    error.errors = body && body.errors;
    throw error;
  }
  return body;
}

function seriesOrNull(tree, envs) {
  if (tree === null || tree === undefined) return null;
  try {
    const f = compile(tree);
    return envs.map((e) => f(e));
  } catch {
    return null;
  }
}

export function prepareRun(data, request, result) {
  const t = result.t;
  const n = t.length;
  const params = { ...data.parameters, ...(request.parameters || {}) };
  const state = result.state;
  const names = Object.keys(state);
  // the run's extent (qmin_<q>, qmax_<q>) sizes the drawing's fixed parts
  const extent = {};
  for (const q of data.coordinates) {
    let lo = Infinity, hi = -Infinity;
    for (const v of state[q]) { if (v < lo) lo = v; if (v > hi) hi = v; }
    extent[`qmin_${q}`] = lo;
    extent[`qmax_${q}`] = hi;
  }
  const envs = Array.from({ length: n }, (_, i) => {
    const e = { ...params, ...extent, t: t[i] };
    for (const k of names) e[k] = state[k][i];
    return e;
  });
  const trees = data.trees;
  const energy = result.energy || seriesOrNull(trees.energy, envs);
  const hamiltonian = result.hamiltonian || seriesOrNull(trees.hamiltonian, envs);
  const U = seriesOrNull(trees.potential, envs);
  let T = seriesOrNull(trees.kinetic, envs);
  if (!T && U && energy) T = energy.map((e, i) => e - U[i]);
  const momenta = {};
  for (const c of data.conserved) {
    if (!c.name.startsWith("p_")) continue;
    momenta[c.name] = (result.conserved && result.conserved[c.name]) || seriesOrNull(c.tree, envs);
  }
  return {
    data, request, n, t, params, state, energy, hamiltonian, U, T, momenta, extent,
    forces: result.constraint_forces || {}, stats: result.stats || {}, envAt: (i) => envs[i],
  };
}

export class SimulationView {
  constructor(root, data, urls = {}) {
    this.root = root;
    this.data = data;
    this.panels = [];
    this.player = null;
    for (const section of root.querySelectorAll("[data-panel]")) {
      const kind = section.dataset.panel;
      if (kind.startsWith("animation")) {
        if (data.mechanism) this.player = new Player(section, data.mechanism, { onFrame: (i) => this.setIndex(i) });
      } else {
        const panel = createPanel(kind, section, data, urls);
        if (panel) this.panels.push(panel);
      }
    }
    this.pendingIndex = null;
    this.lastCursor = 0;
  }

  draw(run) {
    this.run = run;
    for (const p of this.panels) {
      try {
        const done = p.draw(run);
        if (done && done.catch) done.catch((err) => console.warn(err));
      } catch (err) {
        const out = p.section.querySelector(".readout");
        if (out) out.textContent = `This panel could not be drawn: ${err.message}`;
      }
    }
    if (this.player) this.player.load(run);
  }

  setIndex(i) {
    // time cursors follow the animation at up to 8 updates per second, and always end on the last frame
    this.pendingIndex = i;
    const now = performance.now();
    if (now - this.lastCursor > 125) this.flush();
    else if (!this.timer) this.timer = setTimeout(() => this.flush(), 130);
  }

  flush() {
    clearTimeout(this.timer);
    this.timer = null;
    if (this.pendingIndex === null || !this.run) return;
    this.lastCursor = performance.now();
    for (const p of this.panels) {
      try { p.cursor(this.pendingIndex, this.run); } catch { /* a panel that failed to draw has no cursor */ }
    }
    this.pendingIndex = null;
  }
}

function describe(stats) {
  const parts = [`Method ${stats.method}`];
  if (stats.reason) parts.push(`(${stats.reason})`);
  parts.push(`run time ${fmt((stats.wall_time_s || 0) * 1000)} ms`);
  if (stats.error_estimate !== undefined) parts.push(`estimated error ${fmt(stats.error_estimate)}`);
  return parts.join(", ") + ".";
}

export function connectSimulation({ form, root, data, urls, status }) {
  const view = new SimulationView(root, data, urls);
  const message = status.querySelector(".message");
  const warnings = status.querySelector(".warnings");
  let controller = null;
  let generation = 0;

  async function run(request) {
    // about 60 samples per simulated second: smooth animation, compact arrays
    if (request.samples === undefined) request.samples = Math.min(4000, Math.max(300, Math.round(60 * (request.t_end || data.t_end))));
    controller?.abort();
    controller = new AbortController();
    const mine = ++generation;
    root.setAttribute("aria-busy", "true");
    status.dataset.state = "running";
    message.textContent = "Simulating…";
    try {
      const result = await simulate(urls.simulate, request, { signal: controller.signal });
      if (mine !== generation) return;
      const r = prepareRun(data, request, result);
      view.draw(r);
      status.dataset.state = "ready";
      message.textContent = describe(r.stats);
      warnings.replaceChildren(...(r.stats.warnings || []).map((w) => Object.assign(document.createElement("li"), { textContent: w })));
      root.dataset.runs = String(Number(root.dataset.runs || 0) + 1);
    } catch (err) {
      if (err.name === "AbortError" || mine !== generation) return;
      status.dataset.state = "error";
      message.textContent = `The simulation failed: ${err.message}`;
    } finally {
      if (mine === generation) root.setAttribute("aria-busy", "false");
    }
  }

  bindControls(form, run);
  run(readRequest(form));
  return { run, view };
}
