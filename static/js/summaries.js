/**
 * summaries.js — text alternatives for plots: small data tables.
 *
 *   seriesTable(container, caption, t, series)  a table of each series' value at the
 *       start and end of the run, its minimum and maximum (series: [{name, values}])
 *   table(container, caption, headers, rows)    any table (rows: arrays of cells)
 *   fmt(x)                                       a number for reading: 4 significant digits
 */

export function fmt(x) {
  if (x === null || x === undefined || Number.isNaN(x)) return "–";
  if (x < 0) return `−${fmt(-x)}`; // a typeset minus sign, not a hyphen
  if (!Number.isFinite(x)) return x > 0 ? "∞" : "−∞";
  if (x === 0) return "0";
  const a = Math.abs(x);
  if (a >= 1e5 || a < 1e-3) {
    const [mantissa, exponent] = x.toExponential(3).split("e");
    const sup = String(Number(exponent)).replace("-", "⁻").replace(/\d/g, (d) => "⁰¹²³⁴⁵⁶⁷⁸⁹"[d]);
    return `${Number(mantissa)} × 10${sup}`;
  }
  return String(Number(x.toPrecision(4)));
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
export function fmtResolved(x, floor) {
  return Number.isFinite(x) && Number.isFinite(floor) && Math.abs(x) <= floor ? "≈ 0" : fmt(x);
}

/** "is constant: 0.8774 N" when a series does not vary beyond round-off, else "ranges from a to b N". */
export function constantOrRange(values, unit = "") {
  let lo = Infinity, hi = -Infinity;
  for (const v of values) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  const u = unit ? ` ${unit}` : "";
  if (lo > hi) return "no finite value";
  // constant when the spread is below 10⁻⁹ of the size (the values' round-off) or the 4 shown digits agree
  if (hi - lo <= 1e-9 * Math.max(Math.abs(lo), Math.abs(hi)) || fmt(lo) === fmt(hi)) return `is constant: ${fmt((lo + hi) / 2)}${u}`;
  return `ranges from ${fmt(lo)} to ${fmt(hi)}${u}`;
}

/**
 * Whether a run's error estimate is small against the motion it describes: the worst ratio,
 * over coordinates, of the estimated error to the coordinate's range over the run (or its size,
 * for a coordinate that hardly moves).  A run is to be trusted when the ratio is below `limit`.
 */
export function errorAgainstMotion(stats, state, coordinates, limit = 0.05) {
  const by = stats.error_estimate_by_coordinate || {};
  let worst = 0, where = null;
  for (const q of coordinates) {
    const err = Number.isFinite(by[q]) ? by[q] : stats.error_estimate;
    if (!Number.isFinite(err)) continue;
    let lo = Infinity, hi = -Infinity;
    for (const v of state[q] || []) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    const scale = Math.max(hi - lo, 1e-3 * Math.max(Math.abs(lo), Math.abs(hi)), 1e-12);
    if (err / scale > worst) { worst = err / scale; where = q; }
  }
  return { ratio: worst, coordinate: where, trusted: worst < limit };
}

export function table(container, caption, headers, rows) {
  if (!container) return null;
  const t = document.createElement("table");
  const cap = document.createElement("caption");
  cap.textContent = caption;
  t.append(cap);
  const head = t.createTHead().insertRow();
  for (const h of headers) {
    const th = document.createElement("th");
    th.scope = "col";
    th.textContent = h;
    head.append(th);
  }
  const body = t.createTBody();
  for (const row of rows) {
    const tr = body.insertRow();
    row.forEach((cell, k) => {
      const c = k === 0 ? document.createElement("th") : document.createElement("td");
      if (k === 0) c.scope = "row";
      c.textContent = typeof cell === "number" ? fmt(cell) : String(cell);
      tr.append(c);
    });
  }
  container.replaceChildren(t);
  return t;
}

export function seriesTable(container, caption, t, series) {
  if (!container) return null;
  const rows = series.map(({ name, values }) => {
    let lo = Infinity, hi = -Infinity;
    for (const v of values) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    return [name, values[0], values[values.length - 1], lo, hi];
  });
  const end = t.length ? fmt(t[t.length - 1]) : "–";
  return table(container, caption, ["quantity", "at t = 0", `at t = ${end} s`, "minimum", "maximum"], rows);
}
