/**
 * simulation.js — run a simulation through the API and draw it into panels.
 *
 *   simulate(url, request, {signal})   POST the request (api.js fetchJSON: a 429/503 retried);
 *                                      resolves to the result JSON, rejects with RequestError
 *                                      carrying the API's 4xx "detail" (shown in place)
 *   prepareRun(data, request, result)  the result plus what the panels derive from it
 *                                      (T and U from the engine's expressions, momenta,
 *                                      the run's extent), as plain arrays
 *   new SimulationView(root, data, urls, {onDrag, controls})
 *       .draw(run, source)             draw the animation, the energy bars and the plot
 *                                      panels in view (<section data-panel="energy">, …);
 *                                      panels out of view are drawn when they scroll in
 *                                      (after a server run, also when the browser is idle);
 *                                      a preview leaves panels that need the server greyed
 *       .setIndex(i)                   move the energy bars and every time cursor to sample i
 *   connectSimulation({form, root, data, urls, status, fetchRun})
 *                                      bind the controls: every input repaints a preview
 *                                      integrated in the browser (preview.js) at the next
 *                                      frame; 150 ms after the last change the server's run
 *                                      replaces it.  After each repaint an input caused, the
 *                                      document receives CustomEvent('lagrange:painted',
 *                                      {detail: {source: 'preview' | 'server'}}).
 *
 * data is the page's client JSON (app/viz/page_model.py): coordinates, labels, units,
 * parameters, trees, conserved, reduction, constraint_forces, mechanism, panels.
 */
import { fetchJSON } from "./api.js";
import { Player } from "./animation.js";
import { bindControls, controlRange, readRequest } from "./controls.js";
import { EnergyBars } from "./energybars.js";
import { compile } from "./expr.js";
import { isFolded } from "./fold.js";
import { createPanel } from "./plots.js";
import { compileRhs, integrate } from "./preview.js";
import { followSeparatrix } from "./separatrix.js";
import { fmt, sharedUnit, statusLine } from "./summaries.js";

export function simulate(url, request, { signal } = {}) {
  return fetchJSON(url, { body: { ...request, precision: "display" }, signal });
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
    // momenta: a cyclic coordinate's p, a translation's P, a rotation's angular momentum J (app/engine/equations/noether.py)
    if (!/^(p_|P_|J)/.test(c.name)) continue;
    momenta[c.name] = (result.conserved && result.conserved[c.name]) || seriesOrNull(c.tree, envs);
  }
  // the energy resolution (J): the run's size of energy times its relative error (the server's verdict
  // compares the error estimate with the motion; a preview has none, so a fixed-step RK4's 10⁻⁶), never
  // below round-off.  Energies within it are read as "≈ 0", not as digits of noise.
  let scale = 0;
  for (const s of [energy, U, T]) if (s) for (const v of s) if (Number.isFinite(v)) scale = Math.max(scale, Math.abs(v));
  const relative = result.trust ? result.trust.ratio : 1e-6;
  const resolution = scale * Math.max(1e-9, Number.isFinite(relative) ? relative : 1e-6);
  return {
    data, request, n, t, params, state, energy, hamiltonian, U, T, momenta, extent, resolution,
    forces: result.constraint_forces || {}, stats: result.stats || {}, envAt: (i) => envs[i],
  };
}

const plotly = new Promise((resolve) => {
  // plotly.js loads with `async`: the animation and the math never wait for it
  if (window.Plotly) return resolve(window.Plotly);
  const script = document.getElementById("plotly-js");
  if (script) script.addEventListener("load", () => resolve(window.Plotly));
  window.addEventListener("load", () => { if (window.Plotly) resolve(window.Plotly); });
});

const idle = window.requestIdleCallback || ((f) => setTimeout(f, 50));

export class SimulationView {
  constructor(root, data, urls = {}, { onDrag = null, controls = null } = {}) {
    this.root = root;
    this.data = data;
    this.panels = [];
    this.player = null;
    this.index = 0;
    const barsEl = root.querySelector(".energy-bars");
    this.bars = barsEl ? new EnergyBars(barsEl) : null;
    for (const section of root.querySelectorAll("[data-panel]")) {
      const kind = section.dataset.panel;
      if (kind.startsWith("animation") && data.mechanism) {
        this.player = new Player(section, data.mechanism, { onFrame: (i) => this.setIndex(i), onDrag, controls });
      }
    }
    // panels near the viewport; of those, the ones not folded (fold.js, a phone) are visible and drawn
    this.near = new Set();
    this.visible = new Set();
    this.observer = "IntersectionObserver" in window
      ? new IntersectionObserver((entries) => this.seen(entries), { rootMargin: "100px" }) : null;
    root.addEventListener("lagrange:unfold", () => this.seen([]));
    this.ready = plotly.then(() => {
      for (const section of root.querySelectorAll("[data-panel]")) {
        const kind = section.dataset.panel;
        if (kind.startsWith("animation")) continue;
        const panel = createPanel(kind, section, data, urls);
        if (!panel) continue;
        this.panels.push(panel);
        if (this.observer) this.observer.observe(section); else this.near.add(panel.section);
      }
      if (!this.observer) this.seen([]);
    });
  }

  seen(entries) {
    for (const e of entries) {
      if (e.isIntersecting) this.near.add(e.target); else this.near.delete(e.target);
    }
    this.visible = new Set([...this.near].filter((s) => !isFolded(s)));
    for (const p of this.panels) if (this.visible.has(p.section) && p.dirty) this.drawPanel(p);
  }

  drawPanel(p) {
    const run = p.dirty;
    p.dirty = null;
    p.previewing = run.source === "preview";
    p.section.classList.remove("stale");
    // a preview leaves the data tables (the text alternative) to the server's run
    const summary = p.summary;
    if (p.previewing) p.summary = null;
    try {
      const done = p.draw(run);
      if (done && done.catch) done.catch((err) => console.warn(err));
      p.cursor(Math.min(this.index, run.n - 1), run);
    } catch (err) {
      const out = p.section.querySelector(".readout");
      if (out) out.textContent = `This panel could not be drawn: ${err.message}`;
    } finally {
      p.summary = summary;
    }
  }

  /** Draw a run; source is "preview" (the browser's) or "server". Resolves when the panels in view are drawn. */
  draw(run, source = "server") {
    this.run = run;
    run.source = source;
    this.root.dataset.source = source;
    if (this.player) this.player.load(run);
    else this.setIndex(0);
    if (this.bars) { this.bars.load(run); this.bars.set(this.index); }
    return this.ready.then(() => {
      if (this.run !== run) return;
      for (const p of this.panels) {
        if (source === "preview" && !p.preview) { p.section.classList.add("stale"); continue; }
        p.dirty = run;
        if (this.visible.has(p.section)) this.drawPanel(p);
      }
      // after the server's run, panels out of view are drawn while the browser is idle (a folded one has no
      // size to draw into: it is drawn when unfolded)
      if (source === "server") {
        const later = this.panels.filter((p) => p.dirty === run && !isFolded(p.section));
        const next = () => {
          const p = later.shift();
          if (!p || this.run !== run) return;
          if (p.dirty === run && !isFolded(p.section)) this.drawPanel(p);
          idle(next);
        };
        idle(next);
      }
    });
  }

  setIndex(i) {
    // called by the animation for every frame it shows: only overlays and bars move
    this.index = i;
    if (this.bars) this.bars.set(i);
    if (!this.run) return;
    for (const p of this.panels) {
      if (p.dirty || !this.visible.has(p.section)) continue;
      try { p.cursor(Math.min(i, this.run.n - 1), this.run); } catch { /* a panel that failed to draw has no cursor */ }
    }
  }
}

/** The figures behind the run status's "details": method and why, steps, evaluations, the exact error estimate. */
function details(stats, labels = {}) {
  // the method by its name in the menu (the API's value is stats.method), and why it was chosen: one sentence
  const parts = [`Method: ${labels[stats.method] || stats.method}` + (stats.reason ? `; ${stats.reason}` : "") + "."];
  parts.push(`${stats.steps ?? "–"} steps.`);
  if (Number.isFinite(stats.error_estimate)) parts.push(`Estimated error ${fmt(stats.error_estimate)}: the largest difference between this run's coordinates and the true motion's over the samples, in the coordinates' units.`);
  return parts.join(" ");
}

/** The terminal event that ended a run, in words ("" when the run reached t_end). */
export function ended(stats) {
  const e = stats && stats.event;
  return e ? ` At t = ${fmt(e.t)} s: ${e.message}` : "";
}

const painted = (source) => document.dispatchEvent(new CustomEvent("lagrange:painted", { detail: { source } }));

/** About 60 samples per simulated second: smooth animation, compact arrays. */
export const samplesFor = (tEnd) => Math.min(4000, Math.max(300, Math.round(60 * tEnd)));

/** Bind a scene's simulation section (its data-* URLs) and page data: the scene page's and the embed page's. */
export function connectScene(root, data) {
  return connectSimulation({
    form: document.getElementById("controls"),
    root,
    data,
    urls: {
      simulate: root.dataset.simulateUrl,
      workPrecision: root.dataset.workPrecisionUrl,
      modes: (parameters) => fetchJSON(root.dataset.modesUrl, { body: { parameters } }),
      poincare: (request) => fetchJSON(root.dataset.poincareUrl, { body: request }),
    },
    status: document.getElementById("run-status"),
  });
}

export function connectSimulation({ form, root, data, urls = {}, status, fetchRun = null, serial = false }) {
  const message = status.querySelector(".message");
  const warnings = status.querySelector(".warnings");
  const post = fetchRun || ((request, signal) => simulate(urls.simulate, request, { signal }));
  let controls = null;
  // the initial-condition controls the animation may move: each coordinate and its rate
  const initial = new Set(data.coordinates.flatMap((q) => [q, `${q}_dot`]));
  const view = new SimulationView(root, data, urls, {
    onDrag: (values) => controls && controls.set(values),
    controls: (name) => (initial.has(name) ? controlRange(form, name) : null),
  });
  let controller = null;
  let generation = 0;
  let rhs = null, previewSpec = null;
  let pendingPreview = null;

  const more = status.querySelector(".run-details");
  // list: lines under the message, each a string (a warning) or {text, kind: "event"} (where the run ended)
  // warned: a finished run with warnings keeps the state "ready" (what waits for a run reads it) and takes the
  // warning's colour from data-warned, never the green of a good run over a warning
  function say(state, text, list, detail = "", warned = false) {
    status.dataset.state = state;
    status.dataset.warned = String(warned);
    message.textContent = text;
    if (list) {
      warnings.replaceChildren(...list.map((w) => Object.assign(document.createElement("li"),
        typeof w === "string" ? { textContent: w } : { textContent: w.text, className: w.kind })));
    }
    if (more) { more.hidden = !detail; more.querySelector(".details-text").textContent = detail; }
  }

  function preview(request) {
    // a server run asked for before this input is out of date: it is not drawn (drawing every
    // plot, a 3-D one among them, blocked the next preview frames for up to 0.3 s); the run
    // for the latest settings follows when the input settles
    ++generation;
    // at most one preview per displayed frame: the latest input wins
    const first = pendingPreview === null;
    pendingPreview = request;
    if (!first) return;
    requestAnimationFrame(() => {
      const req = pendingPreview;
      pendingPreview = null;
      if (!rhs) return;
      if (req.samples === undefined) req.samples = samplesFor(req.t_end || data.t_end);
      const t0 = performance.now();
      let result;
      try { result = integrate(previewSpec, rhs, data, req, req.samples); } catch (err) { result = { error: err.message }; }
      const t1 = performance.now();
      root.classList.remove("stale");
      if (result.error) {
        say("preview", `No preview: ${result.error}. The full run follows when you stop.`);
        return;
      }
      const prepared = prepareRun(data, req, result);
      const t2 = performance.now();
      view.draw(prepared, "preview");
      // where the preview's time goes (integrate / prepare / draw, ms): read by benchmarks/bench_browser.py
      root.dataset.previewTiming = [t1 - t0, t2 - t1, performance.now() - t2].map((x) => x.toFixed(1)).join(" ");
      say("preview", "Preview: in your browser; the full run follows when you stop." + ended(result.stats), null,
        "The preview is integrated in your browser with a fixed-step Runge–Kutta method; the full run, with its error estimate, replaces it.");
      painted("preview");
    });
  }

  let inFlight = false, queued = null;

  async function run(request) {
    if (request.samples === undefined) request.samples = samplesFor(request.t_end || data.t_end);
    // serial: a server that runs one job per session (the playground's worker pool) gets the
    // latest settings after the current run ends, instead of an aborted request and a 429
    if (serial && inFlight) { queued = request; return; }
    inFlight = true;
    controller?.abort();
    controller = new AbortController();
    const mine = ++generation;
    root.setAttribute("aria-busy", "true");
    root.classList.remove("stale");
    if (status.dataset.state !== "preview") say("running", "Simulating…");
    try {
      const result = await post(request, controller.signal);
      if (mine !== generation || queued) return; // newer settings are on their way
      if (result.preview && result.preview.rhs !== previewSpec?.rhs) {
        try { rhs = compileRhs(result.preview); previewSpec = result.preview; } catch { rhs = null; }
      }
      const r = prepareRun(data, request, result);
      await view.draw(r, "server");
      if (mine !== generation) return;
      // one line at a glance; the method and its figures behind "details"; the server's verdict on the
      // error against the motion (result.trust) turns it into a plain warning
      const line = statusLine(r.stats, sharedUnit(data));
      const warned = r.stats.warnings || [];
      const notes = [...(r.stats.event ? [{ text: ended(r.stats).trim(), kind: "event" }] : []), ...warned];
      const trust = result.trust || {};
      // one colour for the whole box: never the green of a good run over a warning
      if (trust.trusted === false) say("untrusted", `${line}. ${trust.message}`, notes, details(r.stats, data.method_labels));
      else say("ready", line, notes, details(r.stats, data.method_labels), warned.length > 0);
      root.dataset.runs = String(Number(root.dataset.runs || 0) + 1);
      painted("server");
    } catch (err) {
      if (err.name === "AbortError" || mine !== generation) return;
      say("error", `The simulation failed: ${err.message}`, []);
      root.classList.add("stale");
    } finally {
      if (mine === generation) root.setAttribute("aria-busy", "false");
      inFlight = false;
      if (queued) { const next = queued; queued = null; run(next); }
    }
  }

  // the initial rate's separatrix marks follow the start and the parameters
  const marks = followSeparatrix(form, data.separatrix);
  controls = bindControls(form, {
    onInput: (request) => { marks(request); preview(request); },
    onSettle: (request) => { marks(request); run(request); },
    onInvalid: (why) => {
      ++generation;
      controller?.abort();
      root.setAttribute("aria-busy", "false");
      root.classList.add("stale");
      say("invalid", `Not re-run: ${why}.`, []);
    },
  });
  run(readRequest(form));
  return { run, view };
}
