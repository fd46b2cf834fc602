/**
 * summaries.js — text alternatives for plots: small data tables.
 *
 *   seriesTable(container, caption, t, series)  a table of each series' value at the
 *       start and end of the run, its minimum and maximum (series: [{name, values}])
 *   table(container, caption, headers, rows)    any table (rows: arrays of cells)
 *   fmt(x, digits)                               a number for reading: 4 significant digits (or `digits`)
 *   fmtResolved(x, floor, digits)                a number known only to `floor`: no digit finer than it
 *   percent(x, floor)                            a relative difference x in per cent: 3 digits at most
 */

import { proseHTML } from "./prose.js";

// the significant digits of a number read off a run or a formula, as a textbook prints it (6.414 rad/s), and
// of a relative difference, itself the small difference of two such numbers (−6.22 %, not −6.221 %)
export const DIGITS = 4;
export const DIFFERENCE_DIGITS = 3;

/** A number for reading: `digits` significant digits, a true minus sign, powers of ten beyond 10⁵ and below 10⁻³. */
export function fmt(x, digits = DIGITS) {
  if (x === null || x === undefined || Number.isNaN(x)) return "–";
  if (x < 0) return `−${fmt(-x, digits)}`; // a typeset minus sign, not a hyphen
  if (!Number.isFinite(x)) return x > 0 ? "∞" : "−∞";
  if (x === 0) return "0";
  const a = Math.abs(x);
  if (a >= 1e5 || a < 1e-3) {
    const [mantissa, exponent] = x.toExponential(digits - 1).split("e");
    const sup = String(Number(exponent)).replace("-", "⁻").replace(/\d/g, (d) => "⁰¹²³⁴⁵⁶⁷⁸⁹"[d]);
    return `${Number(mantissa)} × 10${sup}`;
  }
  return String(Number(x.toPrecision(digits)));
}

/** The median of finite numbers (null for none). */
export function median(values) {
  const v = values.filter(Number.isFinite).sort((a, b) => a - b);
  if (!v.length) return null;
  const k = Math.floor(v.length / 2);
  return v.length % 2 ? v[k] : (v[k - 1] + v[k]) / 2;
}

/**
 * A value for reading that is only resolved down to `floor` (an error estimate, the round-off
 * of the values it comes from): below it, "≈ 0" rather than digits of noise.
 */
export function fmtResolved(x, floor, digits = DIGITS) {
  if (!Number.isFinite(x) || !(floor > 0) || !Number.isFinite(floor)) return fmt(x, digits);
  if (Math.abs(x) <= floor) return "≈ 0";
  // the digits from x's leading one down to the floor's: a value known to ±0.003 has no digit below 0.001
  const known = Math.floor(Math.log10(Math.abs(x))) - Math.floor(Math.log10(floor)) + 1;
  return fmt(x, Math.max(1, Math.min(digits, known)));
}

/** A relative difference x (0.01 for 1 %) in per cent, known to the relative `floor`: "−6.22 %", "≈ 0 %". */
export const percent = (x, floor = 0) => `${fmtResolved(100 * x, 100 * floor, DIFFERENCE_DIGITS)} %`;

/** "is constant: 0.8774 N" when a series does not vary beyond round-off, else "ranges from a to b N". */
export function constantOrRange(values, unit = "") {
  let lo = Infinity, hi = -Infinity;
  for (const v of values) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  const u = unit ? ` ${unit}` : "";
  if (lo > hi) return "no finite value";
  // constant when the spread is below 10⁻⁹ of the size (the values' round-off) or the 4 shown digits agree
  if (hi - lo <= 1e-9 * Math.max(Math.abs(lo), Math.abs(hi)) || fmt(lo) === fmt(hi)) return `is constant: ${fmt((lo + hi) / 2)}${u}`;
  const [from, to] = rangeEnds(lo, hi);
  return `ranges from ${from} to ${to}${u}`;
}

// the share of a range's span below which its ends carry no figure: a thousandth, the last of the four digits shown
export const RANGE_FIGURES = 1e-3;

/** A range's two ends, each to the figures that mean something against the range's size: nothing finer than a
 *  thousandth of the span (lo to hi), nor than ``floor`` (a run's energy resolution).  A sampled end that small is
 *  a zero the samples straddle (the pendulum's U at the bottom of its swing, the helix's wire force m α² R ż²
 *  where ż changes sign): "≈ 0", not the digits of the sample nearest it ("1.391 × 10⁻⁵"). */
export function rangeEnds(lo, hi, floor = 0) {
  // |end| ≤ max(floor, 10⁻³ (hi − lo)) reads "≈ 0"; a larger end keeps its digits down to that size
  const known = Math.max(floor > 0 ? floor : 0, RANGE_FIGURES * Math.abs(hi - lo));
  return [fmtResolved(lo, known), fmtResolved(hi, known)];
}

/** "10⁻⁸": the power of ten nearest a positive number (an order of magnitude, for a glance). */
export function magnitude(x) {
  if (!(x > 0) || !Number.isFinite(x)) return fmt(x);
  const e = Math.round(Math.log10(x));
  if (e === 0) return "1";
  return "10" + String(e).replace("-", "⁻").replace(/\d/g, (d) => "⁰¹²³⁴⁵⁶⁷⁸⁹"[d]);
}

/** A number with 2 significant digits (run times: more digits would be timing noise). */
export const short = (x) => (Number.isFinite(x) ? fmt(Number(x.toPrecision(2))) : "–");

/**
 * The run status a student reads at a glance: "Simulated 10 s · error in the coordinates ≈ 4 × 10⁻⁹ rad"
 * (the largest estimated difference from the true motion; "details" says more).
 * stats: the simulate API's stats (t_end_reached, error_estimate); unit: the coordinates' unit when they share one
 * ("" when they do not: the error is then in each coordinate's own unit).  How long the computer took, and with
 * which method, is no part of the physics: those sit under "details".
 */
export function statusLine(stats, unit = "") {
  const parts = [`Simulated ${short(stats.t_end_reached)} s`];
  // the error bound is the largest difference from the true motion over the samples, in the coordinates' units
  const said = (x) => (unit ? `${x} ${unit}` : `${x} (each in its unit)`);
  if (Number.isFinite(stats.error_estimate)) {
    parts.push(`error in the coordinates ≈ ${said(stats.error_estimate > 0 ? fmt(Number(stats.error_estimate.toPrecision(1))) : "0")}`);
  }
  return parts.join(" · ");
}

/** The unit the coordinates share ("rad", "m"), or "" when they have different ones. */
export function sharedUnit(data) {
  const units = [...new Set((data.coordinates || []).map((q) => data.units?.[q]))];
  return units.length === 1 && units[0] ? units[0] : "";
}

export function table(container, caption, headers, rows) {
  if (!container) return null;
  const t = document.createElement("table");
  const cap = document.createElement("caption");
  cap.innerHTML = proseHTML(caption);
  t.append(cap);
  const head = t.createTHead().insertRow();
  for (const h of headers) {
    const th = document.createElement("th");
    th.scope = "col";
    th.innerHTML = proseHTML(h);
    head.append(th);
  }
  const body = t.createTBody();
  for (const row of rows) {
    const tr = body.insertRow();
    row.forEach((cell, k) => {
      const c = k === 0 ? document.createElement("th") : document.createElement("td");
      if (k === 0) c.scope = "row";
      // a missing value reads as a dash, never as "null" or "undefined"
      c.innerHTML = proseHTML(typeof cell === "number" ? fmt(cell) : cell === null || cell === undefined ? "–" : String(cell));
      tr.append(c);
    });
  }
  container.replaceChildren(t);
  return t;
}

/**
 * The run's relative tolerance (its request's rtol), never below 10⁻⁹ (round-off of the sums behind a series):
 * a value smaller than this times its series' size is integration noise, not data.
 */
export const relativeFloor = (run) => Math.max(1e-9, run && run.request && Number.isFinite(run.request.rtol) ? run.request.rtol : 0);

export function seriesTable(container, caption, t, series, relative = 1e-9) {
  if (!container) return null;
  const rows = series.map(({ name, values }) => {
    let lo = Infinity, hi = -Infinity;
    for (const v of values) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    // a value below the tolerance times the series' size prints as 0 (the block at the foot of the ramp: X = 0,
    // not 8.674 × 10⁻¹⁹)
    const floor = relative * Math.max(Math.abs(lo), Math.abs(hi));
    const clean = (v) => (Number.isFinite(v) && Math.abs(v) <= floor ? 0 : v);
    return [name, clean(values[0]), clean(values[values.length - 1]), clean(lo), clean(hi)];
  });
  const end = t.length ? fmt(t[t.length - 1]) : "–";
  return table(container, caption, ["quantity", "at t = 0", `at t = ${end} s`, "minimum", "maximum"], rows);
}
