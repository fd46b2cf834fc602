/**
 * links.js — what joins a mechanism's points, drawn on the canvas (animation.js): rods, springs (a
 * zigzag that stretches with them), strings (slack where the tension the engine derives for them is
 * negative), bars (a rigid body's own length, as the physical pendulum's rod) and wheels (a pulley's rim and hub with the string wrapped over or under it).
 */

/** The links at instant i (those whose length the run confirms); the number drawn. */
export function drawLinks(player, ctx, i, dpr, slack) {
  let count = 0;
  player.spec.links.forEach((link, j) => {
    if (player.unsteady.has(j)) return;
    const [x0, y0] = player.at(link.from, i), [x1, y1] = player.at(link.to, i);
    if (link.style === "bar") { drawBar(ctx, x0, y0, x1, y1, dpr); count++; return; }
    const string = link.style === "string";
    ctx.strokeStyle = string && slack ? "#c26100" : "#1b1f24";
    ctx.lineWidth = (string ? 1.5 : link.style === "spring" ? 1.8 : 3) * dpr;
    ctx.setLineDash(string && slack ? [5 * dpr, 3 * dpr] : []);
    ctx.beginPath();
    if (link.style === "spring") zigzag(ctx, x0, y0, x1, y1, dpr);
    else if (string && slack) {
      // a slack string sags: a curve through a point below the straight line's middle
      const len = Math.hypot(x1 - x0, y1 - y0);
      ctx.moveTo(x0, y0);
      ctx.quadraticCurveTo((x0 + x1) / 2 + 0.15 * len, (y0 + y1) / 2 + 0.3 * len, x1, y1);
    } else { ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); }
    ctx.stroke();
    count++;
  });
  ctx.setLineDash([]);
  return count;
}

/** A bar from (x0, y0) to (x1, y1): a body with a width, as the set-up figure draws it (a light fill inside a dark
 * outline, rounded at its ends), not the thin line of a light rod that holds a bob. */
function drawBar(ctx, x0, y0, x1, y1, dpr) {
  ctx.setLineDash([]);
  ctx.lineCap = "round";
  for (const [colour, width] of [["#1b1f24", BAR_WIDTH + 3], ["#c9d8ea", BAR_WIDTH]]) {
    ctx.strokeStyle = colour; ctx.lineWidth = width * dpr;
    ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); ctx.stroke();
  }
}

const BAR_WIDTH = 9; // a bar's width inside its outline, CSS pixels

function zigzag(ctx, x0, y0, x1, y1, dpr) {
  const dx = x1 - x0, dy = y1 - y0, len = Math.hypot(dx, dy) || 1;
  const nx = -dy / len, ny = dx / len, turns = 10, amp = 6 * dpr;
  ctx.moveTo(x0, y0);
  for (let k = 1; k < 2 * turns; k++) {
    const f = 0.1 + (0.8 * k) / (2 * turns), s = k % 2 ? amp : -amp;
    ctx.lineTo(x0 + dx * f + nx * s, y0 + dy * f + ny * s);
  }
  ctx.lineTo(x1, y1);
}

/** Each wheel at instant i on the canvas (device pixels): its centre, its radius and where the string wraps; the
 * one home of their geometry (drawn here, kept clear by the handle's words and the bodies' labels). */
export function wheelsAt(player, i) {
  const out = [];
  for (const w of player.wheels || []) {
    const [x, y] = player.at(w.at, i);
    // a frame not laid out yet (a folded panel's canvas) may carry a negative scale: the wheel's size is its magnitude
    const r = Math.abs(w.r(player.run.envAt(i)) * player.camera.frame.scale);
    // the turning angle, counter-clockwise in the view (the canvas's y points down: drawn clockwise on it)
    const turn = w.turn ? w.turn(player.run.envAt(i)) : null;
    if (Number.isFinite(r) && r > 0) out.push({ x, y, r, wrap: w.wrap, turn: Number.isFinite(turn) ? turn : null });
  }
  return out;
}

/** The wheels at instant i: the rim, the spokes of one whose turning is given, the hub, and the string wrapped
 * over its top (a fixed pulley) or under its bottom (the movable one), none for a rolling wheel; the number drawn. */
export function drawWheels(player, ctx, i, dpr, slack) {
  let count = 0;
  for (const w of wheelsAt(player, i)) {
    const { x, y, r } = w;
    ctx.fillStyle = "#fff"; ctx.strokeStyle = "#6b747e"; ctx.lineWidth = 2 * dpr;
    ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    if (w.turn !== null) {
      // two spokes across the wheel at right angles, one of them dark, turned with the wheel: its rotation seen
      const c = Math.cos(w.turn), s = -Math.sin(w.turn);
      ctx.lineWidth = 1.5 * dpr;
      for (const [dx, dy, colour] of [[c, s, "#1b1f24"], [-s, c, "#9aa3ad"]]) {
        ctx.strokeStyle = colour; ctx.beginPath();
        ctx.moveTo(x - r * dx, y - r * dy); ctx.lineTo(x + r * dx, y + r * dy); ctx.stroke();
      }
    }
    ctx.fillStyle = "#6b747e"; ctx.beginPath(); ctx.arc(x, y, 3 * dpr, 0, 2 * Math.PI); ctx.fill();
    ctx.strokeStyle = slack ? "#c26100" : "#1b1f24"; ctx.lineWidth = 1.5 * dpr;
    ctx.beginPath();
    if (w.wrap === "top") ctx.arc(x, y, r, Math.PI, 2 * Math.PI);
    else if (w.wrap === "bottom") ctx.arc(x, y, r, 0, Math.PI);
    ctx.stroke();
    count++;
  }
  return count;
}
