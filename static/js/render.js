/**
 * render.js — one frame of a mechanism on its canvas (animation.js): the scenery, trails, links and
 * wheels, fixed points, labels and bodies, forces, messages and the velocity handle, in that order
 * (later ones over earlier ones).
 *
 * For tests and tools it records what it drew: canvas.dataset.bodies (each body's label and position
 * in CSS pixels), canvas.dataset.drawn (counts, the slack string, forces, the run's event, the solid curves' boxes) and
 * canvas.dataset.handle (the velocity handle's position in CSS pixels, "" when none is shown), canvas.dataset.wheels
 * (each wheel's centre and radius in CSS pixels at the first instant).  The
 * handle carries a label in the page ("drag: initial velocity", arrows.js labelHandle) until it is first held.
 */
import { drawForces, drawHandle, labelHandle } from "./arrows.js";
import { drawBodies, drawFixed, drawLabels, drawTrails } from "./bodies.js";
import { drawLinks, drawWheels, wheelsAt } from "./links.js";
import { MESSAGE_Y, curveCover, drawCurve, drawSolids, eventLine, message, scaleBar } from "./scenery.js";

export function drawFrame(player, i) {
  const canvas = player.canvas, ctx = player.ctx, dpr = window.devicePixelRatio || 1, run = player.run, spec = player.spec;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.lineCap = "round"; ctx.lineJoin = "round";
  const drawn = { links: 0, wheels: 0, slack: false, forces: [], event: "", none: !!spec.none };
  // a system with no particle positions has no canvas shown (site.css): its caption says so, once
  // fixed bodies (a ramp, a wedge), then the curves: the ground, wires, dashed guides
  drawn.solids = drawSolids(player, ctx, i, dpr);
  for (const c of player.curveCols) drawCurve(player.camera, ctx, c, c.moving ? c.at(run.envAt(i)) : c.cols, dpr);
  if (!spec.none) scaleBar(ctx, canvas, player.camera.frame.scale, dpr);
  // fading trails first, so that strings, rods and springs are drawn over them
  drawTrails(player, ctx, i, dpr);
  const tension = spec.slack && run.forces[spec.slack] ? run.forces[spec.slack][i] : null;
  const slack = tension !== null && tension !== undefined && tension < 0;
  drawn.links = drawLinks(player, ctx, i, dpr, slack);
  drawn.slack = slack;
  drawn.wheels = drawWheels(player, ctx, i, dpr, slack);
  drawFixed(player, ctx, i, dpr);
  ctx.font = `${13 * dpr}px system-ui, sans-serif`;
  const placed = player.masses.map((p) => player.at(p, i));
  if (player.masses.length > 1) drawLabels(player, ctx, i, dpr, placed, i === 0 ? player.drag.handle() : null);
  const bodies = drawBodies(player, ctx, i, dpr, placed);
  if (player.showForces?.checked) drawn.forces = drawForces(player, ctx, i, dpr);
  if (slack) message(ctx, canvas, dpr, "The string is slack (its tension would be negative).", MESSAGE_Y * dpr);
  const event = run.stats && run.stats.event;
  if (event && i === run.n - 1) {
    drawn.event = event.name;
    // the band's bottom edge, CSS pixels: the view keeps the drawing below it (Player.messageRoom)
    drawn.band = Math.round(message(ctx, canvas, dpr, eventLine(event), MESSAGE_Y * dpr) / dpr);
  }
  // the solid curves' extents with their hatching, CSS pixels: [left, top, right, bottom] by label
  drawn.curves = curveCover(player, i, dpr).filter((c) => c.points.length).map(({ label, points }) => {
    // a loop, not Math.min(...points): a long cover would pass the call stack's limit on arguments
    const box = [Infinity, Infinity, -Infinity, -Infinity];
    for (const [x, y] of points) {
      box[0] = Math.min(box[0], x); box[1] = Math.min(box[1], y); box[2] = Math.max(box[2], x); box[3] = Math.max(box[3], y);
    }
    return { label, box: box.map((v) => Math.round(v / dpr)) };
  });
  canvas.dataset.bodies = JSON.stringify(bodies);
  canvas.dataset.drawn = JSON.stringify(drawn);
  const handle = i === 0 ? player.drag.handle() : null;
  if (handle) drawHandle(ctx, handle, dpr);
  labelHandle(player, handle, dpr);
  canvas.dataset.handle = handle ? JSON.stringify({ x: Math.round(handle.x / dpr), y: Math.round(handle.y / dpr) }) : "";
  if (i === 0) {
    canvas.dataset.wheels = JSON.stringify(wheelsAt(player, 0).map(({ x, y, r }) => [x / dpr, y / dpr, r / dpr]));
    // the rods, strings and springs at the first instant, CSS pixels: what the handle's words keep off (the tests)
    canvas.dataset.links = JSON.stringify(spec.links.map((l) => [player.at(l.from, 0), player.at(l.to, 0)].map(([x, y]) => [x / dpr, y / dpr])));
  }
}
