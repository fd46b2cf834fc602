/**
 * action-verdict.js — what the action panel says after Relax, in sentences, from the server's answer.
 *
 *   verdict(answer, { q, label, unit, rateUnit, T, steps }) -> { found, text, advice: [codes] }
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
  "closer-trial": "drag the trial path nearer the true path (a smaller ε)",
  "shorter-t": "choose a shorter τ",
  "from-shooting": "start from the shooting solution (the button “Start from the shooting solution”)",
};

export function verdict(f, { q, label, unit, rateUnit, T, steps: gridSteps }) {
  const newton = f.iterations.length - 1;
  // the shooting solution's starting rate of the shown coordinate; below the shooting's accuracy it is 0
  const v = f.shooting ? f.shooting.velocity[`${q}_dot`] : null;
  const rate = Math.abs(v) < RATE_FLOOR ? "0" : fmt(v);
  const start = f.shooting ? `the motion that starts with ${label}̇(0) = ${rate}${rateUnit ? ` ${rateUnit}` : ""}` : "";
  if (f.found) {
    const what = f.kind === "minimum"
      ? "It is a minimum of the discrete action: every small change of the path raises S."
      : `It is a saddle of the discrete action, not a minimum: ${f.negative_directions} direction${f.negative_directions > 1 ? "s" : ""} of change lower${f.negative_directions > 1 ? "" : "s"} S, because τ = ${fmt(T)} s is past the kinetic focus.`;
    const text = `Newton's method made the discrete action stationary in ${newton} step${newton === 1 ? "" : "s"}, and the path it found is the path of a true motion between these ends. `
      + `The shooting solution (${start}) runs along it to within ${bound(f.difference, unit)}; `
      + `halving the time step of the ${gridSteps}-step grid moves the path by at most ${bound(3 * f.error_estimate, unit)}, and the extrapolated path shown is closer still. ${what}`;
    return { found: true, text, advice: [] };
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
    why.push(`No motion from the start reaches the end point at τ = ${fmt(T)} s by shooting, so there is nothing to check the curve against.`);
  }
  const tips = f.advice.map((a) => ADVICE[a]).filter(Boolean);
  const todo = tips.length ? ` To find it: ${tips.length > 1 ? `${tips.slice(0, -1).join(", ")}, or ${tips[tips.length - 1]}` : tips[0]}.` : "";
  return { found: false, text: `The path was not found. ${why.join(" ")}${todo}`, advice: f.advice };
}
