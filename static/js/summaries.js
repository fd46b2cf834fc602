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
