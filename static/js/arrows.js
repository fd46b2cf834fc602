/**
 * arrows.js — vectors drawn over a mechanism (animation.js): the forces of constraint at an instant,
 * on one scale for the whole run with a legend, and the velocity handle of the selected body with its label.
 */
import { blockBase } from "./bodies.js";
import { HANDLE_RADIUS } from "./drag.js";
import { wheelsAt } from "./links.js";

const FORCE_COLORS = ["#7b1fa2", "#00796b", "#c62828"];

/** Per force of constraint: its values along the run and the largest size (for a common scale). */
export function forceSeries(spec, run, compile) {
  const out = [];
  let largest = 0;
  for (const f of spec.forces || []) {
    const values = run.forces[f.name];
    if (!values || !values.length) continue;
    const ratio = f.ratio === undefined ? null : compile(f.ratio);
    // the largest force drawn sets the scale: the reported size times this body's share of it
    values.forEach((v, k) => { if (Number.isFinite(v)) largest = Math.max(largest, Math.abs(v * (ratio ? ratio(run.envAt(k)) : 1))); });
    out.push({ ...f, values, dir: f.direction.map(compile), ratio });
  }
  return { list: out, largest };
}

/** Arrows of the forces of constraint at instant i, on one scale for the whole run, with a legend. */
export function drawForces(player, ctx, i, dpr) {
  const { list, largest } = player.forces;
  const canvas = player.canvas, camera = player.camera;
  if (!list.length || !(largest > 0)) return [];
  const env = player.run.envAt(i), longest = 0.3 * Math.min(canvas.width, canvas.height);
  const perNewton = longest / largest; // screen pixels per newton
  const out = [];
  // one colour per force, however many bodies it acts on
  const names = [...new Set(list.map((f) => f.name))];
  list.forEach((f) => {
    const j = names.indexOf(f.name);
    // the force on this body: the reported signed size times |grad_i g| / |grad_on g|
    const value = f.values[i] * (f.ratio ? f.ratio(env) : 1);
    if (!Number.isFinite(value)) return;
    // from its point of application where the spec names one (the middle of the wedge's base), else its body
    const p = Number.isInteger(f.at) ? f.at : player.masses[f.on], a = player.xyz[p];
    const r = a.map((col) => col[i]), d = f.dir.map((g) => g(env));
    // the arrow is the vector F (grad g / |grad g|) drawn at perNewton screen pixels per newton
    // (a negative F points against grad g); in 3-D it is projected like everything else
    const len = (value * perNewton) / camera.frame.scale;
    let [x, y] = camera.screenOf([r[0], r[1], r[2] ?? 0]);
    // on a block, from the middle of its base (where the slope pushes), wherever the particle sits on it
    const base = Number.isInteger(f.at) ? null : blockBase(player, p, i, dpr, x, y);
    const shift = base ? [base.middle[0] - x, base.middle[1] - y] : [0, 0];
    [x, y] = [x + shift[0], y + shift[1]];
    let [tx, ty] = camera.screenOf([r[0] + len * d[0], r[1] + len * d[1], (r[2] ?? 0) + len * (d[2] ?? 0)]);
    [tx, ty] = [tx + shift[0], ty + shift[1]];
    if (!Number.isFinite(tx + ty)) return;
    const color = FORCE_COLORS[j % FORCE_COLORS.length];
    arrow(ctx, x, y, tx, ty, color, dpr);
    out.push({ name: f.name, on: f.on, value, x: Math.round(x / dpr), y: Math.round(y / dpr), tx: Math.round(tx / dpr), ty: Math.round(ty / dpr) });
  });
  // the legend, top right on a white card: a round force (at most the largest) and its arrow,
  // then each force's colour and name
  const pow = Math.pow(10, Math.floor(Math.log10(largest)));
  const unit = [5, 2, 1].map((m) => m * pow).find((v) => v <= largest) || pow;
  ctx.font = `${12 * dpr}px system-ui, sans-serif`;
  const rows = names.map((name) => `→ ${name}`);
  const width = Math.max(unit * perNewton + 60 * dpr, ...rows.map((t) => ctx.measureText(t).width)) + 12 * dpr;
  const W = canvas.width, x1 = W - 12 * dpr, top = 30 * dpr, rowH = 16 * dpr;
  ctx.fillStyle = "rgba(255,255,255,0.9)";
  ctx.fillRect(x1 - width, top - 12 * dpr, width + 6 * dpr, rowH * (rows.length + 1) + 6 * dpr);
  ctx.textAlign = "right";
  rows.forEach((text, j) => {
    ctx.fillStyle = FORCE_COLORS[j % FORCE_COLORS.length];
    ctx.fillText(text, x1, top + j * rowH);
  });
  const y = top + rows.length * rowH - 4 * dpr, x0 = x1 - unit * perNewton;
  arrow(ctx, x0, y, x1, y, "#4b535c", dpr);
  ctx.fillStyle = "#4b535c"; ctx.fillText(`${Number(unit.toPrecision(2))} N`, x0 - 6 * dpr, y + 4 * dpr);
  ctx.textAlign = "left";
  return out;
}

function arrow(ctx, x0, y0, x1, y1, color, dpr) {
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

/** The velocity handle h (drag.js handle()): an arrow from the body ending in a round grip. */
export function drawHandle(ctx, h, dpr) {
  const color = "#c2185b", r0 = 11 * dpr, x0 = h.bx + h.ux * r0, y0 = h.by + h.uy * r0;
  ctx.strokeStyle = color; ctx.fillStyle = color; ctx.lineWidth = 2.5 * dpr;
  ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(h.x, h.y); ctx.stroke();
  // an arrowhead just short of the handle, pointing along the velocity; at rest an open one, the stub of an
  // arrow of zero length pointing the way the first coordinate moves: it shows the handle is an arrow's end
  const back = (HANDLE_RADIUS + 2) * dpr, tx = h.x - h.ux * back, ty = h.y - h.uy * back, s = 7 * dpr;
  ctx.beginPath();
  ctx.moveTo(tx - h.ux * s - h.uy * s * 0.6, ty - h.uy * s + h.ux * s * 0.6);
  ctx.lineTo(tx, ty);
  ctx.lineTo(tx - h.ux * s + h.uy * s * 0.6, ty - h.uy * s - h.ux * s * 0.6);
  if (h.len > 2 * dpr) { ctx.closePath(); ctx.fill(); } else ctx.stroke();
  ctx.fillStyle = "#fff";
  ctx.beginPath(); ctx.arc(h.x, h.y, HANDLE_RADIUS * dpr, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
}

export const HANDLE_LABEL = "drag: initial velocity";

/** Points along every rod, string and spring at the first instant, about 8 CSS pixels apart, the fixed points
 * (pivots, anchors), each wheel's hub and rim (a pulley: the words lay across the movable one on a
 * phone), the fixed solids' outlines and insides (a wedge: the words sat over it on a phone) and the
 * curves (the ground and its hatching, wires, guides): what the handle's words should not cover where there is
 * room (handleWordsBox). */
export function linePoints(player, dpr) {
  const out = (player.fixed || []).map((p) => player.at(p, 0));
  const along = (ax, ay, bx, by) => {
    const n = Math.max(1, Math.ceil(Math.hypot(bx - ax, by - ay) / (8 * dpr)));
    for (let k = 0; k <= n; k++) out.push([ax + ((bx - ax) * k) / n, ay + ((by - ay) * k) / n]);
  };
  for (const link of player.spec.links || []) along(...player.at(link.from, 0), ...player.at(link.to, 0));
  for (const { x, y, r } of wheelsAt(player, 0)) {
    out.push([x, y]);
    const n = Math.max(8, Math.ceil((2 * Math.PI * r) / (8 * dpr)));
    for (let k = 0; k < n; k++) out.push([x + r * Math.cos((2 * Math.PI * k) / n), y + r * Math.sin((2 * Math.PI * k) / n)]);
  }
  for (const solid of player.spec.solids || []) {
    const corners = solid.corners.map((p) => player.at(p, 0));
    corners.forEach(([ax, ay], k) => along(ax, ay, ...corners[(k + 1) % corners.length]));
    // its inside, every 8 px: a point is inside when a ray to the right crosses the outline an odd number of times
    const xs = corners.map(([x]) => x), ys = corners.map(([, y]) => y), step = 8 * dpr;
    for (let y = Math.min(...ys); y <= Math.max(...ys); y += step) {
      for (let x = Math.min(...xs); x <= Math.max(...xs); x += step) {
        let inside = false;
        corners.forEach(([ax, ay], k) => {
          const [bx, by] = corners[(k + 1) % corners.length];
          if ((ay > y) !== (by > y) && x < ax + ((y - ay) * (bx - ax)) / (by - ay)) inside = !inside;
        });
        if (inside) out.push([x, y]);
      }
    }
  }
  for (const c of player.curveCols || []) {
    const cols = c.moving ? c.at(player.run.envAt(0)) : c.cols;
    // a ground's hatching hangs up to 7 px below it (scenery.js): its points count 7 px down as well
    const hatched = ["ground", "ceiling", "wall-left", "wall-right"].includes(c.style);
    for (let k = 0; k < cols[0].length; k++) {
      const [x, y] = player.camera.screenOf([cols[0][k], cols[1][k], cols[2] ? cols[2][k] : 0]);
      if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
      out.push([x, y]);
      if (hatched) out.push([x, y + (c.style === "ceiling" ? -7 : 7) * dpr]);
    }
  }
  return out;
}

// the height of the handle's words, CSS pixels (their font and padding: .handle-label in site.css), on one line
// and on two ("drag: initial" over "velocity (now 0)", where one line finds no clear place: the pulley's strings)
export const HANDLE_WORDS_HIGH = 22;
export const HANDLE_WORDS_TWO_LINES = 40;
// the words on two lines: the break after "initial", so that the wider line is the shorter half
export const HANDLE_LABEL_LINES = ["drag: initial", "velocity"];
// how far from a body (CSS pixels) its label may reach: bodies.js sets it 26 px below the centre, 13 px high
export const LABEL_ROOM = 30;
// how far from the handle (CSS pixels, to the nearest point of the words' box) a clear place is sought around it
export const HANDLE_WORDS_REACH = 40;

/**
 * Where the handle's words go on the canvas (device pixels: their box [x0, y0, x1, y1], and ``lines`` on it, 1 or
 * 2), ``wide`` device pixels wide on one line and ``wide2`` on two (0: never on two). The first of right of the
 * handle and above it, left, centred; the same below it; then one to three lines higher or lower; then any place
 * whose nearest point is within HANDLE_WORDS_REACH of the handle, nearest first — that stays inside the canvas and
 * covers no body (``placed``, the bodies' centres) — a body at the top of the view, the double pendulum's lower bob
 * at 2 rad, was hidden under them — nor the handle and its arrow, and, where a place allows it, nothing
 * drawn (``lines``, from linePoints: the physical pendulum's rod ran under them on a phone, the pulley's strings and
 * the wedge on a phone). Where one line finds no such place, two lines are tried; where neither does, the
 * place on one line that covers the fewest points drawn. One home: the words (labelHandle) and the bodies' labels
 * that keep clear of them (bodies.js) both place them here.
 */
/** The points in square cells ``cell`` device pixels wide, so that a box asks only the cells it overlaps:
 * ``count(x0, y0, x1, y1)`` the points inside the closed box (exactly: each point of those cells is compared). The
 * places tried for the handle's words are thousands and the points drawn as many (a wedge's inside, every 8 px):
 * each place asks only the few cells it covers. */
export function pointGrid(points, cell) {
  const cells = new Map();
  const key = (i, j) => i * 65536 + j;
  for (const p of points) {
    const k = key(Math.floor(p[0] / cell), Math.floor(p[1] / cell));
    const list = cells.get(k);
    if (list) list.push(p); else cells.set(k, [p]);
  }
  const count = (x0, y0, x1, y1, stop = Infinity) => {
    let n = 0;
    for (let i = Math.floor(x0 / cell), i1 = Math.floor(x1 / cell); i <= i1; i++) {
      for (let j = Math.floor(y0 / cell), j1 = Math.floor(y1 / cell); j <= j1; j++) {
        for (const [x, y] of cells.get(key(i, j)) || []) {
          if (x >= x0 && x <= x1 && y >= y0 && y <= y1 && ++n >= stop) return n;
        }
      }
    }
    return n;
  };
  return { count, any: (x0, y0, x1, y1) => count(x0, y0, x1, y1, 1) > 0 };
}

export function handleWordsBox(grip, wide, canvas, placed, dpr, lines = [], wide2 = 0) {
  const grid = pointGrid(lines, 32 * dpr);
  const gap = (HANDLE_RADIUS + 6) * dpr, clear = 12 * dpr;
  const own = placed.reduce((k, [x, y], j) => (k < 0 || Math.hypot(x - grip.x, y - grip.y) < Math.hypot(placed[k][0] - grip.x, placed[k][1] - grip.y) ? j : k), -1);
  const others = placed.filter((_, j) => j !== own);
  // the handle's arrow, from its body to the handle, and the handle itself: never under the words
  const arrow = [];
  if (own >= 0) {
    const [bx, by] = placed[own], n = Math.max(1, Math.ceil(Math.hypot(grip.x - bx, grip.y - by) / (4 * dpr)));
    for (let k = 0; k <= n; k++) arrow.push([bx + ((grip.x - bx) * k) / n, by + ((grip.y - by) * k) / n]);
  }
  const place = (wide, high, ownRoom, reachPx = HANDLE_WORDS_REACH) => {
    const right = grip.x + gap, left = grip.x - gap - wide;
    const above = grip.y - high - 2 * dpr, below = grip.y + (HANDLE_RADIUS + 4) * dpr;
    const inside = (x0, y0) => x0 >= 0 && x0 + wide <= canvas.width && y0 >= 0 && y0 + high <= canvas.height;
    const away = (points, margin) => (x0, y0) => points.every(([bx, by]) =>
      bx < x0 - margin || bx > x0 + wide + margin || by < y0 - margin || by > y0 + high + margin);
    // the handle's own body (the nearest) kept 12 px clear; every other body with room for its label as well, which
    // bodies.js sets beside it, up to 26 px above or below (the pulleys' middle mass lost its label under the words)
    const free = (x0, y0) => away(placed.slice(own, own + 1), ownRoom)(x0, y0) && away(others, LABEL_ROOM * dpr)(x0, y0)
      && away(arrow, 4 * dpr)(x0, y0) && away([[grip.x, grip.y]], (HANDLE_RADIUS + 3) * dpr)(x0, y0);
    // no point drawn inside the box widened by 2 px (as away(lines, 2 px), asked of the grid)
    const uncrossed = (x0, y0) => !grid.any(x0 - 2 * dpr, y0 - 2 * dpr, x0 + wide + 2 * dpr, y0 + high + 2 * dpr);
    // centred on the handle, moved inside the canvas (on a phone neither side may have room)
    const centred = Math.min(Math.max(0, grip.x - wide / 2), canvas.width - wide);
    // beside the handle first, then one, two, three lines higher or lower: past the bodies hung side by side at the
    // handle's height and their labels (the pulleys' three masses) there may be room where one line off had none
    const higher = above - high, lower = below + high;
    const spots = [[right, above], [left, above], [centred, above], [right, below], [left, below], [centred, below],
      [right, higher], [centred, higher], [left, higher], [right, lower], [left, lower], [centred, lower]];
    const room = spots.filter(([x, y]) => inside(x, y) && free(x, y));
    const found = room.find(([x, y]) => uncrossed(x, y));
    if (found) return { spot: found, room };
    // then every place around the handle, 4 px apart and flush with the canvas's edges, nearest first
    const reach = reachPx * dpr, step = (reachPx > HANDLE_WORDS_REACH ? 6 : 4) * dpr, near = [];
    const range = (lo, hi, edge) => {
      const out = [0, edge];
      for (let v = lo; v <= hi; v += step) out.push(v);
      return out.filter((v) => v >= lo && v <= hi);
    };
    for (const y of range(grip.y - high - reach, grip.y + reach, canvas.height - high)) {
      for (const x of range(grip.x - wide - reach, grip.x + reach, canvas.width - wide)) {
        const d = Math.hypot(Math.max(x - grip.x, 0, grip.x - x - wide), Math.max(y - grip.y, 0, grip.y - y - high));
        if (d <= reach && inside(x, y)) near.push([d, x, y]);
      }
    }
    near.sort((a, b) => a[0] - b[0]);
    const nearby = near.find(([, x, y]) => free(x, y) && uncrossed(x, y));
    return { spot: nearby ? [nearby[1], nearby[2]] : null, room };
  };
  // with two bodies or more, each has a label (bodies.js) beside it, the handle's own body's too: its room is kept
  // first (the pulley's "left mass" lay under the words), then only 12 px about that body
  const high = HANDLE_WORDS_HIGH * dpr, high2 = HANDLE_WORDS_TWO_LINES * dpr;
  const rooms = placed.length > 1 ? [LABEL_ROOM * dpr, clear] : [clear];
  let one = null;
  // nearer the handle first; then twice as far (a handle inside a wedge on a wide screen: its slope is further off)
  for (const reach of [HANDLE_WORDS_REACH, 2 * HANDLE_WORDS_REACH]) {
    for (const ownRoom of rooms) {
      const first = place(wide, high, ownRoom, reach);
      one ??= ownRoom === clear ? first : null;
      if (first.spot) return Object.assign([...first.spot, first.spot[0] + wide, first.spot[1] + high], { lines: 1 });
      const two = wide2 > 0 ? place(wide2, high2, ownRoom, reach) : { spot: null };
      if (two.spot) return Object.assign([...two.spot, two.spot[0] + wide2, two.spot[1] + high2], { lines: 2 });
    }
  }
  // of the places clear of the bodies, the one that covers the fewest points of lines and wheels (the first such in
  // the order above), never simply the first
  const covered = ([x, y]) => grid.count(x - 2 * dpr, y - 2 * dpr, x + wide + 2 * dpr, y + high + 2 * dpr);
  const right = grip.x + gap, left = grip.x - gap - wide, above = grip.y - high - 2 * dpr;
  const [x0, y0] = one.room.reduce((best, spot) => (best === null || covered(spot) < covered(best) ? spot : best), null)
    // none clear: above, to the right unless that leaves the canvas (as before any body was looked at)
    ?? [right + wide <= canvas.width ? right : Math.max(0, left), Math.max(0, above)];
  return Object.assign([x0, y0, x0 + wide, y0 + high], { lines: 1 });
}

/** The handle's words' widths in CSS pixels, [on one line, on two lines], as the page sets them (.handle-label,
 *  measured once per text on the element itself, created if need be): one measure for the words (labelHandle) and
 *  for the bodies' labels that keep clear of them (bodies.js). */
export function handleWordsWidths(player, text) {
  player.handleWordsWidths ??= new Map();
  const known = player.handleWordsWidths.get(text);
  if (known) return known;
  const wrap = player.canvas.parentElement;
  let label = wrap?.querySelector(".handle-label");
  if (!label) {
    if (!wrap) return [0, 0];
    label = Object.assign(document.createElement("span"), { className: "handle-label", hidden: true });
    wrap.append(label);
  }
  const { hidden, textContent } = label, className = label.className, width = label.style.width;
  label.hidden = false; label.className = "handle-label"; label.style.width = "";
  const measure = (words) => { label.textContent = words; return label.offsetWidth; };
  // on two lines (their own narrower padding) as wide as the wider of "drag: initial" and "velocity (now 0)", and
  // 1 px for rounding
  const first = HANDLE_LABEL_LINES[0], one = measure(text);
  label.className = "handle-label two-lines"; label.style.whiteSpace = "nowrap";
  const widths = [one, Math.max(measure(first), measure(text.slice(first.length + 1))) + 1];
  Object.assign(label, { hidden, textContent, className }); label.style.width = width; label.style.whiteSpace = "";
  if (widths[0] > 0) player.handleWordsWidths.set(text, widths);
  return widths;
}

/**
 * The words beside the velocity handle h (or none, h null) until the reader first holds it: a span over the
 * canvas (.handle-label in its .mechanism-wrap), beyond the handle along the arrow, kept inside the canvas.
 */
export function labelHandle(player, h, dpr) {
  const wrap = player.canvas.parentElement;
  if (!wrap) return;
  let label = wrap.querySelector(".handle-label");
  if (!h || player.handleHeld) { if (label) label.hidden = true; return; }
  if (!label) {
    label = Object.assign(document.createElement("span"), { className: "handle-label", textContent: HANDLE_LABEL });
    wrap.append(label);
  }
  label.hidden = false;
  const text = h.len > 2 * dpr ? HANDLE_LABEL : `${HANDLE_LABEL} (now 0)`;
  const [wide, wide2] = handleWordsWidths(player, text).map((w) => w * dpr);
  label.textContent = text;
  label.classList.remove("two-lines");
  label.style.width = "";
  // clear of every body and of what is drawn at the first instant (handleWordsBox), in CSS pixels within the wrap:
  // the canvas's own offset (its border) plus the box's place on it
  const placed = (player.masses || []).map((p) => player.at(p, 0));
  const box = handleWordsBox(h, wide, player.canvas, placed, dpr, linePoints(player, dpr), wide2);
  const [x0, y0] = box;
  if (box.lines === 2) {
    label.classList.add("two-lines");
    label.style.width = `${wide2 / dpr}px`;
  }
  label.style.left = `${Math.round(player.canvas.offsetLeft + player.canvas.clientLeft + x0 / dpr)}px`;
  label.style.top = `${Math.round(player.canvas.offsetTop + player.canvas.clientTop + y0 / dpr)}px`;
}
