/**
 * action-live.js — the action panel's numbers in the browser (static/js/action.js draws them).
 *
 *   compileLagrangian(preview)    L(t, y, k) from the server's engine-generated JavaScript
 *   path(rhs, y0, k, T)           the true path on STEPS + 1 even times (RK4)
 *   varied(L, path, k, c, k, ε)   L along q + ε sin(kπt/T) e_c, and S by Simpson's rule
 *   focus(rhs, y0, k, T)          the first kinetic focus: det of the Jacobi fields ∂q/∂q̇(0) = 0
 *   focusAlone(fns, y0, k, T, c)  the first kinetic focus of the variations of coordinate c alone
 *   openingDuration(tEnd, t*)     the τ the panel opens on: before the first kinetic focus
 *   liveAction(fns, setup)        all of it for one setup (a drag reuses what only ε leaves alone)
 */

import { rk4Scratch, rk4Step } from "./preview.js";

export const STEPS = 400; // RK4 steps of the browser's true path (an even number: Simpson)
export const SHAPES = 8; // k = 1 … SHAPES tried for the kind

export function compileLagrangian(preview) {
  // printed on the server from the engine's L with every symbol renamed (q0, v0, k0, t)
  return new Function("t", "y", "k", `"use strict";\n${preview.lagrangian}`);
}

/** y(t) on STEPS + 1 even times by RK4 (sub-steps so that h·ω stays small); null if it leaves the finite numbers. */
export function path(rhs, y0, k, T, steps = STEPS, sub = 4) {
  const m = y0.length, h = T / (steps * sub);
  const y = Float64Array.from(y0), scratch = rk4Scratch(m);
  const Y = [Float64Array.from(y)];
  let time = 0;
  for (let s = 0; s < steps; s++) {
    for (let r = 0; r < sub; r++) {
      rk4Step(rhs, time, y, k, h, scratch);
      time += h;
    }
    if (!y.every(Number.isFinite)) return null;
    Y.push(Float64Array.from(y));
  }
  return { t: Float64Array.from({ length: steps + 1 }, (_, i) => (i * T) / steps), Y };
}

/** L along q + ε η e_c (η = sin(kπt/T)), and S by Simpson's rule. */
export function varied(L, p, k, c, shape, eps) {
  const n = p.Y[0].length / 2, N = p.t.length - 1, T = p.t[N], w = (shape * Math.PI) / T;
  const values = new Float64Array(N + 1), y = new Float64Array(2 * n);
  let S = 0;
  for (let i = 0; i <= N; i++) {
    const t = p.t[i];
    y.set(p.Y[i]);
    y[c] += eps * Math.sin(w * t);
    y[n + c] += eps * w * Math.cos(w * t);
    values[i] = L(t, y, k);
    // Simpson: h/3 (f0 + 4 f1 + 2 f2 + … + f_N)
    S += values[i] * (i === 0 || i === N ? 1 : i % 2 ? 4 : 2);
  }
  return { L: values, S: (S * T) / N / 3 };
}

export const OPENING_SHARE = 10; // the panel opens on a tenth of the run …
export const BEFORE_FOCUS = 0.8; // … or on 80 % of the first kinetic focus, if that comes sooner
export const T_STEPS = 200; // the τ slider's steps over the run

/**
 * The τ the panel opens on: the ordinary case, a true path that is a minimum of S. Before the first kinetic
 * focus t* every variation with fixed ends raises S; past it some lower it. So τ = t_end/10, unless that
 * reaches 0.8 t*; then the slider's last step at or below 0.8 t* (at least one step).
 */
export function openingDuration(tEnd, tStar) {
  const step = tEnd / T_STEPS, share = tEnd / OPENING_SHARE;
  if (tStar === null || tStar === undefined || share < BEFORE_FOCUS * tStar) return share;
  return Math.max(step, Math.floor((BEFORE_FOCUS * tStar) / step + 1e-9) * step);
}

/** The first t* where det J = 0, J the Jacobi fields ∂q/∂q̇(0) (differences of neighbouring paths); null before T. */
export function focus(rhs, y0, k, T, steps = STEPS) {
  const n = y0.length / 2, d = 1e-6;
  const base = path(rhs, y0, k, T, steps);
  if (!base) return null;
  const fields = [];
  for (let j = 0; j < n; j++) {
    const up = Float64Array.from(y0), down = Float64Array.from(y0);
    up[n + j] += d; down[n + j] -= d;
    const a = path(rhs, up, k, T, steps), b = path(rhs, down, k, T, steps);
    if (!a || !b) return null;
    fields.push(a.Y.map((y, i) => Array.from({ length: n }, (_, r) => (y[r] - b.Y[i][r]) / (2 * d))));
  }
  const det = (i) => determinant(fields.map((f) => f[i]));
  let previous = det(1);
  for (let i = 2; i <= steps; i++) {
    const now = det(i);
    if (previous > 0 && now <= 0) return base.t[i - 1] + (previous / (previous - now)) * (base.t[i] - base.t[i - 1]);
    previous = now;
  }
  return null;
}

/**
 * The first kinetic focus of the variations of coordinate c alone (the other coordinates kept on the true path),
 * null before T.  Their second variation is ∫ (P η′² + 2 C η η′ + R η²) dt with P = ∂²L/∂q̇_c², C = ∂²L/∂q_c∂q̇_c
 * and R = ∂²L/∂q_c², here by central differences of the generated L along the true path.  Its Jacobi equation,
 * with Π = P η′ + C η, is η′ = (Π − C η)/P, Π′ = C η′ + R η; from η(0) = 0, η′(0) = 1 (RK4 with step 2h, its
 * middle a grid time) the focus is the first zero of η.  These variations are some of all, so the focus comes at
 * the one of all coordinates together or later (with one coordinate it is that one).
 */
export function focusAlone(fns, y0, k, T, c, steps = STEPS) {
  const n = y0.length / 2, p = path(fns.rhs, y0, k, T, steps);
  if (!p) return null;
  const P = new Float64Array(steps + 1), C = new Float64Array(steps + 1), R = new Float64Array(steps + 1);
  const y = new Float64Array(2 * n);
  for (let i = 0; i <= steps; i++) {
    const t = p.t[i], base = p.Y[i];
    const dq = 1e-4 * Math.max(1, Math.abs(base[c])), dv = 1e-4 * Math.max(1, Math.abs(base[n + c]));
    const L = (a, b) => { y.set(base); y[c] += a; y[n + c] += b; return fns.L(t, y, k); };
    const L0 = L(0, 0);
    P[i] = (L(0, dv) - 2 * L0 + L(0, -dv)) / (dv * dv);
    R[i] = (L(dq, 0) - 2 * L0 + L(-dq, 0)) / (dq * dq);
    C[i] = (L(dq, dv) - L(dq, -dv) - L(-dq, dv) + L(-dq, -dv)) / (4 * dq * dv);
  }
  const f = (i, eta, Pi) => { const d = (Pi - C[i] * eta) / P[i]; return [d, C[i] * d + R[i] * eta]; };
  const H = 2 * (p.t[1] - p.t[0]);
  let eta = 0, Pi = P[0];
  for (let i = 0; i + 2 <= steps; i += 2) {
    const [a1, b1] = f(i, eta, Pi);
    const [a2, b2] = f(i + 1, eta + (H / 2) * a1, Pi + (H / 2) * b1);
    const [a3, b3] = f(i + 1, eta + (H / 2) * a2, Pi + (H / 2) * b2);
    const [a4, b4] = f(i + 2, eta + H * a3, Pi + H * b3);
    const next = eta + (H / 6) * (a1 + 2 * a2 + 2 * a3 + a4);
    Pi += (H / 6) * (b1 + 2 * b2 + 2 * b3 + b4);
    if (!Number.isFinite(next)) return null;
    if (i > 0 && eta > 0 && next <= 0) return p.t[i] + (eta / (eta - next)) * H;
    eta = next;
  }
  return null;
}

function determinant(rows) {
  const a = rows.map((r) => [...r]), n = a.length;
  let det = 1;
  for (let c = 0; c < n; c++) {
    let p = c;
    for (let r = c + 1; r < n; r++) if (Math.abs(a[r][c]) > Math.abs(a[p][c])) p = r;
    if (a[p][c] === 0) return 0;
    if (p !== c) { [a[p], a[c]] = [a[c], a[p]]; det = -det; }
    det *= a[c][c];
    for (let r = c + 1; r < n; r++) {
      const f = a[r][c] / a[c][c];
      for (let q = c; q < n; q++) a[r][q] -= f * a[c][q];
    }
  }
  return det;
}

/**
 * The browser's numbers for one setup {y0, k, T, c, shape, eps, epsilons, focusSpan}: the true and varied
 * paths with L along them, S on the ε curve, the second variation per shape k (central differences),
 * the kind, and t* up to focusSpan.
 */
export function liveAction(fns, s) {
  const p = s.path || path(fns.rhs, s.y0, s.k, s.T);
  if (!p) return { error: "the true path leaves the region where the equations can be evaluated" };
  const now = varied(fns.L, p, s.k, s.c, s.shape, s.eps);
  // a drag moves ε only: the true path's S, the curve and the second variations are kept from the last setup
  const same = s.previous && s.previous.path === p && s.previous.shape === s.shape && s.previous.c === s.c
    && s.previous.epsilons === s.epsilons;
  if (same) return { ...s.previous, now };
  const truth = varied(fns.L, p, s.k, s.c, s.shape, 0);
  const curve = s.epsilons.map((e) => (e === 0 ? truth.S : varied(fns.L, p, s.k, s.c, s.shape, e).S));
  const h = 1e-3;
  const second = [];
  for (let j = 1; j <= SHAPES; j++) {
    const plus = varied(fns.L, p, s.k, s.c, j, h).S, minus = varied(fns.L, p, s.k, s.c, j, -h).S;
    second.push((plus + minus - 2 * truth.S) / (h * h));
  }
  const lowest = Math.min(...second);
  const kind = lowest >= 0 ? "minimum" : second.every((x) => x < 0) ? "maximum" : "saddle";
  return {
    path: p, truth, now, curve, second, kind, secondVariation: second[s.shape - 1],
    shape: s.shape, c: s.c, epsilons: s.epsilons,
  };
}
