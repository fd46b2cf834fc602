/**
 * energybars.js — bars of T, U, E = T + U (and h where h ≠ E) at the instant the animation shows.
 * A system given by L alone has no T and U told apart, so no E: its one bar is h.
 *
 *   const bars = new EnergyBars(container);
 *   bars.load(run);   // run from simulation.js prepareRun(): one scale for the whole run
 *   bars.set(i);      // the values at sample i (a few style writes: cheap enough for every frame)
 *
 * Every bar starts at zero on one shared axis, so a negative U points left and the bars of
 * T and U add up to the bar of E.  Each row carries its value as text; a value within the run's
 * energy resolution (simulation.js prepareRun) reads "≈ 0 J", not digits of rounding noise.
 * A line under the bars says each energy's range over the run ("Over the 2 s run: T from ≈ 0 to 8.1 J ·
 * U from −8.1 to ≈ 0 J · E stays ≈ 0 J"), so the first view, at t = 0, already tells where the run goes.
 */

/** Each row's least and greatest value over the run, in words; a row that never leaves its start "stays". */
export function overTheRun(rows, t, resolution) {
  const parts = rows.map((r) => {
    let lo = Infinity, hi = -Infinity;
    for (const v of r.values) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    if (lo > hi) return `${r.name} has no finite value`;
    // a spread within the run's energy resolution, or below the four digits shown, is no change; each end to the
    // figures that mean something against the range's size (U from ≈ 0, not from 1.391 × 10⁻⁵ J)
    const [a, b] = rangeEnds(lo, hi, resolution);
    if (hi - lo <= resolution || a === b) return `${r.name} stays ${fmtResolved((lo + hi) / 2, resolution)} J`;
    return `${r.name} from ${a} to ${b} J`;
  });
  const end = t && t.length ? t[t.length - 1] : null;
  return `Over the ${end === null ? "" : `${fmt(Number(end.toPrecision(2)))} s `}run: ${parts.join(" · ")}.`;
}
import { COLORS } from "./plotkit.js";
import { fmt, fmtResolved, rangeEnds } from "./summaries.js";

export class EnergyBars {
  constructor(container) {
    this.container = container;
  }

  load(run) {
    const rows = [];
    if (run.T) rows.push({ key: "T", name: "T", title: "kinetic energy", values: run.T, color: COLORS.T });
    if (run.U) rows.push({ key: "U", name: "U", title: "potential energy", values: run.U, color: COLORS.U });
    // h_equals_e null: only L was given, E = T + U is not defined (the series the server calls energy is h)
    const undecided = run.data.h_equals_e === null || run.data.h_equals_e === undefined;
    if (run.energy && !undecided) rows.push({ key: "E", name: "E", title: "T + U", values: run.energy, color: COLORS.E });
    if (run.hamiltonian && !run.data.h_equals_e) rows.push({ key: "h", name: "h", title: "the energy function", values: run.hamiltonian, color: COLORS.h });
    let lo = 0, hi = 0;
    for (const r of rows) for (const v of r.values) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    this.lo = lo; this.span = Math.max(hi - lo, 1e-300);
    this.rows = rows;
    this.resolution = run.resolution; // below it an energy reads "≈ 0" (within the run's error)
    const zero = (100 * -lo) / this.span;
    this.container.replaceChildren(...rows.map((r) => {
      const row = document.createElement("div");
      row.className = "ebar";
      row.dataset.key = r.key;
      row.innerHTML = `<span class="ebar-name" title="${r.title}"><i>${r.name}</i></span><span class="ebar-track"><span class="ebar-zero"></span><span class="ebar-fill"></span></span><span class="ebar-value"></span>`;
      row.querySelector(".ebar-fill").style.background = r.color;
      row.querySelector(".ebar-zero").style.left = `${zero}%`;
      r.fill = row.querySelector(".ebar-fill");
      r.text = row.querySelector(".ebar-value");
      return row;
    }));
    // the run at a glance under the bars: at t = 0 a mechanism at rest where U = 0 shows three empty bars,
    // and this line says where the energies go over the run
    const range = document.createElement("p");
    range.className = "ebar-range";
    range.textContent = overTheRun(rows, run.t, this.resolution);
    this.container.append(range);
    this.container.dataset.ready = "true";
  }

  set(i) {
    if (!this.rows) return;
    for (const r of this.rows) {
      const v = r.values[i];
      if (!Number.isFinite(v)) { r.fill.style.width = "0"; r.text.textContent = "–"; continue; }
      const a = (100 * (Math.min(0, v) - this.lo)) / this.span, w = (100 * Math.abs(v)) / this.span;
      r.fill.style.left = `${a}%`;
      r.fill.style.width = `${w}%`;
      r.text.textContent = `${fmtResolved(v, this.resolution)} J`;
    }
  }
}
