/**
 * rk4.js — one classical Runge–Kutta step, in place, shared by the live preview (preview.js) and the
 * action panel's true path (action-live.js).
 *
 *   rk4Scratch(m)                         the work arrays for a state of m numbers
 *   rk4Step(rhs, time, y, k, h, scratch)  y ← y(t + h) for y' = rhs(t, y, k)
 */

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
