/**
 * action-verdict.js — what the action panel says after Relax, in sentences, from the server's answer.
 *
 *   verdict(answer, { q, label, unit, rateUnit, T, steps }) -> { found, text, method, advice: [codes] }
 *
 * ``text`` leads with what a student needs (how close the relaxed path is to the true motion); a found path's
 * ``method`` is the account of how that was computed (Newton's steps, the grid, shooting), which the panel puts
 * behind a disclosure.
 *
 * The server (POST .../action/relax) decides whether the relaxed path is the true one: Newton's method
 * solved the discrete Euler–Lagrange equations on both grids, the grid resolves the path, and the
 * shooting solution between the same ends runs along it.  `reasons` says which of these failed and
 * `advice` what to try; this module only words them.  A bound below round-off reads
 * "10⁻¹²", never "about 0".
 */
import { fmt, magnitude } from "./summaries.js";

const TINY = 1e-12;
const RATE_FLOOR = 1e-9; // shooting meets the end to 1e-12: a starting rate below this is zero

/** "7.9 × 10⁻⁹ rad" or, for a bound below round-off, "10⁻¹² rad" (a bound is never printed as 0). */
function bound(x, unit) {
  return `${fmt(Math.max(x, TINY))}${unit ? ` ${unit}` : ""}`.replace(/^1 × /, "");
}

const ADVICE = {
  "closer-trial": "drag the points of the trial path nearer the true path",
  "shorter-t": "choose a shorter τ",
  "from-shooting": "start from the shooting solution (the button “Start from the shooting solution”)",
};

/** When the shooting solution is not the grey path from the run's start (same ends, another starting rate): both are
 *  true motions, and the reader is told why there can be several (else three different "true" paths go unexplained). */
function several(f, { q, label, rateUnit, T, startRate, sameEnds }) {
  const shot = f.shooting?.velocity?.[`${q}_dot`];
  if (!sameEnds || startRate === undefined || shot === undefined) return "";
  if (Math.abs(shot - startRate) <= 1e-6 * Math.max(1, Math.abs(startRate))) return "";
  const u = rateUnit ? ` ${rateUnit}` : "";
  const start = Math.abs(startRate) < RATE_FLOOR ? "0" : fmt(startRate);
  return ` It is not the grey path from the start, which leaves with ${label}̇(0) = ${start}${u}, and both are true motions: `
    + `more than one motion can join the same two positions in the same time τ = ${fmt(T)} s, each leaving with its `
    + `own starting rate, and each makes S stationary. Which one Newton's method settles on depends on the trial path it starts from.`;
}

export function verdict(f, { q, label, unit, rateUnit, T, steps: gridSteps, startRate, sameEnds }) {
  const newton = f.iterations.length - 1;
  // the shooting solution's starting rate of the shown coordinate; below the shooting's accuracy it is 0
  const v = f.shooting ? f.shooting.velocity[`${q}_dot`] : null;
  const rate = Math.abs(v) < RATE_FLOOR ? "0" : fmt(v);
  const start = f.shooting ? `the motion that starts with ${label}̇(0) = ${rate}${rateUnit ? ` ${rateUnit}` : ""}` : "";
  if (f.found) {
    const what = f.kind === "minimum"
      ? "It is a minimum of the discrete action: every small change of the path raises S."
      : `It is a saddle of the discrete action, not a minimum: ${f.negative_directions} direction${f.negative_directions > 1 ? "s" : ""} of change lower${f.negative_directions > 1 ? "" : "s"} S, because τ = ${fmt(T)} s is past the kinetic focus.`;
    // what a second-year needs first: how close the relaxed path is to the true motion, the shooting
    // solution's distance from it (the panel's own number), and what kind of stationary point it is
    const text = `The relaxed path agrees with the true motion to within ${bound(f.difference, unit)}: it is the path of a true motion between these ends, ${start}. ${what}`;
    // the method's account, behind "How this was computed"
    const method = `Newton's method made the discrete action stationary in ${newton} step${newton === 1 ? "" : "s"} on a ${gridSteps}-step time grid. `
      + `The true motion between the same ends comes from shooting (the starting rate adjusted until the run ends at the end point): the shooting solution runs along the relaxed path to within ${bound(f.difference, unit)}. `
      + `Halving the time step of the grid moves the path by at most ${bound(3 * f.error_estimate, unit)}, and the extrapolated path shown is closer still.`;
    return { found: true, text: text + several(f, { q, label, rateUnit, T, startRate, sameEnds }), method, advice: [] };
  }
  const why = [];
  if (f.reasons.includes("not-stationary")) {
    why.push(`Newton's method stopped after ${newton} step${newton === 1 ? "" : "s"} without solving the discrete Euler–Lagrange equations (they are still off by about ${magnitude(f.residual)} of their size), so the curve shown is not a stationary path of S.`);
  }
  if (f.reasons.includes("too-coarse")) {
    why.push(`The ${gridSteps}-step time grid is too coarse for this path: halving the step moves it by ${bound(3 * f.error_estimate, unit)}.`);
  }
  if (f.reasons.includes("disagrees")) {
    why.push(`No true motion runs along it: the shooting solution between the same ends (${start}) differs from it by up to ${bound(f.difference, unit)}.`);
  }
  if (f.reasons.includes("no-shooting")) {
    // shooting failing to converge proves nothing about existence: say what was tried, not that no motion exists
    why.push(`Shooting (adjusting the starting rate until the run ends at the end point at τ = ${fmt(T)} s) did not converge from the starting rates it tried, so there is no true motion to check the curve against.`);
  }
  const tips = f.advice.map((a) => ADVICE[a]).filter(Boolean);
  const todo = tips.length ? ` To find it: ${tips.length > 1 ? `${tips.slice(0, -1).join(", ")}, or ${tips[tips.length - 1]}` : tips[0]}.` : "";
  return { found: false, text: `The path was not found. ${why.join(" ")}${todo}`, method: "", advice: f.advice };
}
