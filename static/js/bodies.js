/**
 * bodies.js — a mechanism's bodies drawn on the canvas (animation.js): fading trails, fixed points,
 * the moving bodies (balls, or blocks on their slope) and their labels, placed where they hide least.
 */
import { HANDLE_LABEL, handleWordsBox, handleWordsWidths, linePoints } from "./arrows.js";
import { HANDLE_RADIUS } from "./drag.js";
import { wheelsAt } from "./links.js";
import { curveCover } from "./scenery.js";

export const MASS_COLORS = ["#0b5cad", "#b34700", "#2e7d32", "#6a1b9a"];

function mix(hex, amount) {
  // blend a colour toward white: amount 0 -> white, 1 -> the colour (a fading trail without alpha)
  const n = parseInt(hex.slice(1), 16);
  const c = [(n >> 16) & 255, (n >> 8) & 255, n & 255].map((v) => Math.round(255 + (v - 255) * amount));
  return `rgb(${c.join(",")})`;
}

/** Each body's trail up to instant i, fading with age. */
export function drawTrails(player, ctx, i, dpr) {
  player.masses.forEach((p, k) => {
    const color = MASS_COLORS[k % MASS_COLORS.length];
    for (let j = Math.max(0, i - player.trailLength + 1); j < i; j++) {
      const age = (i - j) / player.trailLength;
      const [x, y] = player.at(p, j);
      ctx.fillStyle = mix(color, 0.5 * (1 - age) + 0.06);
      ctx.beginPath(); ctx.arc(x, y, 2.5 * dpr, 0, 2 * Math.PI); ctx.fill();
    }
  });
}

/** The fixed points (pivots, anchors) at instant i. */
export function drawFixed(player, ctx, i, dpr) {
  ctx.fillStyle = "#1b1f24";
  for (const p of player.fixed) {
    const [x, y] = player.at(p, i);
    ctx.beginPath(); ctx.arc(x, y, 4 * dpr, 0, 2 * Math.PI); ctx.fill();
  }
}

/** Labels of two or more bodies (at their screen positions `placed`), before the bodies, so no label hides a
 * body; `grip` is the velocity handle drawn at the first instant (or null). */
export function drawLabels(player, ctx, i, dpr, placed, grip) {
  const canvas = player.canvas;
  // each label goes to the corner beside its body where it covers the fewest rods, strings, springs and
  // bodies and stays inside the canvas, with a white halo so that bodies that meet keep readable labels
  const segments = player.spec.links.map((link) => [player.at(link.from, i), player.at(link.to, i)]);
  // the outlines of the fixed solids (a wedge's slope) and of the blocks: a label with its white halo over a
  // slope hides the ground a block stands on, and the block looks perched on a corner
  const edges = [];
  const outline = (corners) => corners.forEach((c, k) => edges.push([c, corners[(k + 1) % corners.length]]));
  for (const solid of player.spec.solids || []) outline(solid.corners.map((p) => player.at(p, i)));
  // a wheel's rim as links.js draws it (a label over the movable pulley hid its lower half on a phone)
  for (const { x, y, r } of wheelsAt(player, i)) {
    outline(Array.from({ length: 24 }, (_, k) => [x + r * Math.cos((k * Math.PI) / 12), y + r * Math.sin((k * Math.PI) / 12)]));
  }
  player.masses.forEach((p, k) => {
    const base = blockBase(player, p, i, dpr, ...placed[k]);
    if (!base) return;
    const { a, b, nx, ny } = base, H = BLOCK_HEIGHT * dpr;
    outline([a, b, [b[0] + H * nx, b[1] + H * ny], [a[0] + H * nx, a[1] + H * ny]]);
  });
  // the ground, walls and wires with the floor's hatching: each weighs as much as a label already placed
  const covers = curveCover(player, i, dpr);
  const boxes = [];
  // the handle's words as wide as the page sets them, on one line and on two (arrows.js handleWordsWidths)
  const [words, words2] = grip ? handleWordsWidths(player, `${HANDLE_LABEL} (now 0)`).map((w) => w * dpr) : [0, 0];
  const gripWords = grip ? handleWordsBox(grip, words, canvas, placed, dpr, linePoints(player, dpr), words2) : null;
  const cost = (x0, y0, x1, y1) => {
    let c = 0;
    if (x0 < 2 * dpr || x1 > canvas.width - 2 * dpr || y0 < 2 * dpr || y1 > canvas.height - 2 * dpr) c += 100;
    const inside = (x, y) => x >= x0 && x <= x1 && y >= y0 && y <= y1;
    for (const [[ax, ay], [bx, by]] of segments) {
      for (let f = 0; f <= 1; f += 0.125) if (inside(ax + (bx - ax) * f, ay + (by - ay) * f)) { c += 1; break; }
    }
    // an outline is looked at every 2 px, however long it is (a slope may be the canvas's width)
    for (const [[ax, ay], [bx, by]] of edges) {
      const n = Math.max(1, Math.ceil(Math.hypot(bx - ax, by - ay) / (2 * dpr)));
      for (let s = 0; s <= n; s++) if (inside(ax + ((bx - ax) * s) / n, ay + ((by - ay) * s) / n)) { c += 1; break; }
    }
    for (const cover of covers) if (cover.points.some(([x, y]) => inside(x, y))) c += 5;
    for (const [bx, by] of placed) if (inside(bx, by) || inside(bx - 10 * dpr, by) || inside(bx + 10 * dpr, by)) c += 2;
    // labels already placed, and the velocity handle (drawn at the first instant), weigh most
    for (const [a0, b0, a1, b1] of boxes) if (x0 < a1 && x1 > a0 && y0 < b1 && y1 > b0) c += 5;
    if (grip) {
      const r = (HANDLE_RADIUS + 2) * dpr;
      if (grip.x + r > x0 && grip.x - r < x1 && grip.y + r > y0 && grip.y - r < y1) c += 4;
      // the handle's own words ("drag: initial velocity") where arrows.js places them
      if (gripWords[0] < x1 && gripWords[2] > x0 && gripWords[1] < y1 && gripWords[3] > y0) c += 5;
    }
    return c;
  };
  // a label reads as naming what it is nearest: one nearer another body, or the handle, than its own misleads
  const misleading = (k, x0, y0, x1, y1) => {
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, d = ([u, v]) => Math.hypot(u - cx, v - cy);
    const own = d(placed[k]);
    const others = placed.filter((_, j) => j !== k).concat(grip ? [[grip.x, grip.y]] : []);
    return others.some((o) => d(o) < own) ? 6 : 0;
  };
  const drawn = [];
  player.masses.forEach((p, k) => {
    const [x, y] = placed[k], label = player.spec.points[p].label, w = ctx.measureText(label).width, h = 13 * dpr;
    let best = null;
    // the four corners beside the body, then straight above and below it (for a body between two others)
    for (const [sx, sy] of [[1, -1], [-1, -1], [1, 1], [-1, 1], [0, -1], [0, 1]]) {
      const lx = x + sx * 14 * dpr, ly = y + (sy < 0 ? (sx ? -12 : -14) : (sx ? 22 : 26)) * dpr;
      const x0 = sx > 0 ? lx : sx < 0 ? lx - w : lx - w / 2, box = [x0, ly - h, x0 + w, ly + 3 * dpr];
      const c = cost(...box) + misleading(k, ...box);
      if (!best || c < best.c) best = { c, lx, ly, align: sx > 0 ? "left" : sx < 0 ? "right" : "center", box };
    }
    boxes.push(best.box);
    drawn.push({ label, box: best.box.map((v) => Math.round(v / dpr)) });
    ctx.textAlign = best.align;
    ctx.strokeStyle = "#fff"; ctx.lineWidth = 4 * dpr;
    ctx.strokeText(label, best.lx, best.ly);
    ctx.fillStyle = "#1b1f24";
    ctx.fillText(label, best.lx, best.ly);
  });
  ctx.textAlign = "left";
  // for tests and tools: each label's box [left, top, right, bottom] in CSS pixels
  canvas.dataset.labels = JSON.stringify(drawn);
}

const BLOCK_HALF = 15; // half a block's length along its slope, CSS pixels
const BLOCK_HEIGHT = 18; // a block's height out of its slope, CSS pixels

/**
 * A block's base on screen at instant i (null for a ball): its ends a and b along the slope, its middle, and
 * the unit normal (nx, ny) out of the slope.  The particle (screen point x, y) is the middle of the base,
 * or with base "ahead" its first end, the base running along the slope's direction from it.
 */
export function blockBase(player, p, i, dpr, x, y) {
  const tilt = player.tilts[p];
  if (!tilt) return null;
  const angle = tilt(player.run.envAt(i)), W = BLOCK_HALF * dpr;
  const dx = Math.cos(angle), dy = -Math.sin(angle), nx = -Math.sin(angle), ny = -Math.cos(angle); // along, and up from, the slope on screen
  const ahead = player.spec.points[p].base === "ahead";
  const a = ahead ? [x, y] : [x - W * dx, y - W * dy], b = ahead ? [x + 2 * W * dx, y + 2 * W * dy] : [x + W * dx, y + W * dy];
  return { a, b, middle: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], nx, ny };
}

/** A body's centre of mass at (x, y): the textbook's mark, a small circle with two opposite quarters filled, in the
 * body's colour (ringed when selected), small enough that the bar it sits on stays the body seen. */
function centreMark(ctx, x, y, dpr, colour, selected) {
  const r = CENTRE_RADIUS * dpr;
  ctx.fillStyle = "#fff";
  ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.fill();
  ctx.fillStyle = colour;
  for (const start of [0, Math.PI]) {
    ctx.beginPath(); ctx.moveTo(x, y); ctx.arc(x, y, r, start, start + Math.PI / 2); ctx.closePath(); ctx.fill();
  }
  ctx.lineWidth = (selected ? 3 : 1.5) * dpr;
  ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.stroke();
}

const CENTRE_RADIUS = 6; // a centre-of-mass mark's radius, CSS pixels

/** The bodies at their screen positions `placed` (the selected one ringed while the canvas has focus);
 * returns each body's label and position in CSS pixels. */
export function drawBodies(player, ctx, i, dpr, placed) {
  const bodies = [];
  player.masses.forEach((p, k) => {
    const [x, y] = placed[k];
    const selected = k === player.selected && player.focused;
    ctx.fillStyle = MASS_COLORS[k % MASS_COLORS.length];
    ctx.strokeStyle = selected ? "#ffbf47" : "#1b1f24";
    ctx.lineWidth = (selected ? 4 : 1.5) * dpr;
    const base = blockBase(player, p, i, dpr, x, y);
    if (base) {
      // a block: a rectangle whose base lies on its slope (from a to b), standing up from it by H
      const { a, b, nx, ny } = base, H = BLOCK_HEIGHT * dpr;
      ctx.beginPath();
      ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]);
      ctx.lineTo(b[0] + H * nx, b[1] + H * ny); ctx.lineTo(a[0] + H * nx, a[1] + H * ny);
      ctx.closePath(); ctx.fill(); ctx.stroke();
    } else if (player.spec.points[p].centre) {
      centreMark(ctx, x, y, dpr, ctx.fillStyle, selected);
    } else {
      // a body that is itself a turning wheel (a rolling cylinder): a small dot at its centre, so that its rim and
      // its spokes stay in sight; any other body a ball
      const hub = player.wheels.some((w) => w.at === p && w.turn);
      ctx.beginPath(); ctx.arc(x, y, (hub ? 5 : 10) * dpr, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    }
    const body = { label: player.spec.points[p].label, x: Math.round(x / dpr), y: Math.round(y / dpr) };
    // a centre of mass drawn as its mark on the body, not as a ball (the tests read which)
    if (player.spec.points[p].centre) body.mark = "centre of mass";
    // a block's base, in CSS pixels (the geometry a test checks against its slope)
    if (base) body.base = [base.a, base.b].map(([u, v]) => [Math.round(u / dpr), Math.round(v / dpr)]);
    bodies.push(body);
  });
  return bodies;
}
