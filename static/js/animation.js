/**
 * animation.js — the mechanism drawn on our own <canvas>, played with requestAnimationFrame.
 *
 *   const player = new Player(root, spec, { onFrame, onDrag, controls });
 *   player.load(run);      // run from simulation.js prepareRun(); keeps the current instant
 *   player.play(); player.pause(); player.toggle(); player.seek(i);
 *
 * root holds canvas.mechanism, [data-action="play"], input.scrub (a range over sample
 * indices), select.speed and output.time.  spec is the scene's mechanism
 * (app/viz/mechanism.py): points, links and fixed curves as expression trees in
 * {parameters, q, q_dot, t} (curves in s and the run's extent qmin_<q>, qmax_<q>).
 * Positions are computed once per run; a frame only redraws the canvas (no plotting
 * library), so playback keeps up with the display.
 *
 * The Player holds a run's geometry and the instant shown; the rest is in modules of their own:
 * camera.js (world to screen, the 3-D view), clock.js (playback time), render.js (a frame, drawn
 * by scenery.js, links.js, bodies.js and arrows.js), drag.js (the values a dragged body or
 * velocity handle asks for) and input.js (pointer and keys).  onDrag({q: value, ...}) receives
 * the initial coordinates or rates a drag sets; controls(name) gives {value, min, max} of an
 * initial-condition control.
 *
 * For tests and tools: root.dataset.frame is the sample shown, root.dataset.playing whether it
 * plays; render.js records what it drew on the canvas's dataset.
 */
import { Camera, MARGIN } from "./camera.js";
import { Clock } from "./clock.js";
import { Drag } from "./drag.js";
import { compile, symbolsOf } from "./expr.js";
import { forceSeries } from "./arrows.js";
import { Input } from "./input.js";
import { drawFrame } from "./render.js";
import { HATCH, eventLine, messageBottom } from "./scenery.js";

const TRAIL_SECONDS = 1.5;
const MAX_TRAIL = 90;
const CURVE_SAMPLES = 160; // segments of a drawn curve

export class Player {
  constructor(root, spec, { onFrame = () => {}, onDrag = null, controls = null } = {}) {
    this.root = root;
    this.spec = spec;
    this.onFrame = onFrame;
    this.onDrag = onDrag;
    this.controls = controls; // name -> {value, min, max} of the initial-condition controls
    this.canvas = root.querySelector("canvas.mechanism");
    this.ctx = this.canvas.getContext("2d");
    this.button = root.querySelector('[data-action="play"]');
    this.scrub = root.querySelector("input.scrub");
    this.speedSelect = root.querySelector("select.speed");
    this.timeOut = root.querySelector("output.time");
    this.dragStatus = root.querySelector(".drag-status");
    this.index = 0;
    this.frames = 0;
    this.dim = spec.dim;
    this.camera = new Camera(spec.dim, spec.view);
    this.clock = new Clock({
      speed: () => (this.speedSelect ? Number(this.speedSelect.value) : 1),
      end: () => (this.run ? this.run.t[this.run.t.length - 1] : null),
      onTime: (t) => {
        const i = Math.min(this.run.t.length - 1, Math.round(t / this.dt));
        if (i !== this.index) this.seek(i);
      },
    });
    this.points = spec.points.map((p) => p.xyz.map(compile));
    this.tilts = spec.points.map((p) => (p.block ? compile(p.block) : null)); // blocks: the slope they rest on
    this.masses = spec.points.map((p, i) => (p.mass ? i : -1)).filter((i) => i >= 0);
    this.fixed = spec.points.map((p, i) => (p.mass || p.hidden ? -1 : i)).filter((i) => i >= 0);
    this.wheels = (spec.wheels || []).map((w) => ({ ...w, r: compile(w.radius), turn: w.turn ? compile(w.turn) : null }));
    this.showForces = root.querySelector("input.show-forces");
    this.showForces?.addEventListener("change", () => { if (this.run) this.draw(this.index); });
    this.selected = 0;
    this.button?.addEventListener("click", () => this.toggle());
    this.scrub?.addEventListener("input", () => { this.pause(); this.seek(Number(this.scrub.value)); });
    this.drag = new Drag(this);
    this.input = new Input(this);
    if ("ResizeObserver" in window) new ResizeObserver(() => this.resize()).observe(this.canvas);
    this.resize();
  }

  get playing() {
    return this.clock.playing;
  }

  /** The coordinates each body owns: those it depends on that no earlier body depends on. */
  owners(coordinates) {
    const earlier = new Set();
    return this.masses.map((p) => {
      const deps = new Set();
      for (const tree of this.spec.points[p].xyz) symbolsOf(tree, deps);
      const mine = coordinates.filter((q) => deps.has(q));
      const own = mine.filter((q) => !earlier.has(q));
      mine.forEach((q) => earlier.add(q));
      return own.length ? own : mine;
    });
  }

  resize() {
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(this.canvas.clientWidth * dpr));
    const h = Math.max(1, Math.round(this.canvas.clientHeight * dpr));
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w; this.canvas.height = h;
      this.fit();
      if (this.run) this.draw(this.index);
    }
  }

  // ---- a run's geometry ---------------------------------------------------------------------

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
    // a fixed curve is computed once per run; a moving one (its position uses t or a coordinate:
    // the turning wire) is computed again at every frame from the frame's environment
    const base = { ...run.params, ...run.extent, t: 0 };
    return this.spec.curves.map((c) => {
      const fs = c.xyz.map(compile), from = compile(c.from), to = compile(c.to);
      const at = (env) => {
        const lo = from(env), hi = to(env);
        const cols = fs.map(() => new Float64Array(CURVE_SAMPLES + 1));
        for (let k = 0; k <= CURVE_SAMPLES; k++) {
          const e = { ...env, s: lo + ((hi - lo) * k) / CURVE_SAMPLES };
          fs.forEach((f, a) => { cols[a][k] = f(e); });
        }
        return cols;
      };
      return { label: c.label, style: c.style || "guide", moving: !!c.moving, at, cols: at(c.moving ? run.envAt(0) : base) };
    });
  }

  /** The rods found only numerically on the server, confirmed along this run: indices of links whose length changes. */
  unsteadyLinks(run) {
    const out = new Set();
    this.spec.links.forEach((link, j) => {
      if (!link.check) return;
      const a = this.xyz[link.from], b = this.xyz[link.to];
      let lo = Infinity, hi = -Infinity;
      for (let i = 0; i < run.n; i++) {
        const d = Math.hypot(...a.map((col, k) => col[i] - b[k][i]));
        lo = Math.min(lo, d); hi = Math.max(hi, d);
      }
      if (!(hi - lo <= 1e-6 * Math.max(1, hi))) out.add(j);
    });
    return out;
  }

  fit() {
    // everything the run visits in view: the bodies along the run, the curves (a moving one at 24 instants)
    if (!this.xyz) return;
    const n = this.run.n, dpr = window.devicePixelRatio || 1;
    this.camera.fit((grow) => {
      const stride = Math.max(1, Math.floor(n / 400));
      for (const a of this.xyz) for (let i = 0; i < n; i += stride) grow(a[0][i], a[1][i], a[2] ? a[2][i] : 0);
      for (const a of this.xyz) { const i = n - 1; grow(a[0][i], a[1][i], a[2] ? a[2][i] : 0); }
      for (const c of this.curveCols) {
        const frames = c.moving ? Array.from({ length: 24 }, (_, j) => Math.round((j * (n - 1)) / 23)) : [null];
        for (const f of frames) {
          const cols = f === null ? c.cols : c.at(this.run.envAt(f));
          for (let k = 0; k < cols[0].length; k++) grow(cols[0][k], cols[1][k], cols[2] ? cols[2][k] : 0);
        }
      }
    }, this.canvas.width, this.canvas.height, dpr, this.messageRoom(dpr));
  }

  /** Device pixels kept free at the top for the band that says why a run ended (drawn on its last frame), so that
   * it covers no part of the drawing (the massive pulley's ceiling and its hatching lay under it). Kept for every
   * event the scene declares, whether or not this run met one, so the view stays put from run to run. */
  messageRoom(dpr) {
    const end = this.run.t[this.run.n - 1];
    const lines = (this.run.data.events || []).map((e) => eventLine({ t: end, message: e.message }));
    const ended = this.run.stats && this.run.stats.event;
    if (ended) lines.push(eventLine(ended));
    if (!lines.length) return 0;
    const ctx = this.canvas.getContext("2d");
    const bottom = Math.max(...lines.map((line) => messageBottom(ctx, this.canvas, dpr, line)));
    // the drawing's top edge already stands MARGIN down (Camera.fit's); a ceiling's hatching reaches HATCH above
    // it, and stays 6 px below the band
    return Math.max(0, bottom + (HATCH + 6 - MARGIN) * dpr);
  }

  load(run) {
    const keep = this.run ? this.run.t[this.index] : 0;
    this.run = run;
    this.xyz = this.positions(run);
    this.curveCols = this.curves(run);
    this.unsteady = this.unsteadyLinks(run);
    this.forces = forceSeries(this.spec, run, compile);
    const dt = run.n > 1 ? run.t[1] - run.t[0] : 1;
    this.dt = dt;
    this.root.dataset.dt = String(dt); // the samples' spacing: a link to an instant (statelink.js) reads it
    this.trailLength = Math.max(2, Math.min(MAX_TRAIL, Math.round(TRAIL_SECONDS / dt)));
    this.ownersOf = this.owners(run.data.coordinates);
    // while a body is dragged the view stays put, so the body follows the pointer
    if (!this.dragging || !this.camera.frame) this.fit();
    if (this.scrub) this.scrub.max = String(run.n - 1);
    // a new run (an input changed) keeps the instant shown, so dragging a slider does not jump back
    this.seek(Math.min(run.n - 1, Math.round(keep / dt)));
  }

  /** Point p's position on the canvas (device pixels) at sample i. */
  at(p, i) {
    const a = this.xyz[p];
    return this.camera.screenOf([a[0][i], a[1][i], a[2] ? a[2][i] : 0]);
  }

  draw(i) {
    drawFrame(this, i);
    this.frames++;
  }

  // ---- playback ---------------------------------------------------------------------------

  seek(i) {
    if (!this.run) return;
    this.index = Math.max(0, Math.min(this.run.n - 1, i));
    this.draw(this.index);
    this.root.dataset.frame = String(this.index);
    if (this.scrub) {
      this.scrub.value = String(this.index);
      this.scrub.setAttribute("aria-valuetext", `t = ${this.run.t[this.index].toFixed(2)} s`);
    }
    if (this.timeOut) {
      // the current state in words: a text alternative that follows the animation
      const { data, state } = this.run;
      // a typeset minus sign, as everywhere else on the page
      const parts = data.coordinates.map((q) => `${data.labels[q] || q} = ${state[q][this.index].toFixed(3).replace("-", "−")} ${data.units[q] || ""}`.trim());
      this.timeOut.textContent = [`t = ${this.run.t[this.index].toFixed(2)} s`, ...parts].join(" · ");
    }
    this.onFrame(this.index);
  }

  play() {
    if (!this.run || this.playing) return;
    if (this.index >= this.run.n - 1) this.index = 0;
    this.clock.start(this.run.t[this.index]);
    if (this.button) { this.button.textContent = "Pause"; this.button.setAttribute("aria-pressed", "true"); }
    this.root.dataset.playing = "true";
  }

  pause() {
    this.clock.stop();
    if (this.button) { this.button.textContent = "Play"; this.button.setAttribute("aria-pressed", "false"); }
    this.root.dataset.playing = "false";
  }

  toggle() {
    if (this.playing) this.pause(); else this.play();
  }
}
