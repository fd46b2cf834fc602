/**
 * modes.js — the normal-modes panel: each mode, or a superposition the student picks, played on the
 * scene's own mechanism drawing (animation.js's Player), with predicted against measured frequencies.
 *
 *   new ModesPanel(section, data, urls)   the plots.js interface: draw(run), cursor(i, run)
 *
 * data.normal_modes: equilibria at rest with an oscillating mode (app/viz/panels.py), numbers at the
 * default parameters, shown until the server answers for the run's parameters.  Near the
 * equilibrium q0 the linear motion started at rest is
 *
 *     q(t) = q0 + Σ_k A_k a_k cos(ω_k t)
 *
 * with a_k the mode's shape (largest component 1), ω_k = √ω²_k and A_k the amplitude the student
 * sets.  Modes with ω² ≤ 0 (a free drift, or growth at an unstable equilibrium) are listed, not played.
 * urls.modes(parameters) resolves to the server's modes at those parameter values, each mode with ω
 * measured from a small-amplitude simulation along it (POST /api/scenes/{id}/modes-at; the playground's
 * POST /api/modes answers at the declared values only, which urls.modesFollow = false says).  The
 * panel asks again after every server run whose parameters differ from the last answer's (the
 * simulation's own debounce paces it); a preview greys it until then, and the readout names the
 * parameter values the modes shown were computed at.
 */
import { Player } from "./animation.js";
import { fmt, percent, table } from "./summaries.js";
import { proseReadout } from "./prose.js";

const FPS = 60;
const MAX_SAMPLES = 4000;
const AMPLITUDE = { rad: 0.25, m: 0.2 }; // default amplitude of a mode's largest component
const TOP = { rad: 0.8, m: 0.6 }; // the amplitude slider's end

export class ModesPanel {
  static needsUrls = true;

  constructor(section, data, urls = {}) {
    this.section = section; this.data = data; this.urls = urls;
    this.preview = false; // the modes belong to the server's answer at the run's parameters
    this.equilibria = data.normal_modes || [];
    this.computedAt = { ...data.parameters }; // the page's numbers are at the defaults
    this.which = 0;
    this.choice = section.querySelector(".mode-choice");
    this.freq = section.querySelector(".frequencies");
    this.readout = proseReadout(section.querySelector(".readout"));
    this.player = data.mechanism ? new Player(section, data.mechanism) : null;
    this.build();
  }

  unit(q) { return this.data.units[q] || ""; }

  /** The equilibrium picker, then one row per mode: a checkbox and an amplitude slider. */
  build() {
    const data = this.data;
    const rows = [];
    if (this.equilibria.length > 1) {
      const id = `${this.section.id}-equilibrium`;
      const label = Object.assign(document.createElement("label"), { htmlFor: id, textContent: "About the equilibrium " });
      const select = Object.assign(document.createElement("select"), { id });
      this.equilibria.forEach((e, k) => select.append(new Option(this.where(e), String(k))));
      select.addEventListener("change", () => { this.which = Number(select.value); this.build(); this.play(); this.table(); });
      select.value = String(this.which);
      const div = document.createElement("div");
      div.className = "mode-equilibrium";
      div.append(label, select);
      rows.push(div);
    }
    const e = this.equilibria[this.which];
    const before = (this.inputs || []).map((x) => ({ checked: x.box.checked, value: x.amp.value }));
    this.inputs = [];
    (e ? e.modes : []).forEach((m, k) => {
      const row = document.createElement("div");
      row.className = "mode-row";
      const id = `${this.section.id}-mode-${k}`;
      const box = Object.assign(document.createElement("input"), { type: "checkbox", id, checked: k === 0 && m.omega_squared > 0 });
      box.dataset.mode = String(k);
      const label = Object.assign(document.createElement("label"), { htmlFor: id });
      label.textContent = `Mode ${k + 1}: ${m.omega_squared > 0 ? `ω = ${fmt(Math.sqrt(m.omega_squared))} rad/s` : m.omega_squared === 0 ? "ω² = 0 (drifts freely)" : `ω² = ${fmt(m.omega_squared)} (grows)`}, shape ${this.shape(m)}`;
      const big = Object.entries(m.shape).reduce((a, b) => (Math.abs(b[1]) > Math.abs(a[1]) ? b : a))[0];
      const u = this.unit(big);
      const amp = Object.assign(document.createElement("input"), {
        type: "range", min: "0", max: String(TOP[u] ?? TOP.m), step: "0.01", value: String(AMPLITUDE[u] ?? AMPLITUDE.m), id: `${id}-amplitude`,
      });
      amp.setAttribute("aria-label", `Amplitude of mode ${k + 1} (${u})`);
      const out = Object.assign(document.createElement("output"), { htmlFor: amp.id, textContent: `${amp.value} ${u}` });
      if (before[k] && m.omega_squared > 0) { box.checked = before[k].checked; amp.value = before[k].value; out.textContent = `${amp.value} ${u}`; }
      if (!(m.omega_squared > 0)) { box.disabled = true; amp.disabled = true; }
      const changed = () => { out.textContent = `${amp.value} ${u}`; this.play(); };
      box.addEventListener("change", changed);
      amp.addEventListener("input", changed);
      row.append(box, label, amp, out);
      rows.push(row);
      this.inputs.push({ box, amp, mode: m });
    });
    if (!e) {
      const none = document.createElement("p");
      none.textContent = `At ${this.values()} no equilibrium at rest has a mode that oscillates (every equilibrium is unstable, or there is none).`;
      rows.push(none);
    }
    const legend = this.choice.querySelector("legend");
    this.choice.replaceChildren(legend, ...rows);
  }

  /** "m = 1 kg, k = 10 N/m, κ = 0.1 N/m": the parameter values the modes shown were computed at. */
  values() {
    const units = this.data.parameter_units || {};
    const list = Object.entries(this.computedAt).map(([p, v]) => `${this.data.labels[p] || p} = ${fmt(v)}${units[p] ? ` ${units[p]}` : ""}`);
    return list.length ? list.join(", ") : "the declared values";
  }

  where(e) {
    return Object.entries(e.equilibrium).map(([q, x]) => `${this.data.labels[q] || q} = ${fmt(x)}`).join(", ");
  }

  shape(m) {
    return "(" + Object.entries(m.shape).map(([q, a]) => `${this.data.labels[q] || q}: ${fmt(a)}`).join(", ") + ")";
  }

  /** The picked superposition as a run the Player can draw (simulation.js's prepareRun shape). */
  motion() {
    const e = this.equilibria[this.which];
    const picked = this.inputs.filter((x) => x.box.checked && Number(x.amp.value) > 0 && x.mode.omega_squared > 0);
    const omegas = picked.map((x) => Math.sqrt(x.mode.omega_squared));
    // long enough to see each mode a few times, and a superposition's slowest beat once
    let T = omegas.length ? (4 * 2 * Math.PI) / Math.min(...omegas) : 4;
    for (let a = 0; a < omegas.length; a++) {
      for (let b = a + 1; b < omegas.length; b++) {
        const gap = Math.abs(omegas[a] - omegas[b]);
        if (gap > 0) T = Math.max(T, Math.min(60, (2 * Math.PI) / gap));
      }
    }
    const n = Math.min(MAX_SAMPLES, Math.max(120, Math.round(FPS * T)));
    const t = Array.from({ length: n }, (_, i) => (T * i) / (n - 1));
    const state = {};
    for (const q of this.data.coordinates) {
      const x0 = e ? e.equilibrium[q] ?? 0 : 0;
      const x = new Float64Array(n), v = new Float64Array(n);
      picked.forEach(({ amp, mode }, k) => {
        const A = Number(amp.value) * (mode.shape[q] ?? 0), w = omegas[k];
        for (let i = 0; i < n; i++) { x[i] += A * Math.cos(w * t[i]); v[i] -= A * w * Math.sin(w * t[i]); }
      });
      for (let i = 0; i < n; i++) x[i] += x0;
      state[q] = x; state[`${q}_dot`] = v;
    }
    return { t, state, picked };
  }

  play() {
    const { t, state, picked } = this.motion();
    this.section.dataset.modes = picked.map((x) => this.inputs.indexOf(x) + 1).join(",");
    const data = this.data, params = data.parameters;
    const extent = {};
    for (const q of data.coordinates) {
      extent[`qmin_${q}`] = Math.min(...state[q]);
      extent[`qmax_${q}`] = Math.max(...state[q]);
    }
    const envAt = (i) => {
      const env = { ...params, ...extent, t: t[i] };
      for (const k of Object.keys(state)) env[k] = state[k][i];
      return env;
    };
    const run = { data, request: {}, n: t.length, t, params, state, extent, envAt, momenta: {}, forces: {}, stats: {} };
    this.readout.textContent = picked.length
      ? `Playing ${picked.length === 1 ? "mode" : "modes"} ${this.section.dataset.modes} about ${this.where(this.equilibria[this.which])}, computed at ${this.values()}${this.note || ""} (linear motion).`
        + (picked.length > 1 ? " Each mode keeps its own frequency, so the shape of the motion changes as they drift in and out of step." : "")
      : "Tick a mode (with an amplitude above 0) to play it.";
    if (!this.player) return;
    this.player.load(run);
    if (picked.length) this.player.play(); else this.player.pause();
  }

  /** Ask the server for the modes at these parameter values; the latest request wins. */
  async measure(params) {
    if (!this.urls.modes) return;
    const mine = (this.asked = (this.asked || 0) + 1);
    this.section.setAttribute("aria-busy", "true");
    let answer;
    try {
      answer = await this.urls.modes(params);
    } catch (err) {
      if (mine !== this.asked) return;
      this.measured = null;
      this.section.setAttribute("aria-busy", "false");
      this.freq.textContent = `The modes at these parameter values could not be computed: ${err.message}. Shown: the modes at ${this.values()}.`;
      return;
    }
    if (mine !== this.asked) return;
    this.section.setAttribute("aria-busy", "false");
    this.measured = answer;
    const follows = this.urls.modesFollow !== false;
    if (follows) {
      // the server's equilibria and modes at the run's parameters replace the page's (at the defaults)
      const shown = this.equilibria[this.which];
      this.equilibria = answer.map((x) => ({ ...x, stable: x.kind !== "unstable", momenta: {} }));
      this.computedAt = answer[0]?.parameters || { ...params };
      const same = shown ? this.equilibria.findIndex((x) => this.near(x, shown)) : -1;
      this.which = same >= 0 ? same : 0;
      this.note = answer.some((x) => x.at_defaults) ? " (found numerically at the default parameters only)" : "";
      this.build();
      this.play();
    } else {
      this.computedAt = answer[0]?.parameters || this.computedAt;
      const differ = Object.entries(params).some(([p, v]) => this.computedAt[p] !== undefined && Math.abs(this.computedAt[p] - v) > 1e-12 * Math.max(1, Math.abs(v)));
      this.note = differ ? "; the sliders' values differ: apply them to the declaration to recompute the modes" : "";
      this.play();
    }
    this.section.dataset.computedAt = JSON.stringify(this.computedAt);
    this.table();
  }

  near(a, b) {
    return Object.entries(b.equilibrium).every(([q, v]) => Math.abs((a.equilibrium[q] ?? 0) - v) < 1e-9 * Math.max(1, Math.abs(v)));
  }

  table() {
    const e = this.equilibria[this.which];
    const m = this.measured && e && this.measured.find((x) => this.near(x, e));
    if (!m) { this.freq.replaceChildren(); return; }
    // a difference below 0.001 % is rounding and integration error, not physics: say so instead of printing it
    const difference = (x) => (Math.abs(x) < 1e-5 ? "< 0.001 %" : percent(x));
    table(this.freq, `ω in rad/s at ${this.values()}: predicted, and measured in a run along each mode (amplitude ${fmt(m.modes[0]?.amplitude)})`,
      ["mode", "predicted", "measured", "difference"],
      m.modes.map((x, k) => [`${k + 1}`, x.predicted === null ? `ω² = ${fmt(x.omega_squared)}` : fmt(x.predicted), x.measured === null ? "–" : fmt(x.measured),
        x.relative_difference === null ? "–" : difference(x.relative_difference)]));
    this.freq.dataset.measured = JSON.stringify(m.modes.map((x) => [x.predicted, x.measured]));
  }

  draw(run) {
    // a server run at parameter values the modes were not computed for asks for them again (after the
    // run has been drawn: a playground session runs one job at a time)
    if (!this.started) { this.started = true; this.play(); }
    const params = {};
    for (const p of Object.keys(this.data.parameters)) params[p] = run.params[p];
    const key = JSON.stringify(params);
    if (key !== this.key) { this.key = key; this.measure(params); }
  }

  cursor() {}
}
