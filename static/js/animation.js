/**
 * animation.js — the mechanism drawn on our own <canvas>, played with requestAnimationFrame.
 *
 *   const player = new Player(root, spec, { onFrame, onDrag });
 *   player.load(run);      // run from simulation.js prepareRun(); keeps the current instant
 *   player.play(); player.pause(); player.toggle(); player.seek(i);
 *
 * root holds canvas.mechanism, [data-action="play"], input.scrub (a range over sample
 * indices), select.speed and output.time.  spec is the scene's mechanism
 * (app/viz/mechanism.py): points, links and fixed curves as expression trees in
 * {parameters, q, q_dot, t} (curves in s and the run's extent qmin_<q>, qmax_<q>).
 * Positions are computed once per run; a frame only redraws the canvas (no plotting
 * library), so playback keeps up with the display.  3-D mechanisms are drawn in an
 * orthographic view that turns when the background is dragged.
 *
 * Direct manipulation: dragging a body (or the arrow keys while the canvas has focus;
 * N picks the next body) moves it along its constraint; onDrag({q: value, ...}) receives
 * the initial coordinates that put it nearest the pointer, found by Gauss–Newton steps on
 * the body's on-screen position as a function of the coordinates it owns.
 *
 * At t = 0 the selected body also carries its initial velocity: an arrow ending in a round
 * handle.  Dragging the handle (or Shift with the arrow keys) sets the initial rates q_dot of
 * the coordinates the body owns, by least squares on the handle's screen position, clamped to
 * the controls' ranges.  2-D views only, and only where those rate controls exist.
 *
 * For tests and tools: root.dataset.frame is the sample shown; canvas.dataset.bodies lists
 * each body's label and position in CSS pixels of the canvas; canvas.dataset.handle is the
 * velocity handle's position in CSS pixels ("" when none is shown).
 */
import { compile, symbolsOf } from "./expr.js";

const MASS_COLORS = ["#0b5cad", "#b34700", "#2e7d32", "#6a1b9a"];
const FORCE_COLORS = ["#7b1fa2", "#00796b", "#c62828"];
const TRAIL_SECONDS = 1.5;
const MAX_TRAIL = 90;
const GRAB_RADIUS = 26; // CSS pixels around a body that start a drag
// the velocity arrow: TAU seconds of motion at the initial velocity (less where the fastest
// start the controls allow would leave the view), drawn beyond a fixed offset from the
// body's centre so that at rest the handle sits beside the body, not on it
const TAU = 0.25;
const REACH = 0.4; // the longest arrow, as a fraction of the canvas's shorter side
const HANDLE_OFFSET = 24; // CSS pixels from the body's centre to the handle at rest
const HANDLE_RADIUS = 7;
const HANDLE_GRAB = 16;

function mix(hex, amount) {
  // blend a colour toward white: amount 0 -> white, 1 -> the colour (a fading trail without alpha)
  const n = parseInt(hex.slice(1), 16);
  const c = [(n >> 16) & 255, (n >> 8) & 255, n & 255].map((v) => Math.round(255 + (v - 255) * amount));
  return `rgb(${c.join(",")})`;
}

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
    this.playing = false;
    this.index = 0;
    this.frames = 0;
    this.dim = spec.dim;
    this.view = { yaw: -0.6, pitch: 0.35 }; // 3-D only
    this.points = spec.points.map((p) => p.xyz.map(compile));
    this.tilts = spec.points.map((p) => (p.block ? compile(p.block) : null)); // blocks: the slope they rest on
    this.masses = spec.points.map((p, i) => (p.mass ? i : -1)).filter((i) => i >= 0);
    this.fixed = spec.points.map((p, i) => (p.mass || p.hidden ? -1 : i)).filter((i) => i >= 0);
    this.wheels = (spec.wheels || []).map((w) => ({ ...w, r: compile(w.radius) }));
    this.showForces = root.querySelector("input.show-forces");
    this.showForces?.addEventListener("change", () => { if (this.run) this.draw(this.index); });
    this.selected = 0;
    this.button?.addEventListener("click", () => this.toggle());
    this.scrub?.addEventListener("input", () => { this.pause(); this.seek(Number(this.scrub.value)); });
    this.tick = this.tick.bind(this);
    this.bindPointer();
    this.bindKeys();
    if ("ResizeObserver" in window) new ResizeObserver(() => this.resize()).observe(this.canvas);
    this.resize();
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

  // ---- geometry ---------------------------------------------------------------------------

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
        const cols = fs.map(() => new Float64Array(161));
        for (let k = 0; k <= 160; k++) {
          const e = { ...env, s: lo + ((hi - lo) * k) / 160 };
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

  /** Per force of constraint: its values along the run and the largest size (for a common scale). */
  forceSeries(run) {
    const out = [];
    let largest = 0;
    for (const f of this.spec.forces || []) {
      const values = run.forces[f.name];
      if (!values || !values.length) continue;
      for (const v of values) if (Number.isFinite(v)) largest = Math.max(largest, Math.abs(v));
      out.push({ ...f, values, dir: f.direction.map(compile) });
    }
    return { list: out, largest };
  }

  fit() {
    // equal scales on both screen axes, everything the run visits in view, with a margin
    if (!this.xyz) return;
    let ulo = Infinity, uhi = -Infinity, vlo = Infinity, vhi = -Infinity;
    const grow = (x, y, z) => {
      const [u, v] = this.project(x, y, z);
      if (!Number.isFinite(u) || !Number.isFinite(v)) return;
      ulo = Math.min(ulo, u); uhi = Math.max(uhi, u); vlo = Math.min(vlo, v); vhi = Math.max(vhi, v);
    };
    const stride = Math.max(1, Math.floor(this.run.n / 400));
    for (const a of this.xyz) for (let i = 0; i < this.run.n; i += stride) grow(a[0][i], a[1][i], a[2] ? a[2][i] : 0);
    for (const a of this.xyz) { const i = this.run.n - 1; grow(a[0][i], a[1][i], a[2] ? a[2][i] : 0); }
    for (const c of this.curveCols) {
      const frames = c.moving ? Array.from({ length: 24 }, (_, j) => Math.round((j * (this.run.n - 1)) / 23)) : [null];
      for (const f of frames) {
        const cols = f === null ? c.cols : c.at(this.run.envAt(f));
        for (let k = 0; k < cols[0].length; k++) grow(cols[0][k], cols[1][k], cols[2] ? cols[2][k] : 0);
      }
    }
    if (!Number.isFinite(ulo)) { ulo = -1; uhi = 1; vlo = -1; vhi = 1; }
    const W = this.canvas.width, H = this.canvas.height, pad = 24 * (window.devicePixelRatio || 1);
    const su = Math.max(uhi - ulo, 1e-6), sv = Math.max(vhi - vlo, 1e-6);
    const scale = Math.min((W - 2 * pad) / su, (H - 2 * pad) / sv);
    this.frame = { scale, u0: (ulo + uhi) / 2, v0: (vlo + vhi) / 2, cx: W / 2, cy: H / 2 };
  }

  load(run) {
    const keep = this.run ? this.run.t[this.index] : 0;
    this.run = run;
    this.xyz = this.positions(run);
    this.curveCols = this.curves(run);
    this.unsteady = this.unsteadyLinks(run);
    this.forces = this.forceSeries(run);
    const dt = run.n > 1 ? run.t[1] - run.t[0] : 1;
    this.dt = dt;
    this.trailLength = Math.max(2, Math.min(MAX_TRAIL, Math.round(TRAIL_SECONDS / dt)));
    this.ownersOf = this.owners(run.data.coordinates);
    // while a body is dragged the view stays put, so the body follows the pointer
    if (!this.dragging || !this.frame) this.fit();
    if (this.scrub) this.scrub.max = String(run.n - 1);
    // a new run (an input changed) keeps the instant shown, so dragging a slider does not jump back
    this.seek(Math.min(run.n - 1, Math.round(keep / dt)));
  }

  // ---- drawing ----------------------------------------------------------------------------

  at(p, i) {
    const a = this.xyz[p];
    return this.screenOf([a[0][i], a[1][i], a[2] ? a[2][i] : 0]);
  }

  draw(i) {
    const ctx = this.ctx, dpr = window.devicePixelRatio || 1, run = this.run;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    ctx.lineCap = "round"; ctx.lineJoin = "round";
    const drawn = { links: 0, wheels: 0, slack: false, forces: [], event: "", none: !!this.spec.none };
    if (this.spec.none) {
      this.message(ctx, dpr, "No picture of its own: this system has no particle positions.", this.canvas.height / 2);
    }
    // fixed bodies (a ramp, a wedge), then the curves: the ground, wires, dashed guides
    for (const solid of this.spec.solids || []) {
      ctx.beginPath();
      solid.corners.forEach((p, k) => { const [x, y] = this.at(p, i); if (k) ctx.lineTo(x, y); else ctx.moveTo(x, y); });
      ctx.closePath();
      ctx.fillStyle = "#e3e7ec"; ctx.fill();
      ctx.strokeStyle = "#6b747e"; ctx.lineWidth = 2 * dpr; ctx.stroke();
    }
    for (const c of this.curveCols) this.drawCurve(ctx, c, c.moving ? c.at(run.envAt(i)) : c.cols, dpr);
    if (!this.spec.none) this.scaleBar(ctx, dpr);
    // fading trails first, so that strings, rods and springs are drawn over them
    this.masses.forEach((p, k) => {
      const color = MASS_COLORS[k % MASS_COLORS.length];
      for (let j = Math.max(0, i - this.trailLength + 1); j < i; j++) {
        const age = (i - j) / this.trailLength;
        const [x, y] = this.at(p, j);
        ctx.fillStyle = mix(color, 0.5 * (1 - age) + 0.06);
        ctx.beginPath(); ctx.arc(x, y, 2.5 * dpr, 0, 2 * Math.PI); ctx.fill();
      }
    });
    // links: rods, springs (a zigzag that stretches with them) and strings (slack where the
    // tension the engine derives for them is negative)
    const tension = this.spec.slack && run.forces[this.spec.slack] ? run.forces[this.spec.slack][i] : null;
    const slack = tension !== null && tension !== undefined && tension < 0;
    this.spec.links.forEach((link, j) => {
      if (this.unsteady.has(j)) return;
      const [x0, y0] = this.at(link.from, i), [x1, y1] = this.at(link.to, i);
      const string = link.style === "string";
      ctx.strokeStyle = string && slack ? "#c26100" : "#1b1f24";
      ctx.lineWidth = (string ? 1.5 : link.style === "spring" ? 1.8 : 3) * dpr;
      ctx.setLineDash(string && slack ? [5 * dpr, 3 * dpr] : []);
      ctx.beginPath();
      if (link.style === "spring") this.zigzag(ctx, x0, y0, x1, y1, dpr);
      else if (string && slack) {
        // a slack string sags: a curve through a point below the straight line's middle
        const len = Math.hypot(x1 - x0, y1 - y0);
        ctx.moveTo(x0, y0);
        ctx.quadraticCurveTo((x0 + x1) / 2 + 0.15 * len, (y0 + y1) / 2 + 0.3 * len, x1, y1);
      } else { ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); }
      ctx.stroke();
      drawn.links++;
    });
    ctx.setLineDash([]);
    drawn.slack = slack;
    // wheels: the rim, the hub, and the string wrapped over its top (a fixed pulley) or under its
    // bottom (the movable one)
    for (const w of this.wheels) {
      const [x, y] = this.at(w.at, i);
      const env = run.envAt(i), r = Math.abs(w.r(env)) * this.frame.scale;
      if (!Number.isFinite(r)) continue;
      ctx.fillStyle = "#fff"; ctx.strokeStyle = "#6b747e"; ctx.lineWidth = 2 * dpr;
      ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      ctx.fillStyle = "#6b747e"; ctx.beginPath(); ctx.arc(x, y, 3 * dpr, 0, 2 * Math.PI); ctx.fill();
      ctx.strokeStyle = slack ? "#c26100" : "#1b1f24"; ctx.lineWidth = 1.5 * dpr;
      ctx.beginPath();
      if (w.wrap === "top") ctx.arc(x, y, r, Math.PI, 2 * Math.PI); else ctx.arc(x, y, r, 0, Math.PI);
      ctx.stroke();
      drawn.wheels++;
    }
    ctx.fillStyle = "#1b1f24";
    for (const p of this.fixed) {
      const [x, y] = this.at(p, i);
      ctx.beginPath(); ctx.arc(x, y, 4 * dpr, 0, 2 * Math.PI); ctx.fill();
    }
    const bodies = [];
    ctx.font = `${13 * dpr}px system-ui, sans-serif`;
    const placed = this.masses.map((p) => this.at(p, i));
    if (this.masses.length > 1) {
      // labels first, so no label hides a body; each goes to the corner beside its body where it
      // covers the fewest rods, strings, springs and bodies and stays inside the canvas, with a
      // white halo so that bodies that meet keep readable labels
      const segments = this.spec.links.map((link) => [this.at(link.from, i), this.at(link.to, i)]);
      const cost = (x0, y0, x1, y1) => {
        let c = 0;
        if (x0 < 2 * dpr || x1 > this.canvas.width - 2 * dpr || y0 < 2 * dpr || y1 > this.canvas.height - 2 * dpr) c += 100;
        const inside = (x, y) => x >= x0 && x <= x1 && y >= y0 && y <= y1;
        for (const [[ax, ay], [bx, by]] of segments) {
          for (let f = 0; f <= 1; f += 0.125) if (inside(ax + (bx - ax) * f, ay + (by - ay) * f)) { c += 1; break; }
        }
        for (const [bx, by] of placed) if (inside(bx, by) || inside(bx - 10 * dpr, by) || inside(bx + 10 * dpr, by)) c += 2;
        // labels already placed, and the velocity handle (drawn at the first instant), weigh most
        for (const [a0, b0, a1, b1] of boxes) if (x0 < a1 && x1 > a0 && y0 < b1 && y1 > b0) c += 5;
        if (grip) {
          const r = (HANDLE_RADIUS + 2) * dpr;
          if (grip.x + r > x0 && grip.x - r < x1 && grip.y + r > y0 && grip.y - r < y1) c += 4;
        }
        return c;
      };
      const boxes = [];
      const grip = i === 0 ? this.handle() : null;
      this.masses.forEach((p, k) => {
        const [x, y] = placed[k], label = this.spec.points[p].label, w = ctx.measureText(label).width, h = 13 * dpr;
        let best = null;
        for (const [sx, sy] of [[1, -1], [-1, -1], [1, 1], [-1, 1]]) {
          const lx = x + sx * 14 * dpr, ly = y + (sy < 0 ? -12 : 22) * dpr;
          const x0 = sx > 0 ? lx : lx - w, c = cost(x0, ly - h, x0 + w, ly + 3 * dpr);
          if (!best || c < best.c) best = { c, lx, ly, align: sx > 0 ? "left" : "right", box: [x0, ly - h, x0 + w, ly + 3 * dpr] };
        }
        boxes.push(best.box);
        ctx.textAlign = best.align;
        ctx.strokeStyle = "#fff"; ctx.lineWidth = 4 * dpr;
        ctx.strokeText(label, best.lx, best.ly);
        ctx.fillStyle = "#1b1f24";
        ctx.fillText(label, best.lx, best.ly);
      });
      ctx.textAlign = "left";
    }
    this.masses.forEach((p, k) => {
      const [x, y] = placed[k];
      const selected = k === this.selected && this.focused;
      ctx.fillStyle = MASS_COLORS[k % MASS_COLORS.length];
      ctx.strokeStyle = selected ? "#ffbf47" : "#1b1f24";
      ctx.lineWidth = (selected ? 4 : 1.5) * dpr;
      const tilt = this.tilts[p];
      if (tilt) {
        // a block: a rectangle whose base lies on its slope, the particle at the middle of the base
        const a = tilt(run.envAt(i)), W = 15 * dpr, H = 18 * dpr;
        const dx = Math.cos(a), dy = -Math.sin(a), nx = -Math.sin(a), ny = -Math.cos(a); // along, and up from, the slope on screen
        ctx.beginPath();
        ctx.moveTo(x - W * dx, y - W * dy); ctx.lineTo(x + W * dx, y + W * dy);
        ctx.lineTo(x + W * dx + H * nx, y + W * dy + H * ny); ctx.lineTo(x - W * dx + H * nx, y - W * dy + H * ny);
        ctx.closePath(); ctx.fill(); ctx.stroke();
      } else {
        ctx.beginPath(); ctx.arc(x, y, 10 * dpr, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      }
      bodies.push({ label: this.spec.points[p].label, x: Math.round(x / dpr), y: Math.round(y / dpr) });
    });
    if (this.showForces?.checked) drawn.forces = this.drawForces(ctx, i, dpr);
    if (slack) this.message(ctx, dpr, "The string is slack (its tension would be negative).", 18 * dpr);
    const event = run.stats && run.stats.event;
    if (event && i === run.n - 1) {
      drawn.event = event.name;
      this.message(ctx, dpr, `t = ${Number(event.t.toFixed(3))} s: ${event.message}`, 18 * dpr);
    }
    this.canvas.dataset.bodies = JSON.stringify(bodies);
    this.canvas.dataset.drawn = JSON.stringify(drawn);
    const handle = i === 0 ? this.handle() : null;
    if (handle) this.drawHandle(ctx, handle, dpr);
    this.canvas.dataset.handle = handle ? JSON.stringify({ x: Math.round(handle.x / dpr), y: Math.round(handle.y / dpr) }) : "";
    this.frames++;
  }

  drawCurve(ctx, c, cols, dpr) {
    const style = c.style;
    ctx.strokeStyle = style === "guide" ? "#8c959f" : "#4b535c";
    ctx.lineWidth = (style === "guide" ? 1.5 : 2.5) * dpr;
    ctx.setLineDash(style === "guide" ? [4 * dpr, 4 * dpr] : []);
    const pts = [];
    for (let k = 0; k < cols[0].length; k++) pts.push(this.screenOf([cols[0][k], cols[1][k], cols[2] ? cols[2][k] : 0]));
    ctx.beginPath();
    let pen = false;
    for (const [x, y] of pts) {
      if (!Number.isFinite(x) || !Number.isFinite(y)) { pen = false; continue; }
      if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
      pen = true;
    }
    ctx.stroke();
    ctx.setLineDash([]);
    // the ground, a ceiling or a wall: short slanted hatches on the side away from the motion
    const away = { ground: [-1, 1], ceiling: [1, -1], "wall-left": [-1, 1], "wall-right": [1, 1] }[style];
    if (!away) return;
    const [x0, y0] = pts[0], [x1, y1] = pts[pts.length - 1], len = Math.hypot(x1 - x0, y1 - y0);
    if (!(len > 0)) return;
    const gap = 10 * dpr, h = 7 * dpr, count = Math.floor(len / gap);
    ctx.lineWidth = 1.2 * dpr; ctx.strokeStyle = "#8c959f";
    ctx.beginPath();
    for (let k = 0; k <= count; k++) {
      const x = x0 + ((x1 - x0) * k) / count, y = y0 + ((y1 - y0) * k) / count;
      const vertical = style.startsWith("wall");
      ctx.moveTo(x, y);
      ctx.lineTo(x + (vertical ? away[0] * h : away[0] * h * 0.7), y + (vertical ? away[1] * h * 0.7 : away[1] * h));
    }
    ctx.stroke();
  }

  /** Arrows of the forces of constraint at instant i, on one scale for the whole run, with a legend. */
  drawForces(ctx, i, dpr) {
    const { list, largest } = this.forces;
    if (!list.length || !(largest > 0)) return [];
    const env = this.run.envAt(i), longest = 0.3 * Math.min(this.canvas.width, this.canvas.height);
    const perNewton = longest / largest; // screen pixels per newton
    const out = [];
    list.forEach((f, j) => {
      const value = f.values[i];
      if (!Number.isFinite(value)) return;
      // from its point of application where the spec names one (the middle of the wedge's base), else its body
      const p = Number.isInteger(f.at) ? f.at : this.masses[f.on], a = this.xyz[p];
      const r = a.map((col) => col[i]), d = f.dir.map((g) => g(env));
      // the arrow is the vector F (grad g / |grad g|) drawn at perNewton screen pixels per newton
      // (a negative F points against grad g); in 3-D it is projected like everything else
      const len = (value * perNewton) / this.frame.scale;
      const [x, y] = this.screenOf([r[0], r[1], r[2] ?? 0]);
      const [tx, ty] = this.screenOf([r[0] + len * d[0], r[1] + len * d[1], (r[2] ?? 0) + len * (d[2] ?? 0)]);
      if (!Number.isFinite(tx + ty)) return;
      const color = FORCE_COLORS[j % FORCE_COLORS.length];
      this.arrow(ctx, x, y, tx, ty, color, dpr);
      out.push({ name: f.name, value, x: Math.round(x / dpr), y: Math.round(y / dpr), tx: Math.round(tx / dpr), ty: Math.round(ty / dpr) });
    });
    // the legend, top right on a white card: a round force (at most the largest) and its arrow,
    // then each force's colour and name
    const pow = Math.pow(10, Math.floor(Math.log10(largest)));
    const unit = [5, 2, 1].map((m) => m * pow).find((v) => v <= largest) || pow;
    ctx.font = `${12 * dpr}px system-ui, sans-serif`;
    const names = list.map((f) => `→ ${f.name}`);
    const width = Math.max(unit * perNewton + 60 * dpr, ...names.map((t) => ctx.measureText(t).width)) + 12 * dpr;
    const W = this.canvas.width, x1 = W - 12 * dpr, top = 30 * dpr, rowH = 16 * dpr;
    ctx.fillStyle = "rgba(255,255,255,0.9)";
    ctx.fillRect(x1 - width, top - 12 * dpr, width + 6 * dpr, rowH * (names.length + 1) + 6 * dpr);
    ctx.textAlign = "right";
    names.forEach((text, j) => {
      ctx.fillStyle = FORCE_COLORS[j % FORCE_COLORS.length];
      ctx.fillText(text, x1, top + j * rowH);
    });
    const y = top + names.length * rowH - 4 * dpr, x0 = x1 - unit * perNewton;
    this.arrow(ctx, x0, y, x1, y, "#4b535c", dpr);
    ctx.fillStyle = "#4b535c"; ctx.fillText(`${Number(unit.toPrecision(2))} N`, x0 - 6 * dpr, y + 4 * dpr);
    ctx.textAlign = "left";
    return out;
  }

  arrow(ctx, x0, y0, x1, y1, color, dpr) {
    const len = Math.hypot(x1 - x0, y1 - y0);
    ctx.strokeStyle = color; ctx.fillStyle = color; ctx.lineWidth = 2.5 * dpr;
    ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); ctx.stroke();
    if (len < 2 * dpr) return;
    const ux = (x1 - x0) / len, uy = (y1 - y0) / len, s = Math.min(9 * dpr, len / 2);
    ctx.beginPath();
    ctx.moveTo(x1, y1);
    ctx.lineTo(x1 - ux * s - uy * s * 0.5, y1 - uy * s + ux * s * 0.5);
    ctx.lineTo(x1 - ux * s + uy * s * 0.5, y1 - uy * s - ux * s * 0.5);
    ctx.closePath(); ctx.fill();
  }

  /** Text across the canvas at height y (wrapped to its width), on a white band. */
  message(ctx, dpr, text, y) {
    ctx.font = `${13 * dpr}px system-ui, sans-serif`;
    const room = this.canvas.width - 24 * dpr, lines = [];
    for (const word of text.split(" ")) {
      const last = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
      if (lines.length && ctx.measureText(last).width <= room) lines[lines.length - 1] = last;
      else lines.push(word);
    }
    const h = 17 * dpr, w = Math.min(room, Math.max(...lines.map((l) => ctx.measureText(l).width)));
    const x = (this.canvas.width - w) / 2, top = Math.max(4 * dpr, y - 14 * dpr - ((lines.length - 1) * h) / 2);
    ctx.fillStyle = "rgba(255,255,255,0.9)";
    ctx.fillRect(x - 6 * dpr, top, w + 12 * dpr, lines.length * h + 6 * dpr);
    ctx.fillStyle = "#1b1f24";
    lines.forEach((line, k) => ctx.fillText(line, x, top + 14 * dpr + k * h, room));
  }

  zigzag(ctx, x0, y0, x1, y1, dpr) {
    const dx = x1 - x0, dy = y1 - y0, len = Math.hypot(dx, dy) || 1;
    const nx = -dy / len, ny = dx / len, turns = 10, amp = 6 * dpr;
    ctx.moveTo(x0, y0);
    for (let k = 1; k < 2 * turns; k++) {
      const f = 0.1 + (0.8 * k) / (2 * turns), s = k % 2 ? amp : -amp;
      ctx.lineTo(x0 + dx * f + nx * s, y0 + dy * f + ny * s);
    }
    ctx.lineTo(x1, y1);
  }

  scaleBar(ctx, dpr) {
    // a bar of a round length (1, 2 or 5 times a power of ten metres) in the lower left corner
    const target = 90 * dpr / this.frame.scale;
    const p = Math.pow(10, Math.floor(Math.log10(target)));
    const len = [5, 2, 1].map((m) => m * p).find((v) => v <= target) || p;
    const x = 12 * dpr, y = this.canvas.height - 10 * dpr, w = len * this.frame.scale;
    ctx.strokeStyle = "#4b535c"; ctx.lineWidth = 2 * dpr;
    ctx.beginPath(); ctx.moveTo(x, y - 5 * dpr); ctx.lineTo(x, y); ctx.lineTo(x + w, y); ctx.lineTo(x + w, y - 5 * dpr); ctx.stroke();
    ctx.fillStyle = "#4b535c"; ctx.font = `${12 * dpr}px system-ui, sans-serif`;
    ctx.fillText(`${Number(len.toPrecision(2))} m`, x + w + 6 * dpr, y);
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
      const parts = data.coordinates.map((q) => `${data.labels[q] || q} = ${state[q][this.index].toFixed(3)} ${data.units[q] || ""}`.trim());
      this.timeOut.textContent = [`t = ${this.run.t[this.index].toFixed(2)} s`, ...parts].join(" · ");
    }
    this.onFrame(this.index);
  }

  speed() {
    return this.speedSelect ? Number(this.speedSelect.value) : 1;
  }

  play() {
    if (!this.run || this.playing) return;
    this.playing = true;
    if (this.index >= this.run.n - 1) this.index = 0;
    this.simTime = this.run.t[this.index];
    this.last = null;
    if (this.button) { this.button.textContent = "Pause"; this.button.setAttribute("aria-pressed", "true"); }
    this.root.dataset.playing = "true";
    requestAnimationFrame(this.tick);
  }

  pause() {
    this.playing = false;
    if (this.button) { this.button.textContent = "Play"; this.button.setAttribute("aria-pressed", "false"); }
    this.root.dataset.playing = "false";
  }

  toggle() {
    if (this.playing) this.pause(); else this.play();
  }

  tick(now) {
    if (!this.playing || !this.run) return;
    if (this.last !== null) this.simTime += ((now - this.last) / 1000) * this.speed();
    this.last = now;
    const t = this.run.t, end = t[t.length - 1];
    if (this.simTime > end) this.simTime = 0; // loop
    const i = Math.min(t.length - 1, Math.round(this.simTime / this.dt));
    if (i !== this.index) this.seek(i);
    requestAnimationFrame(this.tick);
  }

  // ---- direct manipulation ----------------------------------------------------------------

  pointer(event) {
    const r = this.canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
    return [(event.clientX - r.left) * dpr, (event.clientY - r.top) * dpr];
  }

  grab(x, y) {
    // the body under the pointer (at the instant shown), if any
    if (!this.run) return -1;
    const dpr = window.devicePixelRatio || 1;
    let best = -1, bestD = GRAB_RADIUS * dpr;
    this.masses.forEach((p, k) => {
      const [px, py] = this.at(p, this.index);
      const d = Math.hypot(px - x, py - y);
      if (d < bestD) { best = k; bestD = d; }
    });
    return best;
  }

  /** The body's screen position with the initial coordinates `values` (others as they are), at time t. */
  placed(k, values, t = 0) {
    const env = { ...this.run.envAt(0), ...values, t };
    return this.screenOf(this.points[this.masses[k]].map((f) => f(env)));
  }

  /** Initial coordinates of body k that bring it nearest the screen point (x, y). */
  solve(k, x, y) {
    const names = (this.ownersOf[k] || []).filter((q) => this.controls && this.controls(q));
    return this.fitTo(names, x, y, (values) => this.placed(k, values));
  }

  /** Values of the controls `names` that bring the screen point at(values) nearest (x, y): Gauss–Newton, clamped to the controls' ranges. */
  fitTo(names, x, y, at) {
    if (!names.length) return null;
    const ranges = names.map((q) => this.controls(q));
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

  // ---- the initial velocity ------------------------------------------------------------

  /** The initial state as the controls hold it now (the run may lag a frame behind a drag). */
  initialState(values = {}) {
    const state = {};
    for (const q of this.run.data.coordinates) {
      for (const name of [q, `${q}_dot`]) {
        const r = this.controls && this.controls(name);
        state[name] = r ? r.value : this.run.envAt(0)[name];
      }
    }
    return { ...state, ...values };
  }

  /** Screen velocity of body k (device pixels per second) with the initial state overridden by `values`. */
  velocity(k, values = {}) {
    const s = this.initialState(values), h = 1e-5, ahead = {}, behind = {};
    // v = Σ ∂r/∂q_k q̇_k + ∂r/∂t: the derivative of the screen position along (q̇, 1),
    // a central difference of r(q ± h q̇, t ± h)
    for (const q of this.run.data.coordinates) {
      ahead[q] = s[q] + h * s[`${q}_dot`];
      behind[q] = s[q] - h * s[`${q}_dot`];
    }
    const a = this.placed(k, { ...s, ...ahead }, h), b = this.placed(k, { ...s, ...behind }, -h);
    return [(a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h)];
  }

  /** The rate controls body k can set: those of the coordinates it owns. */
  rateNames(k) {
    if (this.dim === 3 || !this.controls || !this.onDrag) return [];
    return (this.ownersOf[k] || []).map((q) => `${q}_dot`).filter((n) => this.controls(n));
  }

  /** Seconds of motion the arrow of body k shows: TAU, or less so the fastest allowed start stays in view. */
  tau(k) {
    const s = this.initialState(), rates = Object.keys(s).filter((n) => n.endsWith("_dot"));
    // the fastest screen speed the rate controls allow: Σ_j |∂(screen)/∂q̇_j| max|q̇_j|
    let fastest = 0;
    for (const name of this.rateNames(k)) {
      const r = this.controls(name);
      const v = this.velocity(k, Object.fromEntries(rates.map((n) => [n, n === name ? 1 : 0])));
      fastest += Math.hypot(...v) * Math.max(Math.abs(r.min), Math.abs(r.max));
    }
    const reach = REACH * Math.min(this.canvas.width, this.canvas.height);
    return fastest > 0 ? Math.min(TAU, reach / fastest) : TAU;
  }

  /** The selected body's velocity handle: {k, x, y, bx, by, ux, uy, len} in device pixels, or null. */
  handle() {
    if (!this.run) return null;
    const k = this.selected, names = this.rateNames(k);
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

  drawHandle(ctx, h, dpr) {
    const color = "#c2185b", r0 = 11 * dpr, x0 = h.bx + h.ux * r0, y0 = h.by + h.uy * r0;
    ctx.strokeStyle = color; ctx.fillStyle = color; ctx.lineWidth = 2.5 * dpr;
    ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(h.x, h.y); ctx.stroke();
    if (h.len > 2 * dpr) {
      // an arrowhead just short of the handle, pointing along the velocity
      const back = (HANDLE_RADIUS + 2) * dpr, tx = h.x - h.ux * back, ty = h.y - h.uy * back, s = 7 * dpr;
      ctx.beginPath();
      ctx.moveTo(tx, ty);
      ctx.lineTo(tx - h.ux * s - h.uy * s * 0.6, ty - h.uy * s + h.ux * s * 0.6);
      ctx.lineTo(tx - h.ux * s + h.uy * s * 0.6, ty - h.uy * s - h.ux * s * 0.6);
      ctx.closePath(); ctx.fill();
    }
    ctx.fillStyle = "#fff";
    ctx.beginPath(); ctx.arc(h.x, h.y, HANDLE_RADIUS * dpr, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
  }

  /** Is the pointer on the velocity handle (and nearer to it than to the body's centre)? */
  onHandle(x, y) {
    const h = this.index === 0 ? this.handle() : null;
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

  bindPointer() {
    const c = this.canvas;
    // a touch that lands on a body drags it; any other touch scrolls the page (touch-action: pan-y)
    c.addEventListener("touchstart", (e) => {
      const t = e.touches[0];
      if (t && (this.onHandle(...this.pointer(t)) || this.grab(...this.pointer(t)) >= 0)) e.preventDefault();
    }, { passive: false });
    c.addEventListener("pointerdown", (e) => {
      const [x, y] = this.pointer(e);
      const h = this.onDrag ? this.onHandle(x, y) : null;
      const k = h ? -1 : this.grab(x, y);
      if (h) {
        this.pause();
        // the pointer's offset from the handle's centre stays put during the drag
        this.dragging = { rates: h.k, dx: h.x - x, dy: h.y - y };
      } else if (k >= 0 && this.onDrag) {
        this.pause();
        this.selected = k;
        this.dragging = { k };
        if (this.index !== 0) this.seek(0);
      } else if (this.dim === 3 && e.pointerType !== "touch") {
        this.dragging = { rotate: true, x, y, yaw: this.view.yaw, pitch: this.view.pitch };
      } else return;
      c.setPointerCapture(e.pointerId);
      e.preventDefault();
    });
    c.addEventListener("pointermove", (e) => {
      if (!this.dragging) {
        if (this.onDrag && e.pointerType === "mouse") {
          const [x, y] = this.pointer(e);
          c.style.cursor = this.onHandle(x, y) || this.grab(x, y) >= 0 ? "grab" : "";
        }
        return;
      }
      const [x, y] = this.pointer(e);
      if (this.dragging.rotate) {
        const d = this.dragging, dpr = window.devicePixelRatio || 1;
        this.view.yaw = d.yaw + (x - d.x) / (120 * dpr);
        this.view.pitch = Math.max(-1.4, Math.min(1.4, d.pitch + (y - d.y) / (120 * dpr)));
        this.fit();
        this.draw(this.index);
        return;
      }
      if (this.dragging.rates !== undefined) {
        const d = this.dragging, values = this.solveRates(d.rates, x + d.dx, y + d.dy);
        if (values) this.onDrag(values);
        return;
      }
      const values = this.solve(this.dragging.k, x, y);
      if (values) this.onDrag(values);
    });
    const end = () => { this.dragging = null; };
    c.addEventListener("pointerup", end);
    c.addEventListener("pointercancel", end);
  }

  bindKeys() {
    const c = this.canvas;
    c.addEventListener("focus", () => { this.focused = true; if (this.run) this.draw(this.index); });
    c.addEventListener("blur", () => { this.focused = false; if (this.run) this.draw(this.index); });
    c.addEventListener("keydown", (e) => {
      if (!this.run || !this.onDrag || !this.masses.length) return;
      if (e.key === "n" || e.key === "N") {
        this.selected = (this.selected + 1) % this.masses.length;
        this.draw(this.index);
        this.say(`${this.spec.points[this.masses[this.selected]].label} selected`);
        e.preventDefault();
        return;
      }
      const keys = { ArrowRight: [0, 1], ArrowUp: [1, 1], ArrowLeft: [0, -1], ArrowDown: [1, -1] };
      if (!(e.key in keys)) return;
      e.preventDefault();
      if (!e.shiftKey) {
        // the body moves the way the arrow points on screen: the initial coordinates that bring it
        // nearest a point a few pixels that way (along its constraint, if it has one)
        const names = (this.ownersOf[this.selected] || []).filter((q) => this.controls && this.controls(q));
        if (!names.length) return;
        const now = Object.fromEntries(names.map((q) => [q, this.controls(q).value]));
        const [px, py] = this.placed(this.selected, now);
        const dx = { ArrowRight: 1, ArrowLeft: -1 }[e.key] || 0, dy = { ArrowDown: 1, ArrowUp: -1 }[e.key] || 0;
        const PIXELS = 6;
        const values = this.solve(this.selected, px + PIXELS * dx, py + PIXELS * dy);
        const moved = values && names.filter((q) => Math.abs(values[q] - now[q]) > 1e-9 * Math.max(1, Math.abs(now[q])));
        if (!moved || !moved.length) { this.say("This body cannot move that way from here; try another arrow."); return; }
        this.pause();
        if (this.index !== 0) this.seek(0);
        this.onDrag(Object.fromEntries(moved.map((q) => [q, values[q]])));
        this.say(moved.map((q) => `${this.run.data.labels[q] || q} starts at ${Number(values[q].toPrecision(4))}`).join(", "));
        return;
      }
      // Shift: the body's initial rates, Right/Left the first, Up/Down the second (or the first if it has one)
      const names = this.rateNames(this.selected);
      if (!names.length) return;
      const [which, sign] = keys[e.key];
      const q = names[Math.min(which, names.length - 1)];
      const r = this.controls(q);
      const step = (r.max - r.min) / 200;
      const value = Math.min(r.max, Math.max(r.min, r.value + sign * step));
      this.pause();
      if (this.index !== 0) this.seek(0);
      this.onDrag({ [q]: value });
      this.say(`${this.run.data.labels[q] || q} starts at ${Number(value.toPrecision(4))}`);
    });
  }

  say(text) {
    if (this.dragStatus) this.dragStatus.textContent = text;
  }
}
