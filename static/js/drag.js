/**
 * drag.js — direct manipulation of a mechanism's bodies (animation.js): which body the pointer holds,
 * and the initial coordinates and rates that put it where the pointer is.
 *
 * Dragging a body moves it along its constraint: the initial coordinates it owns that put it nearest
 * the pointer, found by Gauss–Newton steps on its on-screen position as a function of those
 * coordinates.  At t = 0 the selected body also carries its initial velocity, an arrow ending in a
 * round handle; dragging the handle sets the initial rates q_dot of the coordinates the body owns, by
 * least squares on the handle's screen position, clamped to the controls' ranges (2-D views only,
 * and only where those rate controls exist).
 */

const GRAB_RADIUS = 26; // CSS pixels around a body that start a drag
// the velocity arrow: TAU seconds of motion at the initial velocity (less where the fastest
// start the controls allow would leave the view), drawn beyond a fixed offset from the
// body's centre so that at rest the handle sits beside the body, not on it
const TAU = 0.25;
const REACH = 0.4; // the longest arrow, as a fraction of the canvas's shorter side
const HANDLE_OFFSET = 24; // CSS pixels from the body's centre to the handle at rest
export const HANDLE_RADIUS = 7;
const HANDLE_GRAB = 16;

export class Drag {
  constructor(player) {
    this.player = player; // the Player whose bodies are dragged (its run, camera, controls and selection)
  }

  grab(x, y) {
    // the body under the pointer (at the instant shown), if any
    if (!this.player.run) return -1;
    const dpr = window.devicePixelRatio || 1;
    let best = -1, bestD = GRAB_RADIUS * dpr;
    this.player.masses.forEach((p, k) => {
      const [px, py] = this.player.at(p, this.player.index);
      const d = Math.hypot(px - x, py - y);
      if (d < bestD) { best = k; bestD = d; }
    });
    return best;
  }

  /** The body's screen position with the initial coordinates `values` (others as they are), at time t. */
  placed(k, values, t = 0) {
    const env = { ...this.player.run.envAt(0), ...values, t };
    return this.player.camera.screenOf(this.player.points[this.player.masses[k]].map((f) => f(env)));
  }

  /** Initial coordinates of body k that bring it nearest the screen point (x, y). */
  solve(k, x, y) {
    const names = (this.player.ownersOf[k] || []).filter((q) => this.player.controls && this.player.controls(q));
    return this.fitTo(names, x, y, (values) => this.placed(k, values));
  }

  /** Values of the controls `names` that bring the screen point at(values) nearest (x, y): Gauss–Newton, clamped to the controls' ranges. */
  fitTo(names, x, y, at) {
    if (!names.length) return null;
    const ranges = names.map((q) => this.player.controls(q));
    const values = Object.fromEntries(names.map((q, j) => [q, ranges[j].value]));
    for (let iter = 0; iter < 12; iter++) {
      const [px, py] = at(values);
      const rx = x - px, ry = y - py;
      // columns of the Jacobian d(screen)/d(q) by central differences
      const J = names.map((q, j) => {
        const h = 1e-4 * Math.max(1, Math.abs(values[q]), ranges[j].max - ranges[j].min);
        const a = at({ ...values, [q]: values[q] + h }), b = at({ ...values, [q]: values[q] - h });
        return [(a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h)];
      });
      // normal equations (J^T J + mu I) d = J^T r, for one or two unknowns
      const mu = 1e-9;
      let step;
      if (names.length === 1) {
        const [a, b] = J[0];
        step = [(a * rx + b * ry) / (a * a + b * b + mu)];
      } else {
        const [a, b] = J[0], [c, d] = J[1];
        const m11 = a * a + b * b + mu, m12 = a * c + b * d, m22 = c * c + d * d + mu;
        const g1 = a * rx + b * ry, g2 = c * rx + d * ry, det = m11 * m22 - m12 * m12;
        step = [(m22 * g1 - m12 * g2) / det, (m11 * g2 - m12 * g1) / det];
      }
      let moved = 0;
      names.slice(0, step.length).forEach((q, j) => {
        if (!Number.isFinite(step[j])) return;
        const next = Math.min(ranges[j].max, Math.max(ranges[j].min, values[q] + step[j]));
        moved = Math.max(moved, Math.abs(next - values[q]));
        values[q] = next;
      });
      if (moved < 1e-9) break;
    }
    return values;
  }

  /** The initial state as the controls hold it now (the run may lag a frame behind a drag). */
  initialState(values = {}) {
    const state = {};
    for (const q of this.player.run.data.coordinates) {
      for (const name of [q, `${q}_dot`]) {
        const r = this.player.controls && this.player.controls(name);
        state[name] = r ? r.value : this.player.run.envAt(0)[name];
      }
    }
    return { ...state, ...values };
  }

  /** Screen velocity of body k (device pixels per second) with the initial state overridden by `values`. */
  velocity(k, values = {}) {
    const s = this.initialState(values), h = 1e-5, ahead = {}, behind = {};
    // v = Σ ∂r/∂q_k q̇_k + ∂r/∂t: the derivative of the screen position along (q̇, 1),
    // a central difference of r(q ± h q̇, t ± h)
    for (const q of this.player.run.data.coordinates) {
      ahead[q] = s[q] + h * s[`${q}_dot`];
      behind[q] = s[q] - h * s[`${q}_dot`];
    }
    const a = this.placed(k, { ...s, ...ahead }, h), b = this.placed(k, { ...s, ...behind }, -h);
    return [(a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h)];
  }

  /** The rate controls body k can set: those of the coordinates it owns. */
  rateNames(k) {
    if (this.player.dim === 3 || !this.player.controls || !this.player.onDrag) return [];
    return (this.player.ownersOf[k] || []).map((q) => `${q}_dot`).filter((n) => this.player.controls(n));
  }

  /** Seconds of motion the arrow of body k shows: TAU, or less so the fastest allowed start stays in view. */
  tau(k) {
    const s = this.initialState(), rates = Object.keys(s).filter((n) => n.endsWith("_dot"));
    // the fastest screen speed the rate controls allow: Σ_j |∂(screen)/∂q̇_j| max|q̇_j|
    let fastest = 0;
    for (const name of this.rateNames(k)) {
      const r = this.player.controls(name);
      const v = this.velocity(k, Object.fromEntries(rates.map((n) => [n, n === name ? 1 : 0])));
      fastest += Math.hypot(...v) * Math.max(Math.abs(r.min), Math.abs(r.max));
    }
    const reach = REACH * Math.min(this.player.canvas.width, this.player.canvas.height);
    return fastest > 0 ? Math.min(TAU, reach / fastest) : TAU;
  }

  /** The selected body's velocity handle: {k, x, y, bx, by, ux, uy, len} in device pixels, or null. */
  handle() {
    if (!this.player.run) return null;
    const k = this.player.selected, names = this.rateNames(k);
    if (!names.length) return null;
    const s = this.initialState(), [bx, by] = this.placed(k, s);
    // the direction the body can move in: the screen image of the first owned rate
    const probe = this.velocity(k, Object.fromEntries(Object.keys(s).filter((n) => n.endsWith("_dot")).map((n) => [n, n === names[0] ? 1 : 0])));
    const [vx, vy] = this.velocity(k);
    const dpr = window.devicePixelRatio || 1, tau = this.tau(k);
    if (!Number.isFinite(bx + by + vx + vy) || Math.hypot(...probe) * tau < 1e-3 * dpr) return null;
    // the arrow: tau seconds of motion, from HANDLE_OFFSET beyond the centre (the direction of
    // motion, or of the first coordinate's motion at rest)
    const len = Math.hypot(vx, vy) * tau, u = len > 1e-9 ? [vx, vy] : probe, n = Math.hypot(...u);
    const ux = u[0] / n, uy = u[1] / n, off = HANDLE_OFFSET * dpr;
    return { k, bx, by, ux, uy, len, x: bx + ux * (off + len), y: by + uy * (off + len) };
  }

  /** Is the pointer on the velocity handle (and nearer to it than to the body's centre)? */
  onHandle(x, y) {
    const h = this.player.index === 0 ? this.handle() : null;
    if (!h) return null;
    const dpr = window.devicePixelRatio || 1, d = Math.hypot(x - h.x, y - h.y);
    return d < HANDLE_GRAB * dpr && d < Math.hypot(x - h.bx, y - h.by) ? h : null;
  }

  /** Initial rates of body k that put its handle nearest the screen point (x, y). */
  solveRates(k, x, y) {
    const names = this.rateNames(k);
    const [bx, by] = this.placed(k, this.initialState());
    // undo the handle's offset: the arrow's own tip lies HANDLE_OFFSET nearer the body
    // (the pointer within the offset of the body's centre asks for rest)
    const dpr = window.devicePixelRatio || 1, dx = x - bx, dy = y - by, r = Math.hypot(dx, dy);
    const keep = r > 0 ? Math.max(0, r - HANDLE_OFFSET * dpr) / r : 0;
    const tx = bx + dx * keep, ty = by + dy * keep, tau = this.tau(k);
    return this.fitTo(names, tx, ty, (values) => {
      const [vx, vy] = this.velocity(k, values);
      return [bx + tau * vx, by + tau * vy];
    });
  }
}
