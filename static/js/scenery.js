/**
 * scenery.js — what a mechanism moves in, drawn on the canvas (animation.js): fixed solids (a ramp, a
 * wedge), curves (the ground, walls, wires, dashed guides), the scale bar, and a message band.
 */

/** Fixed bodies: polygons through points of the mechanism, at instant i; returns their corners in CSS pixels. */
export function drawSolids(player, ctx, i, dpr) {
  const drawn = [];
  for (const solid of player.spec.solids || []) {
    ctx.beginPath();
    const corners = solid.corners.map((p) => player.at(p, i));
    corners.forEach(([x, y], k) => { if (k) ctx.lineTo(x, y); else ctx.moveTo(x, y); });
    drawn.push(corners.map(([x, y]) => [Math.round(x / dpr), Math.round(y / dpr)]));
    ctx.closePath();
    ctx.fillStyle = "#e3e7ec"; ctx.fill();
    ctx.strokeStyle = "#6b747e"; ctx.lineWidth = 2 * dpr; ctx.stroke();
  }
  return drawn;
}

/** A curve's points on screen (device pixels) at the columns ``cols``. */
const screenPoints = (camera, cols) =>
  Array.from(cols[0], (_, k) => camera.screenOf([cols[0][k], cols[1][k], cols[2] ? cols[2][k] : 0]));

/** The part of the segment from (x0, y0) to (x1, y1) inside the canvas (W × H device pixels) widened by a margin m,
 * as the segment's parameters [t0, t1] (0 at its start, 1 at its end), or null if none of it is (Liang–Barsky).
 * A curve drawn far beyond the canvas (a rail reaching metres past a narrow view) then costs only what is seen. */
function visiblePart(x0, y0, x1, y1, W, H, m) {
  let t0 = 0, t1 = 1;
  const dx = x1 - x0, dy = y1 - y0;
  // each edge of the box: the segment is inside where p·t ≤ q
  for (const [p, q] of [[-dx, x0 + m], [dx, W + m - x0], [-dy, y0 + m], [dy, H + m - y0]]) {
    if (p === 0) { if (q < 0) return null; continue; }
    const t = q / p;
    if (p < 0) { if (t > t1) return null; if (t > t0) t0 = t; } else { if (t < t0) return null; if (t < t1) t1 = t; }
  }
  return [t0, t1];
}

const MARGIN = 20; // CSS pixels beyond the canvas's edge still covered: a hatch or a label reaching in from outside

/** The short slanted hatches of the ground, a ceiling or a wall on the side away from the motion: each [[x, y], [x, y]]
 * in device pixels ([] for a wire or a guide), only those on the canvas (W × H device pixels); each stays where it
 * is on the line whatever part of the line is seen. */
// how far a hatch reaches out from its ground, ceiling or wall, CSS pixels
export const HATCH = 7;

function hatches(style, pts, dpr, W, H) {
  const away = { ground: [-1, 1], ceiling: [1, -1], "wall-left": [-1, 1], "wall-right": [1, 1] }[style];
  if (!away || !pts.length) return [];
  const [x0, y0] = pts[0], [x1, y1] = pts[pts.length - 1], len = Math.hypot(x1 - x0, y1 - y0);
  if (!(len > 0)) return [];
  const gap = 10 * dpr, h = HATCH * dpr, count = Math.floor(len / gap), vertical = style.startsWith("wall");
  const seen = count > 0 ? visiblePart(x0, y0, x1, y1, W, H, MARGIN * dpr) : [0, 0];
  if (!seen) return [];
  const out = [];
  for (let k = Math.ceil(seen[0] * count); k <= Math.floor(seen[1] * count); k++) {
    const x = count ? x0 + ((x1 - x0) * k) / count : x0, y = count ? y0 + ((y1 - y0) * k) / count : y0;
    out.push([[x, y], [x + (vertical ? away[0] * h : away[0] * h * 0.7), y + (vertical ? away[1] * h * 0.7 : away[1] * h)]]);
  }
  return out;
}

/**
 * What the solid curves (the ground, a ceiling, walls, wires: not the dashed guides) cover on screen at instant i:
 * per curve, its label and its points about 2 device pixels apart with the ends of its hatches, so that a body's
 * label (bodies.js) keeps off them — the coupled oscillators' "left mass" sat on the floor's hatching.
 */
export function curveCover(player, i, dpr) {
  const out = [], W = player.canvas.width, H = player.canvas.height;
  for (const c of player.curveCols || []) {
    if (c.style === "guide") continue;
    const pts = screenPoints(player.camera, c.moving ? c.at(player.run.envAt(i)) : c.cols);
    const cover = [];
    pts.forEach(([x, y], k) => {
      if (!Number.isFinite(x) || !Number.isFinite(y)) return;
      const [px, py] = k && Number.isFinite(pts[k - 1][0]) && Number.isFinite(pts[k - 1][1]) ? pts[k - 1] : [x, y];
      // only the part on the canvas, sampled where it lies on the whole segment
      const seen = visiblePart(px, py, x, y, W, H, MARGIN * dpr);
      if (!seen) return;
      const n = Math.max(1, Math.ceil(Math.hypot(x - px, y - py) / (2 * dpr)));
      for (let s = Math.max(1, Math.ceil(seen[0] * n)); s <= Math.floor(seen[1] * n); s++) {
        cover.push([px + ((x - px) * s) / n, py + ((y - py) * s) / n]);
      }
    });
    for (const [, end] of hatches(c.style, pts, dpr, W, H)) cover.push(end);
    out.push({ label: c.label, points: cover });
  }
  return out;
}

export function drawCurve(camera, ctx, c, cols, dpr) {
  const style = c.style;
  ctx.strokeStyle = style === "guide" ? "#8c959f" : "#4b535c";
  ctx.lineWidth = (style === "guide" ? 1.5 : 2.5) * dpr;
  ctx.setLineDash(style === "guide" ? [4 * dpr, 4 * dpr] : []);
  const pts = screenPoints(camera, cols);
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
  const marks = hatches(style, pts, dpr, ctx.canvas.width, ctx.canvas.height);
  if (!marks.length) return;
  ctx.lineWidth = 1.2 * dpr; ctx.strokeStyle = "#8c959f";
  ctx.beginPath();
  for (const [[x, y], [u, v]] of marks) { ctx.moveTo(x, y); ctx.lineTo(u, v); }
  ctx.stroke();
}

/** The line a run that an event ended says on its last frame. */
export function eventLine(event) {
  return `t = ${Number(event.t.toFixed(3))} s: ${event.message}`;
}

// a message band's top line sits this far from the canvas's top (CSS pixels): message() and messageBottom()
export const MESSAGE_Y = 18;

/** A message's lines (wrapped to the canvas's width), their widest and the band's top, device pixels. */
function band(ctx, canvas, dpr, text, y) {
  ctx.font = `${13 * dpr}px system-ui, sans-serif`;
  const room = canvas.width - 24 * dpr, lines = [];
  for (const word of text.split(" ")) {
    const last = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
    if (lines.length && ctx.measureText(last).width <= room) lines[lines.length - 1] = last;
    else lines.push(word);
  }
  const h = 17 * dpr, w = Math.min(room, Math.max(...lines.map((l) => ctx.measureText(l).width)));
  const top = Math.max(4 * dpr, y - 14 * dpr - ((lines.length - 1) * h) / 2);
  return { lines, h, w, room, top, bottom: top + lines.length * h + 6 * dpr };
}

/** Text across the canvas at height y (wrapped to its width), on a white band; returns the band's bottom edge,
 * device pixels. */
export function message(ctx, canvas, dpr, text, y) {
  const { lines, h, w, room, top, bottom } = band(ctx, canvas, dpr, text, y);
  const x = (canvas.width - w) / 2;
  ctx.fillStyle = "rgba(255,255,255,0.9)";
  ctx.fillRect(x - 6 * dpr, top, w + 12 * dpr, bottom - top);
  ctx.fillStyle = "#1b1f24";
  lines.forEach((line, k) => ctx.fillText(line, x, top + 14 * dpr + k * h, room));
  return bottom;
}

/** Where a message's band ends below the canvas's top, device pixels: the room a view keeps free for it. */
export function messageBottom(ctx, canvas, dpr, text) {
  return band(ctx, canvas, dpr, text, MESSAGE_Y * dpr).bottom;
}

export function scaleBar(ctx, canvas, scale, dpr) {
  // a bar of a round length (1, 2 or 5 times a power of ten metres) in the lower left corner
  const target = 90 * dpr / scale;
  const p = Math.pow(10, Math.floor(Math.log10(target)));
  const len = [5, 2, 1].map((m) => m * p).find((v) => v <= target) || p;
  const x = 12 * dpr, y = canvas.height - 10 * dpr, w = len * scale;
  ctx.strokeStyle = "#4b535c"; ctx.lineWidth = 2 * dpr;
  ctx.beginPath(); ctx.moveTo(x, y - 5 * dpr); ctx.lineTo(x, y); ctx.lineTo(x + w, y); ctx.lineTo(x + w, y - 5 * dpr); ctx.stroke();
  ctx.fillStyle = "#4b535c"; ctx.font = `${12 * dpr}px system-ui, sans-serif`;
  ctx.fillText(`${Number(len.toPrecision(2))} m`, x + w + 6 * dpr, y);
}
