/**
 * camera.js — how the mechanism's world coordinates land on the canvas (animation.js).
 *
 *   const camera = new Camera(dim, view);   view: {yaw, pitch} the page opens on (3-D), or null
 *   camera.fit(visit, width, height, dpr, top)  equal scales on both screen axes, everything visit(grow)
 *                                           passes to grow(x, y, z) in view, with a margin, and `top`
 *                                           device pixels more kept free at the top (a message's band)
 *   camera.screenOf([x, y, z])              device pixels on the canvas
 *   camera.turn(start, dx, dy, dpr)         3-D: the view turned by a drag of (dx, dy) pixels
 *
 * 2-D mechanisms use the spec's two axes (the second points up); 3-D ones an orthographic view
 * turned about the vertical axis (yaw), then tilted (pitch).
 */
// the margin kept about the drawing, CSS pixels
export const MARGIN = 24;

export class Camera {
  constructor(dim, view = null) {
    this.dim = dim;
    // 3-D only: the mechanism's own opening view (app/viz/mechanism.py, Family.view), else a general one
    this.view = view ? { yaw: view.yaw, pitch: view.pitch } : { yaw: -0.6, pitch: 0.35 };
    this.frame = null; // {scale, u0, v0, cx, cy}: the view's centre and device pixels per metre
  }

  project(x, y, z) {
    // 2-D: the spec's two axes (the second points up); 3-D: turn about the vertical axis, then tilt
    if (this.dim !== 3) return [x, y];
    const { yaw, pitch } = this.view;
    const xr = x * Math.cos(yaw) - y * Math.sin(yaw);
    const yr = x * Math.sin(yaw) + y * Math.cos(yaw);
    return [xr, z * Math.cos(pitch) + yr * Math.sin(pitch)];
  }

  toScreen(u, v) {
    const f = this.frame;
    return [f.cx + (u - f.u0) * f.scale, f.cy - (v - f.v0) * f.scale];
  }

  screenOf(xyz) {
    const [u, v] = this.project(xyz[0], xyz[1], xyz[2] ?? 0);
    return this.toScreen(u, v);
  }

  fit(visit, W, H, dpr, top = 0) {
    let ulo = Infinity, uhi = -Infinity, vlo = Infinity, vhi = -Infinity;
    visit((x, y, z) => {
      const [u, v] = this.project(x, y, z);
      if (!Number.isFinite(u) || !Number.isFinite(v)) return;
      ulo = Math.min(ulo, u); uhi = Math.max(uhi, u); vlo = Math.min(vlo, v); vhi = Math.max(vhi, v);
    });
    if (!Number.isFinite(ulo)) { ulo = -1; uhi = 1; vlo = -1; vhi = 1; }
    const pad = MARGIN * dpr;
    const su = Math.max(uhi - ulo, 1e-6), sv = Math.max(vhi - vlo, 1e-6);
    // a canvas narrower than its padding (while the page is laid out) keeps a positive scale
    const room = (side, kept = 0) => Math.max(side - 2 * pad - kept, side / 2, 1);
    const scale = Math.min(room(W) / su, room(H, top) / sv);
    // the drawing centred in what is left below the kept band
    this.frame = { scale, u0: (ulo + uhi) / 2, v0: (vlo + vhi) / 2, cx: W / 2, cy: (H + Math.min(top, H / 2)) / 2 };
  }

  turn(start, dx, dy, dpr) {
    this.view.yaw = start.yaw + dx / (120 * dpr);
    this.view.pitch = Math.max(-1.4, Math.min(1.4, start.pitch + dy / (120 * dpr)));
  }
}
