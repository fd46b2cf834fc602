/**
 * action.js — the panel "The action": S = ∫ L dt along the true path and along varied paths.
 *
 *   new ActionPanel(section, data, urls)   the plots.js interface: draw(run), cursor(i, run)
 *
 * The true path q(t) on [0, T] starts from the run's initial state; a varied path moves one
 * coordinate by ε η(t), η = sin(kπt/T), zero at both ends.  Three plots in one figure: q against
 * t (the varied path is dragged up and down, which sets ε), L(t) along both paths, and S(ε) with
 * the current ε marked and the flat tangent at ε = 0.  A T slider moves the end time; past the
 * first kinetic focus t* (where the Jacobi fields from t = 0 vanish) the readout says the true
 * path is no longer a minimum of S, and t* is marked on the time axis.
 *
 * Live: everything is computed in the browser from engine-generated JavaScript: the equations
 * of motion (preview.js compileRhs) and L (app/numerics/action.py), both printed on the server
 * from the engine's expressions.  They arrive with the first answer of POST .../action; after
 * each change the server's numbers (S(ε) on the same ε's, the second variation, the kind, t*)
 * replace the browser's (section.dataset.source says which are shown).
 *
 * The browser's numbers: static/js/action-live.js.
 */
import { fetchJSON, inTurn } from "./api.js";
import { SETTLE_MS } from "./controls.js";
import { axis, CONFIG, drawWhenVisible, layout, PALETTE, rateUnit } from "./plotkit.js";
import { compileLagrangian, focus, focusAlone, liveAction, openingDuration, path, T_STEPS } from "./action-live.js";
import { focusSentences } from "./action-focus.js";
import { verdict } from "./action-verdict.js";
import { compile } from "./expr.js";
import { compileRhs } from "./preview.js";
import { fmt, table } from "./summaries.js";
import { proseReadout } from "./prose.js";

/** Whether the server's dS/dε at ε = 0 is zero within its quadrature's error (it is, on the true path of an
 *  unforced system): rounding noise is not shown as a number. */
function flatWithin(s) {
  return Math.abs(s.first_variation) <= Math.max(10 * s.error_estimate, 1e-9 * Math.abs(s.true));
}

const CURVE = 41; // ε values on the S(ε) curve
const ASK_MS = 250; // the server's numbers are asked for once the input has rested this long
const CONTROLS = 4; // points of a trial path besides its two ends
const RELAX_STEPS = 200; // steps of the relaxed path
const FIND_PAD = 0.04; // of τ, either side of the time axis in "Find the path" (room for the end points' markers)
const FRAME_MS = 350; // per Newton step in the animation
const REPLAY_MS = 1500; // the whole replay of Newton's steps at most

export class ActionPanel {
  static needsUrls = true;

  constructor(section, data, urls = {}) {
    this.section = section; this.data = data;
    this.plot = section.querySelector(".plot");
    this.readout = proseReadout(section.querySelector(".readout"));
    // how a found path was computed (Newton's steps, the grid, shooting), behind a disclosure under the readout's
    // lead; any other sentence in the readout hides it
    this.method = Object.assign(document.createElement("details"), { className: "action-method", hidden: true });
    this.method.append(Object.assign(document.createElement("summary"), { textContent: "How this was computed" }));
    this.methodText = proseReadout(this.method.appendChild(document.createElement("p")));
    this.readout.after(this.method);
    const prose = Object.getOwnPropertyDescriptor(this.readout, "textContent");
    Object.defineProperty(this.readout, "textContent", {
      configurable: true,
      get: prose.get,
      set: (value) => { prose.set.call(this.readout, value); this.method.hidden = true; },
    });
    this.summary = section.querySelector(".data-summary .table");
    this.preview = true;
    const sim = section.closest("#simulation") || document.getElementById("simulation");
    const simulateUrl = urls.simulate || sim?.dataset.simulateUrl || "/api/simulate";
    this.url = simulateUrl.replace(/simulate$/, "action");
    const declared = document.getElementById("playground-system");
    this.system = declared ? JSON.parse(declared.textContent || "{}") : null;
    this.fns = null; this.answers = new Map(); this.serial = 0;
    this.coordinate = 0; this.shape = 1; this.eps = 0;
    this.tEnd = data.t_end || 10;
    // until the reader moves τ, it follows the start's first kinetic focus (openingDuration: before it)
    this.T = openingDuration(this.tEnd, null); this.TChosen = false;
    this.controls();
    this.bindDrag();
    drawWhenVisible(this, section); // the server is asked only once the panel is in view
  }

  controls() {
    const tools = this.section.querySelector(".panel-tools");
    const id = (x) => `action-${x}`;
    const names = this.data.coordinates;
    const group = (html) => `<span style="white-space:nowrap">${html}</span>`;
    tools.insertAdjacentHTML("beforeend", `
      <div class="action-controls" style="display:flex;flex-wrap:wrap;gap:0.4rem 1rem;align-items:center">
        ${names.length > 1 ? group(`<label for="${id("coordinate")}">Vary</label> <select id="${id("coordinate")}">${names.map((q, i) => `<option value="${i}">${this.label(q)}</option>`).join("")}</select>`) : ""}
        <span class="action-vary" style="display:contents">
        ${group(`<label for="${id("k")}">Shape n</label> <select id="${id("k")}">${Array.from({ length: 6 }, (_, j) => `<option value="${j + 1}">${j + 1}</option>`).join("")}</select>`)}
        ${group(`<label for="${id("eps")}">ε</label> <input type="range" id="${id("eps")}" min="-1" max="1" step="0.01" value="0"> <output id="${id("eps-value")}" for="${id("eps")}"></output>`)}
        </span>
        <p class="action-find-note hint" id="${id("find-note")}" hidden>In “Find the path” the trial path is set by its points, so the shape n and ε are not used (press “Back to ε” for them).</p>
        ${group(`<button type="button" id="${id("find")}" aria-pressed="false">Find the path</button> <button type="button" id="${id("relax")}" hidden>Relax</button>`)}
        <button type="button" id="${id("from-shooting")}" hidden>Start from the shooting solution</button>
        ${group(`<label for="${id("T")}">Duration τ</label> <input type="range" id="${id("T")}" min="${this.tEnd / T_STEPS}" max="${this.tEnd}" step="${this.tEnd / T_STEPS}" value="${this.T}"> <output id="${id("T-value")}" for="${id("T")}"></output>`)}
      </div>`);
    this.epsInput = tools.querySelector(`#${id("eps")}`);
    this.TInput = tools.querySelector(`#${id("T")}`);
    this.TOut = tools.querySelector(`#${id("T-value")}`);
    this.epsOut = tools.querySelector(`#${id("eps-value")}`);
    this.varyControls = tools.querySelector(".action-vary");
    this.findNote = tools.querySelector(`#${id("find-note")}`);
    this.findButton = tools.querySelector(`#${id("find")}`);
    this.relaxButton = tools.querySelector(`#${id("relax")}`);
    this.findButton.addEventListener("click", () => this.toggleFind());
    this.relaxButton.addEventListener("click", () => this.relax());
    this.shootButton = tools.querySelector(`#${id("from-shooting")}`);
    this.shootButton.addEventListener("click", () => this.fromShooting());
    tools.querySelector(`#${id("k")}`).addEventListener("change", (e) => { this.shape = Number(e.target.value); this.update(true); });
    tools.querySelector(`#${id("coordinate")}`)?.addEventListener("change", (e) => { this.coordinate = Number(e.target.value); this.eps = 0; this.epsInput.value = "0"; this.update(true); });
    // the slider holds ε itself, in the coordinate's unit (its range follows the path: ±epsMax)
    this.epsInput.addEventListener("input", () => { this.eps = Number(this.epsInput.value); this.update(false); });
    this.TInput.addEventListener("input", () => {
      this.T = Number(this.TInput.value); this.TChosen = true;
      // in "Find the path" a new τ moves the fixed end: the trial path and any relaxed answer belong to the old τ
      if (this.finding) { this.found = null; this.frame = null; this.seed = null; this.shootButton.hidden = true; this.controlsT = null; }
      this.update(true);
    });
    if (this.data.forced) this.findButton.hidden = true; // relaxing makes S alone stationary: not the motion here
  }

  label(q) { return (this.data.labels && this.data.labels[q]) || q; }

  /** The browser's first kinetic focus of the variations of coordinate c alone over the whole run (kept per start). */
  aloneAt(c) {
    if (this.data.coordinates.length === 1) return this.focusAt;
    this.aloneFoci ??= new Map();
    const { y0, k } = this.setup(), key = `${c}|${this.focusKey}`;
    if (!this.aloneFoci.has(key)) {
      if (this.aloneFoci.size > 16) this.aloneFoci.clear();
      this.aloneFoci.set(key, focusAlone(this.fns, y0, k, this.tEnd, c, 800));
    }
    return this.aloneFoci.get(key);
  }

  /** Which sine shape lowers S, naming the one on screen first (second[j] = d²S/dε² for n = j + 1). */
  lowering(second) {
    const n = this.shape, here = second[n - 1];
    const first = second.findIndex((x) => x < 0) + 1;
    if (here < 0) return `The variation on screen, n = ${n}, lowers S: drag it and S falls on both sides of the true path.`;
    if (first > 0) return `The variation on screen, n = ${n}, still raises S, but the shape n = ${first} lowers it.`;
    return `The variation on screen, n = ${n}, raises S, and so does every single sine shape tried; a combination of them lowers it.`;
  }

  bindDrag() {
    // dragging the varied path: ε = (y − q(t)) / η(t) at the pointer, where |η| is not small
    let dragging = false;
    const at = (event) => {
      const full = this.plot._fullLayout;
      if (!full || !this.live) return;
      if (this.finding) { this.moveControl(event, full); return; }
      const xa = full.xaxis, ya = full.yaxis, box = this.plot.getBoundingClientRect();
      const t = xa.p2d(event.clientX - box.left - xa._offset), y = ya.p2d(event.clientY - box.top - ya._offset);
      const eta = Math.sin((this.shape * Math.PI * t) / this.T);
      if (!(t > 0 && t < this.T) || Math.abs(eta) < 0.3) return;
      const i = Math.round((t / this.T) * (this.live.path.t.length - 1));
      const q = this.live.path.Y[i][this.coordinate];
      this.eps = Math.max(-this.epsMax, Math.min(this.epsMax, (y - q) / eta));
      this.epsInput.value = String(this.eps);
      this.update(false);
    };
    this.plot.addEventListener("pointerdown", (e) => {
      const full = this.plot._fullLayout;
      if (!full) return;
      const ya = full.yaxis, box = this.plot.getBoundingClientRect(), y = e.clientY - box.top;
      if (y < ya._offset || y > ya._offset + ya._length) return; // only on the upper plot (the paths)
      dragging = true; this.plot.setPointerCapture?.(e.pointerId); e.preventDefault();
      if (this.finding) this.pickControl(e, full);
      at(e);
    });
    this.plot.addEventListener("pointermove", (e) => { if (dragging) at(e); });
    const stop = () => { if (dragging) { dragging = false; if (!this.finding) this.settle(); } };
    this.plot.addEventListener("pointerup", stop);
    this.plot.addEventListener("pointercancel", stop);
    this.epsInput.addEventListener("change", () => this.settle());
  }

  setup() {
    const run = this.run, data = this.data, n = data.coordinates.length;
    const params = { ...data.parameters, ...(run?.request?.parameters || {}) };
    const initial = { ...data.initial, ...(run?.request?.initial || {}) };
    const names = this.fns.spec.coordinates;
    const y0 = new Float64Array(2 * n);
    names.forEach((q, i) => { y0[i] = initial[q] ?? 0; y0[n + i] = initial[`${q}_dot`] ?? 0; });
    const k = Float64Array.from(this.fns.spec.parameters, (p) => params[p] ?? 0);
    return { y0, k, params, initial };
  }

  async draw(run) {
    this.run = run;
    if (!this.visible) { this.readout.textContent = "The chart is drawn when you scroll to it."; return; }
    if (!this.fns) { await this.ask(true); return; } // the first answer brings the generated functions
    clearTimeout(this.restTimer);
    // while a slider is dragged every panel repaints from the browser's preview on each input; this one,
    // the costliest (a new true path and its S(ε) curve), follows once the input rests as long as the server's run
    // waits (controls.js SETTLE_MS), so that a slow drag's next input does not wait behind it
    if (this.previewing) this.restTimer = setTimeout(() => this.update(true), SETTLE_MS);
    // the server's run for the settings the rest already drew: the same start and parameters, so the same true path
    else this.update(!this.live || this.pathKey !== this.keyOf());
  }

  /** The true path's key: τ, the start and the parameters. */
  keyOf(y0 = null, k = null) {
    if (!y0) ({ y0, k } = this.setup());
    return `${this.T}|${Array.from(y0)}|${Array.from(k)}`;
  }

  /** Recompute in the browser; a new path (T, k, start) also asks the server once the input rests. */
  update(newPath) {
    if (!this.fns) return;
    const started = performance.now();
    const { y0, k } = this.setup();
    if (this.focusKey !== `${Array.from(y0)}|${Array.from(k)}`) {
      this.focusKey = `${Array.from(y0)}|${Array.from(k)}`;
      this.focusAt = focus(this.fns.rhs, y0, k, this.tEnd, 800);
      // the panel opens on the ordinary case, τ before the first kinetic focus of S (none where none can exist)
      const tStar = this.data.kinetic_focus_possible === false ? null : this.focusAt;
      if (!this.TChosen) { this.T = openingDuration(this.tEnd, tStar); this.TInput.value = String(this.T); newPath = true; }
    }
    const key = this.keyOf(y0, k);
    if (newPath || !this.live || this.pathKey !== key) {
      const p = path(this.fns.rhs, y0, k, this.T);
      if (!p) { this.readout.textContent = "The true path leaves the region where L can be evaluated; choose a shorter τ."; return; }
      let lo = Infinity, hi = -Infinity;
      for (const y of p.Y) { lo = Math.min(lo, y[this.coordinate]); hi = Math.max(hi, y[this.coordinate]); }
      this.epsMax = Math.max(0.2, 0.6 * (hi - lo));
      this.eps = Math.max(-this.epsMax, Math.min(this.epsMax, this.eps));
      this.epsInput.min = String(-this.epsMax); this.epsInput.max = String(this.epsMax);
      this.epsInput.step = String(this.epsMax / 100); this.epsInput.value = String(this.eps);
      this.pathKey = key; this.cachedPath = p;
      this.server = null;
      clearTimeout(this.timer);
      this.timer = setTimeout(() => this.ask(false), ASK_MS);
    }
    if (newPath || !this.epsilons || this.epsilons[0] !== -this.epsMax) {
      this.epsilons = Array.from({ length: CURVE }, (_, i) => ((2 * i) / (CURVE - 1) - 1) * this.epsMax);
    }
    this.live = liveAction(this.fns, {
      y0, k, T: this.T, c: this.coordinate, shape: this.shape, eps: this.eps, epsilons: this.epsilons,
      path: this.cachedPath, previous: newPath ? null : this.live,
    });
    const q = this.data.coordinates[this.coordinate], unit = this.data.units?.[q] || "";
    this.TOut.textContent = `${fmt(this.T)} s`;
    this.epsOut.textContent = `${fmt(this.eps)}${unit ? ` ${unit}` : ""}`;
    this.paint();
    this.section.dataset.recompute = (performance.now() - started).toFixed(1);
  }

  /** ∫ Q sin(nπt/τ) dt along the true path (Simpson on its even samples), Q the varied coordinate's generalized
   *  force from its own expression tree; null where the page has none. */
  work(p, T) {
    const q = this.data.coordinates[this.coordinate], tree = this.data.forces?.[q];
    const Q = tree ? compile(tree) : null;
    if (!Q) return null;
    const names = this.data.coordinates, n = names.length, N = p.t.length - 1;
    const params = this.setup().params, w = (this.shape * Math.PI) / T;
    const f = Array.from(p.t, (t, i) => {
      const env = { ...params, t };
      names.forEach((name, j) => { env[name] = p.Y[i][j]; env[`${name}_dot`] = p.Y[i][n + j]; });
      return Q(env) * Math.sin(w * t);
    });
    if (N % 2 !== 0 || !f.every(Number.isFinite)) return null;
    let sum = f[0] + f[N];
    for (let i = 1; i < N; i++) sum += (i % 2 ? 4 : 2) * f[i];
    return (sum * (T / N)) / 3;
  }

  settle() {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.ask(false), ASK_MS);
  }

  /** POST to the panel's address (or `path` after it): a user system's action is a job of the reader's session on
   *  the server, which runs one at a time, so it waits its turn in the page's queue (api.js inTurn); a scene's is not. */
  post(body, path = "") {
    const send = () => fetchJSON(`${this.url}${path}`, { body });
    return this.system ? inTurn(send) : send();
  }

  /** The request body for the action over [0, tEnd] varying coordinate c (the page's parameters and start). */
  requestBody(tEnd, c, k, epsilons) {
    const { params, initial } = this.fns ? this.setup() : { params: { ...this.data.parameters, ...(this.run?.request?.parameters || {}) }, initial: { ...this.data.initial, ...(this.run?.request?.initial || {}) } };
    const request = { initial, t_end: tEnd, coordinate: this.data.coordinates[c], shape: "sine", k, epsilons };
    if (!this.system) return { parameters: params, ...request };
    const parameters = (this.system.parameters || []).map((p) => ({ ...p, value: params[p.name] ?? p.value }));
    return { system: { ...this.system, parameters }, ...request };
  }

  /** The server's foci over the whole run for this start and coordinate c, {all, alone} (undefined until known):
   *  all coordinates varied together, and c alone.  The server also finds a focus where det J only touches 0 (the
   *  tabletop's, at half the spring's period), which the browser's sign test misses. */
  runFoci(c) {
    this.foci ??= new Map();
    const key = `${c}|${this.focusKey}`;
    if (!this.foci.has(key)) {
      if (this.foci.size > 16) this.foci.clear();
      this.foci.set(key, undefined);
      this.post(this.requestBody(this.tEnd, c, 1, [0])).then((a) => {
        this.foci.set(key, { all: a.conjugate_time, alone: a.varied_conjugate_time });
        if (key !== `${this.coordinate}|${this.focusKey}`) return;
        // the panel opens before the first focus of all coordinates together (openingDuration), now the server's
        if (!this.TChosen && this.data.kinetic_focus_possible !== false && !this.data.forced) {
          const T = openingDuration(this.tEnd, a.conjugate_time);
          if (T !== this.T) { this.T = T; this.TInput.value = String(T); this.update(true); return; }
        }
        this.paint();
      }).catch(() => this.foci.delete(key));
    }
    return this.foci.get(key);
  }

  async ask(first) {
    const serial = ++this.serial;
    const names = this.data.coordinates;
    const body = this.requestBody(this.T, this.coordinate, this.shape, this.epsilons || [0]);
    const key = JSON.stringify(body);
    this.section.setAttribute("aria-busy", "true");
    let answer;
    try {
      answer = this.answers.get(key);
      if (!answer) {
        answer = this.post(body);
        this.answers.set(key, answer);
        if (this.answers.size > 32) this.answers.delete(this.answers.keys().next().value);
      }
      answer = await answer;
    } catch (err) {
      this.answers.delete(key);
      if (serial === this.serial) { this.readout.textContent = `No action: ${err.message}`; this.section.setAttribute("aria-busy", "false"); }
      return;
    }
    if (serial !== this.serial) return; // a newer request is on its way
    if (!this.fns || this.fns.spec.lagrangian !== answer.preview.lagrangian) {
      this.fns = { spec: answer.preview, rhs: compileRhs(answer.preview), L: compileLagrangian(answer.preview) };
    }
    this.section.setAttribute("aria-busy", "false");
    // the first answer (for the τ before the browser found the focus) is this τ's unless update moved τ
    if (first) { const asked = this.T; this.update(true); if (this.T === asked) clearTimeout(this.timer); }
    if (answer.t_end === this.T && answer.k === this.shape && answer.coordinate === names[this.coordinate] && this.epsilons && answer.epsilons.length === this.epsilons.length) {
      this.server = answer;
      this.paint();
    } else if (first) this.settle();
  }

  paint() {
    if (this.finding) { this.paintFind(); return; }
    const live = this.live, s = this.server;
    if (!live || live.error) { this.readout.textContent = live?.error || ""; return; }
    const q = this.data.coordinates[this.coordinate], lq = this.label(q), unit = this.data.units?.[q] || "";
    const t = Array.from(live.path.t), T = this.T, w = (this.shape * Math.PI) / T;
    const trueQ = live.path.Y.map((y) => y[this.coordinate]);
    const variedQ = trueQ.map((v, i) => v + this.eps * Math.sin(w * t[i]));
    const curve = s ? s.action : live.curve, S0 = s ? s.true : live.truth.S;
    const kind = s ? s.kind : live.kind;
    // the server looks for the focus up to τ only; the browser's search reaches the end of the run, so a focus
    // past τ comes from it (else the panel said "no kinetic focus before 10 s" at τ = 1 s and t* = 1.57 s at τ = 2 s)
    const forced = Boolean(this.data.forced);
    // where no true path can reach a kinetic focus (the engine's verdict, the same the derivation states) none is sought
    const never = this.data.kinetic_focus_possible === false;
    // with a force Q, S alone is not stationary and its kinetic focus means nothing: none is marked or named
    // the foci over the whole run: the server's once known, else the browser's (the server's answer for τ looks up to τ)
    const run = forced || never ? undefined : this.runFoci(this.coordinate);
    const tStar = forced || never ? null : run ? run.all : s && s.conjugate_time !== null && s.conjugate_time !== undefined ? s.conjugate_time : this.focusAt;
    // the focus of the varied coordinate alone (the others kept on the true path)
    const tAlone = forced || never ? null : run ? run.alone : s && s.varied_conjugate_time !== null && s.varied_conjugate_time !== undefined
      ? s.varied_conjugate_time : this.aloneAt(this.coordinate);
    const said = focusSentences({
      labels: this.data.coordinates.map((name) => this.label(name)), c: this.coordinate, T, tEnd: this.tEnd,
      tAll: tStar, tAlone, kind, never, lowering: this.lowering(live.second),
    });
    // the browser's S(ε) - S(0) (the same quadrature for both) on top of the shown S(0)
    const Snow = S0 + (live.now.S - live.truth.S);
    // the tangent at ε = 0: flat by Hamilton's principle, but with a force Q its slope is dS/dε = −∫ Q η dt
    // (the server's figure, else the curve's central difference at ε = 0)
    const mid = (this.epsilons.length - 1) / 2;
    const slope = !forced ? 0 : s ? s.first_variation
      : (curve[mid + 1] - curve[mid - 1]) / (this.epsilons[mid + 1] - this.epsilons[mid - 1]);
    const reach = 0.35 * this.epsMax;
    const traces = [
      { type: "scatter", mode: "lines", x: t, y: trueQ, name: "true path", line: { color: PALETTE[0], width: 2 } },
      { type: "scatter", mode: "lines", x: t, y: variedQ, name: "your path (drag it)", line: { color: PALETTE[1], width: 3, dash: "dash" } },
      { type: "scatter", mode: "lines", x: t, y: Array.from(live.truth.L), name: "L on the true path", xaxis: "x2", yaxis: "y2", line: { color: PALETTE[0], width: 1.5 }, showlegend: false },
      { type: "scatter", mode: "lines", x: t, y: Array.from(live.now.L), name: "L on your path", xaxis: "x2", yaxis: "y2", line: { color: PALETTE[1], width: 1.5, dash: "dash" }, showlegend: false },
      { type: "scatter", mode: "lines", x: this.epsilons, y: curve, name: "S(ε)", xaxis: "x3", yaxis: "y3", line: { color: PALETTE[2], width: 2 }, showlegend: false },
      { type: "scatter", mode: "lines", x: [-reach, reach], y: [S0 - slope * reach, S0 + slope * reach], name: "tangent at ε = 0", xaxis: "x3", yaxis: "y3", line: { color: "#57606a", width: 1, dash: "dot" }, showlegend: false },
      { type: "scatter", mode: "markers", x: [this.eps], y: [Snow], name: "S of your path", xaxis: "x3", yaxis: "y3", marker: { color: PALETTE[1], size: 10 }, showlegend: false },
    ];
    // each focus before τ a dotted line on the time axis, its label inside the paths' plot beside it (the second lower)
    const shapes = forced ? [] : said.marks.map((m) => ({ type: "line", xref: "x", yref: "paper", x0: m.t, x1: m.t, y0: 0.62, y1: 1, line: { color: "#c62828", width: 2, dash: "dot" } }));
    const annotations = forced ? [] : said.marks.map((m, i) => ({ x: m.t, y: 1 - 0.07 * i, xref: "x", yref: "paper", text: m.text, showarrow: false, font: { color: "#c62828", size: 12 }, yanchor: "top", xanchor: m.t > T / 2 ? "right" : "left", xshift: m.t > T / 2 ? -4 : 4, bgcolor: "rgba(255, 255, 255, 0.85)" }));
    const lay = layout({
      // the paths' plot gets the larger share (a phone's legend takes two lines above it); ε ticks stay upright
      height: 580, hovermode: false, dragmode: false, showlegend: true,
      xaxis: axis("t (s)", { domain: [0, 1], anchor: "y", range: [0, T] }), yaxis: axis(`${lq} (${unit})`, { domain: [0.56, 1] }),
      xaxis2: axis("t (s)", { domain: [0, 0.42], anchor: "y2", range: [0, T] }), yaxis2: axis("L (J)", { domain: [0, 0.36], anchor: "x2" }),
      xaxis3: axis("ε", { domain: [0.64, 1], anchor: "y3", nticks: 4, tickangle: 0 }), yaxis3: axis("S (J·s)", { domain: [0, 0.36], anchor: "x3" }),
      shapes,
      // the label inside the upper plot, beside its line, on the side with more room: above the plot it sat on the legend
      annotations,
    });
    const moved = this.drawn && this.drawn.path === live.path && this.drawn.curve === curve && this.drawn.T === T;
    if (moved && this.plot.data?.length === traces.length) {
      // only ε changed: the varied path, its L and the mark on S(ε)
      window.Plotly?.restyle(this.plot, { x: [traces[1].x, traces[3].x, traces[6].x], y: [traces[1].y, traces[3].y, traces[6].y] }, [1, 3, 6]);
    } else {
      window.Plotly?.react(this.plot, traces, lay, CONFIG);
      this.drawn = { path: live.path, curve, T };
    }
    const source = s ? "server" : "preview";
    this.section.dataset.source = source;
    this.section.dataset.kind = kind;
    this.section.dataset.s0 = String(S0);
    this.section.dataset.sNow = String(Snow);
    const focusWords = forced ? "" : said.focus;
    let verdict = said.verdict;
    if (this.data.forced) {
      // δS + ∫ Q δq dt = 0 on the true path, so with δq = ε sin(nπt/τ): dS/dε at ε = 0 = −∫ Q sin(nπt/τ) dt, not zero.
      // Both sides are shown: the slope of S(ε), and the integral of Q from its own formula along the true path
      const work = this.work(live.path, T);
      const sine = this.shape === 1 ? "sin(πt/τ)" : `sin(${this.shape}πt/τ)`;
      const Qname = `Q${this.data.coordinates.length > 1 ? `_${lq}` : ""}`;
      const per = unit ? ` J·s/${unit}` : " J·s";
      const check = work === null ? "" : ` Here dS/dε at ε = 0 = ${fmt(slope)}${per} (the slope of S(ε)), and −∫ ${Qname} ${sine} dt = ${fmt(-work)}${per} (${Qname} from its formula along the true path).`;
      verdict = `The variation is δ${lq} = ε ${sine}, zero at both ends. A force that no potential describes acts here, so the true path makes δS + ∫ ${Qname} δ${lq} dt vanish rather than `
        + `making S stationary: S(ε) is not flat at ε = 0, and its slope there is −∫ ${Qname} ${sine} dt, the work of ${Qname} along the variation per unit of ε with the sign reversed.${check}`;
    }
    const second = s ? s.second_variation : live.secondVariation;
    const diff = Snow - S0;
    const yours = this.eps === 0
      ? "your path is the true path (drag it, or move ε, to vary it)"
      : `S of your path (ε = ${fmt(this.eps)}${unit ? ` ${unit}` : ""}, n = ${this.shape}) = ${fmt(Snow)} J·s, ${diff >= 0 ? "higher" : "lower"} by ${fmt(Math.abs(diff))} J·s`;
    // every number with its unit: ε is in the coordinate's unit, so d²S/dε² is in J·s per unit²
    const curvature = unit ? ` J·s/${unit}²` : "";
    this.readout.textContent = `S of the true path = ${fmt(S0)} J·s; ${yours}. `
      + `d²S/dε² at ε = 0 is ${fmt(second)}${curvature}. ${verdict}${focusWords ? ` ${focusWords}` : ""}`
      + (s ? ` More accurately, with a finer quadrature: S to within ±${fmt(s.error_estimate)} J·s, and dS/dε at ε = 0 ${flatWithin(s) ? "≈ 0 (within that error)" : `= ${fmt(s.first_variation)} J·s${unit ? `/${unit}` : ""}`}.${s.warnings?.length && !this.data.forced ? ` Note: ${s.warnings.join(" ")}` : ""}` : " Computed in your browser; more accurate figures follow.");
    if (this.summary && s) {
      table(this.summary, `S(ε) for the shape n = ${this.shape}, τ = ${fmt(T)} s`, ["ε", "S (J·s)"], s.epsilons.map((e, i) => [fmt(e), fmt(s.action[i])]));
    }
  }

  // ---- "Find the path": fixed ends, a trial path through a few dragged points, relaxed on the server ----

  toggleFind() {
    this.finding = !this.finding;
    this.drawn = null;
    this.findButton.setAttribute("aria-pressed", String(this.finding));
    this.findButton.textContent = this.finding ? "Back to ε" : "Find the path";
    this.relaxButton.hidden = !this.finding;
    // the shape n and ε vary the true path; in "Find the path" they do nothing, so they go, and a line says why
    this.epsInput.disabled = this.finding;
    this.varyControls.hidden = this.finding;
    this.varyControls.style.display = this.finding ? "none" : "contents";
    this.varyControls.querySelector("select").disabled = this.finding;
    this.findNote.hidden = !this.finding;
    this.found = null; this.frame = null; this.seed = null;
    this.shootButton.hidden = true;
    if (this.finding) this.resetControls();
    this.paint();
  }

  resetControls() {
    // the ends of the true path, and CONTROLS points on the straight line between them lifted by a bump
    const p = this.live.path, c = this.coordinate, N = p.t.length - 1;
    const a = p.Y[0][c], b = p.Y[N][c], lift = 0.5 * this.epsMax;
    this.controlsT = Array.from({ length: CONTROLS + 2 }, (_, j) => (j * this.T) / (CONTROLS + 1));
    this.controlsQ = this.controlsT.map((t, j) => a + ((b - a) * t) / this.T + (j === 0 || j === CONTROLS + 1 ? 0 : lift * Math.sin((Math.PI * t) / this.T)));
  }

  trial(times) {
    // straight between neighbouring control points
    const T = this.controlsT, Q = this.controlsQ;
    return Array.from(times, (t) => {
      let j = 1;
      while (j < T.length - 1 && t > T[j]) j++;
      const f = (t - T[j - 1]) / (T[j] - T[j - 1]);
      return Q[j - 1] + f * (Q[j] - Q[j - 1]);
    });
  }

  pickControl(event, full) {
    const xa = full.xaxis, ya = full.yaxis, box = this.plot.getBoundingClientRect();
    const x = event.clientX - box.left, y = event.clientY - box.top;
    let best = null, distance = 30;
    this.controlsT.forEach((t, j) => {
      const d = Math.hypot(xa.d2p(t) + xa._offset - x, ya.d2p(this.controlsQ[j]) + ya._offset - y);
      if (d < distance) { best = j; distance = d; }
    });
    this.picked = best;
  }

  moveControl(event, full) {
    if (this.picked === null || this.picked === undefined) return;
    const ya = full.yaxis, box = this.plot.getBoundingClientRect();
    this.controlsQ[this.picked] = ya.p2d(event.clientY - box.top - ya._offset);
    this.found = null; this.frame = null; this.seed = null;
    this.shootButton.hidden = true;
    this.paintFind();
  }

  async relax() {
    const names = this.data.coordinates, c = this.coordinate, steps = RELAX_STEPS;
    const { params, initial } = this.setup();
    const p = this.live.path, N = p.t.length - 1;
    const start = {}, end = {};
    names.forEach((q, i) => { start[q] = p.Y[0][i]; end[q] = p.Y[N][i]; });
    start[names[c]] = this.controlsQ[0]; end[names[c]] = this.controlsQ[this.controlsQ.length - 1];
    const times = Array.from({ length: steps + 1 }, (_, i) => (i * this.T) / steps);
    // the trial: the dragged points, or (after "Start from the shooting solution") that solution, every coordinate
    const trial = this.seed || { [names[c]]: this.trial(times) };
    const request = { initial, t_end: this.T, start, end, steps, trial };
    const body = this.system
      ? { system: { ...this.system, parameters: (this.system.parameters || []).map((x) => ({ ...x, value: params[x.name] ?? x.value })) }, ...request }
      : { parameters: params, ...request };
    this.relaxButton.disabled = true; this.shootButton.hidden = true;
    // while the server works, the readout says so and counts the seconds (a long τ takes a few)
    const asked = performance.now();
    const waiting = () => `Relaxing: Newton's method on the discrete Euler–Lagrange equations, then a shooting solution to check the result (${((performance.now() - asked) / 1000).toFixed(0)} s so far)…`;
    this.readout.textContent = waiting();
    const ticker = setInterval(() => { if (!this.found) this.readout.textContent = waiting(); }, 1000);
    try {
      this.found = null;
      const answer = await this.post(body, "/relax").finally(() => clearInterval(ticker));
      this.found = answer;
      // the iterates one after another, then the result beside the shooting solution: the whole replay at most
      // REPLAY_MS, however many steps Newton's method took
      const pause = Math.min(FRAME_MS, REPLAY_MS / Math.max(1, answer.iterations.length));
      for (let f = 0; f < answer.iterations.length && this.finding && this.found === answer; f++) {
        this.frame = f; this.paintFind();
        await new Promise((resolve) => setTimeout(resolve, pause));
      }
      this.frame = null;
      if (this.found === answer) this.paintFind();
    } catch (err) {
      this.readout.textContent = `No relaxed path: ${err.message}`;
    } finally {
      this.relaxButton.disabled = false;
    }
  }

  fromShooting() {
    // the shooting solution becomes the trial path; its values at the control times become the points
    const f = this.found, q = this.data.coordinates[this.coordinate];
    if (!f?.shooting) return;
    this.seed = f.shooting.q;
    const shot = f.shooting.q[q];
    this.controlsQ = this.controlsT.map((t) => shot[Math.round((t / this.T) * (shot.length - 1))]);
    this.found = null; this.frame = null;
    this.relax();
  }

  paintFind() {
    if (!this.controlsT) this.resetControls(); // τ moved: the ends follow the true path to the new τ
    const q = this.data.coordinates[this.coordinate], lq = this.label(q), unit = this.data.units?.[q] || "";
    const p = this.live.path, t = Array.from(p.t);
    const traces = [
      { type: "scatter", mode: "lines", x: t, y: p.Y.map((y) => y[this.coordinate]), name: "true path from the start", line: { color: "#b8bec5", width: 2 } },
      { type: "scatter", mode: "lines+markers", x: this.controlsT, y: this.controlsQ, name: "your trial path (drag its points)", line: { color: PALETTE[1], width: 2, dash: "dash" }, marker: { size: 12, color: PALETTE[1] } },
    ];
    const f = this.found;
    if (f) {
      const shown = this.frame === null || this.frame === undefined ? f.q[q] : f.iterations[this.frame][q];
      traces.push({ type: "scatter", mode: "lines", x: f.t, y: shown, name: this.frame === null || this.frame === undefined ? (f.found ? "relaxed path" : "where Newton's method stopped") : `Newton step ${this.frame}`, line: { color: PALETTE[2], width: 3 } });
      if ((this.frame === null || this.frame === undefined) && f.shooting) traces.push({ type: "scatter", mode: "lines", x: f.t, y: f.shooting.q[q], name: "shooting solution", line: { color: PALETTE[3], width: 2, dash: "dot" } });
    }
    // the time axis reaches a little past 0 and τ, so the end points' markers are drawn whole inside the frame
    const pad = FIND_PAD * this.T;
    const lay = layout({ height: 420, hovermode: false, dragmode: false, xaxis: axis("t (s)", { range: [-pad, this.T + pad] }), yaxis: axis(`${lq} (${unit})`) });
    window.Plotly?.react(this.plot, traces, lay, CONFIG);
    this.section.dataset.source = f ? "server" : "preview";
    delete this.section.dataset.relaxed;
    if (!f) {
      // what dragging an end does (relax() sends the end points as the path's fixed ends): it moves that end
      this.readout.textContent = `Find the path: the path sought joins two ends, at t = 0 and at t = τ = ${fmt(this.T)} s, which stay where they are while it is sought. Drag the points of the trial path; dragging an end point moves that end of ${lq}, and Relax then seeks the true path between the new ends. Press Relax: Newton's method makes the discretized action stationary, and each of its steps is shown.`;
      return;
    }
    if (this.frame !== null && this.frame !== undefined) {
      // the answer is in: its steps are replayed, numbered out of their total ("Replaying" says the work is done)
      const total = f.iterations.length - 1;
      this.readout.textContent = this.frame === 0
        ? "Replaying the relaxation: the trial path, sampled on the discrete grid…"
        : `Replaying the relaxation: Newton step ${this.frame} of ${total}, the path moving toward the one that makes the discrete action stationary…`;
      return;
    }
    // the grey path's ends and starting rate: a relaxed motion with the same ends but another rate is a second true motion
    const Y = p.Y, last = Y.length - 1, n = this.data.coordinates.length, c = this.coordinate, size = Math.max(1, Math.abs(Y[last][c]));
    const sameEnds = Math.abs(this.controlsQ[0] - Y[0][c]) <= 1e-9 * size && Math.abs(this.controlsQ[this.controlsQ.length - 1] - Y[last][c]) <= 1e-9 * size;
    const said = verdict(f, { q, label: lq, unit, rateUnit: rateUnit(this.data, q), T: this.T, steps: RELAX_STEPS, startRate: Y[0][n + c], sameEnds });
    this.section.dataset.relaxed = said.found ? f.kind : "not-found";
    this.shootButton.hidden = !said.advice.includes("from-shooting");
    this.readout.textContent = said.text;
    if (said.method) {
      this.methodText.textContent = said.method;
      this.method.hidden = false;
    }
  }

  cursor() {}
}
