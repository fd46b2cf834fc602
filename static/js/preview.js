/**
 * preview.js — the live preview: the system's right-hand side, integrated in the browser.
 *
 *   const rhs = compileRhs(preview);     // preview = result.preview of the simulate API:
 *                                        // {rhs, coordinates, parameters}, where rhs is the body of
 *                                        // (t, y, k, out) printed on the server from the engine's
 *                                        // expressions (app/numerics/generate.py browser_source)
 *   integrate(preview, rhs, data, request, samples)
 *       -> a result shaped like the simulate API's ({t, state, stats}) or {error}
 *
 * A fixed-step classical Runge–Kutta method (RK4): samples are evenly spaced over t_end (as
 * the server's), with enough sub-steps per sample that h·ω ≤ 0.25 for the fastest frequency
 * ω estimated from the Jacobian's diagonal at the start.  It is a preview: the server's run,
 * with its error estimate and conservation audit, replaces it when the input settles.
 *
 * A scene's terminal events (data.events: {name, message, tree}, app/numerics/events.py) end
 * the preview where the server's run ends: the first sub-step after which an event's g is
 * negative; the instant between the two sub-steps is where the straight line through the two
 * values of g crosses zero, and the state there is interpolated the same way.
 */
import { compile } from "./expr.js";

/** One classical Runge–Kutta step in place (also the action panel's true path, action-live.js). */
export function rk4Scratch(m) {
  return { k1: new Float64Array(m), k2: new Float64Array(m), k3: new Float64Array(m), k4: new Float64Array(m), tmp: new Float64Array(m) };
}

export function rk4Step(rhs, time, y, k, h, { k1, k2, k3, k4, tmp }) {
  const m = y.length;
  // y(t + h) = y + h/6 (k1 + 2 k2 + 2 k3 + k4)
  rhs(time, y, k, k1);
  for (let j = 0; j < m; j++) tmp[j] = y[j] + 0.5 * h * k1[j];
  rhs(time + 0.5 * h, tmp, k, k2);
  for (let j = 0; j < m; j++) tmp[j] = y[j] + 0.5 * h * k2[j];
  rhs(time + 0.5 * h, tmp, k, k3);
  for (let j = 0; j < m; j++) tmp[j] = y[j] + h * k3[j];
  rhs(time + h, tmp, k, k4);
  for (let j = 0; j < m; j++) y[j] += (h / 6) * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
}

const MAX_EVALUATIONS = 400_000; // about 10-20 ms of arithmetic for a small system

export function compileRhs(preview) {
  // the source is generated on the server from validated SymPy expressions, with every
  // symbol renamed (q0, v0, k0, t): no text a user typed reaches it
  return new Function("t", "y", "k", "out", `"use strict";\n${preview.rhs}`);
}

function fastest(rhs, y, k, n) {
  // |d q_ddot_i / d q_i| estimates ω² of coordinate i; |d q_ddot_i / d q_dot_i| a damping rate
  const base = new Float64Array(2 * n), out = new Float64Array(2 * n);
  rhs(0, y, k, base);
  let w = 0;
  for (let i = 0; i < 2 * n; i++) {
    const h = 1e-6 * Math.max(1, Math.abs(y[i]));
    const yy = Float64Array.from(y);
    yy[i] += h;
    rhs(0, yy, k, out);
    const d = Math.abs((out[n + (i % n)] - base[n + (i % n)]) / h);
    w = Math.max(w, i < n ? Math.sqrt(d) : d);
  }
  return Number.isFinite(w) ? w : 0;
}

export function integrate(preview, rhs, data, request, samples) {
  const n = preview.coordinates.length;
  const y = new Float64Array(2 * n);
  preview.coordinates.forEach((q, i) => {
    y[i] = request.initial[q] ?? data.initial[q] ?? 0;
    y[n + i] = request.initial[`${q}_dot`] ?? data.initial[`${q}_dot`] ?? 0;
  });
  const k = Float64Array.from(preview.parameters, (p) => request.parameters[p] ?? data.parameters[p]);
  const tEnd = request.t_end || data.t_end;
  const N = Math.max(2, samples);
  const dt = tEnd / (N - 1);
  const omega = fastest(rhs, y, k, n);
  const sub = Math.max(1, Math.ceil((dt * omega) / 0.25));
  if ((N - 1) * sub * 4 > MAX_EVALUATIONS) return { error: "the motion is too fast for a preview" };
  const h = dt / sub;
  const m = 2 * n;
  const scratch = rk4Scratch(m);
  const cols = Array.from({ length: m }, () => new Float64Array(N));
  const t = new Float64Array(N);
  for (let j = 0; j < m; j++) cols[j][0] = y[j];
  const events = (data.events || []).filter((e) => e.tree !== null).map((e) => ({ ...e, g: compile(e.tree) }));
  const env = { ...data.parameters, ...request.parameters };
  const gOf = (e, time, state) => {
    preview.coordinates.forEach((q, i) => { env[q] = state[i]; env[`${q}_dot`] = state[n + i]; });
    env.t = time;
    return e.g(env);
  };
  const prev = new Float64Array(m);
  const finish = (count, stats) => {
    const state = {};
    preview.coordinates.forEach((q, i) => { state[q] = cols[i].slice(0, count); state[`${q}_dot`] = cols[n + i].slice(0, count); });
    return { t: t.slice(0, count), state, conserved: {}, constraint_forces: {}, stats };
  };
  const stats = (steps) => ({ method: "RK4 (browser preview)", steps, rhs_evaluations: steps * 4, step_size: h, event: null });
  for (const e of events) {
    if (gOf(e, 0, y) < 0) return finish(1, { ...stats(0), event: { name: e.name, t: 0, message: e.message } });
  }
  let time = 0;
  for (let s = 1; s < N; s++) {
    for (let r = 0; r < sub; r++) {
      prev.set(y);
      rk4Step(rhs, time, y, k, h, scratch);
      time += h;
      for (const e of events) {
        const gb = gOf(e, time, y);
        if (!(gb < 0)) continue;
        // g(time - h) >= 0 > g(time): the zero of the line through the two values
        const ga = gOf(e, time - h, prev), f = ga / (ga - gb), at = time - h + f * h;
        t[s] = at;
        for (let j = 0; j < m; j++) cols[j][s] = prev[j] + f * (y[j] - prev[j]);
        return finish(s + 1, { ...stats((s - 1) * sub + r + 1), event: { name: e.name, t: at, message: e.message } });
      }
    }
    t[s] = s * dt;
    for (let j = 0; j < m; j++) {
      if (!Number.isFinite(y[j])) return { error: "the preview left the region where the equations can be evaluated" };
      cols[j][s] = y[j];
    }
  }
  return finish(N, stats((N - 1) * sub));
}
