/**
 * plotkit.js — shared pieces of the plot panels (plots.js, reduction.js): Plotly config,
 * colours, a base layout, axes, the parts of a panel section (.plot, .data-summary .table,
 * .readout, .panel-tools), and Overlay: time cursors and "now" markers drawn in an SVG laid
 * over a plot, so that moving them never asks Plotly to lay the figure out again.
 *
 * No plot shows Plotly's tool bar (a book's figure has no camera or home icons; a double click resets
 * the axes), so nothing offers to send a plot to an outside service (no Chart Studio, no "Share").  On a coarse pointer (a phone) the
 * plots do not zoom or pan on drag, so a swipe that starts on a plot scrolls the page;
 * a "Zoom" button in the panel's tools turns dragging on for that plot.
 *
 * react(panel, traces, layout): Plotly.react for the server's run; for the browser's preview
 * (panel.previewing) the traces are drawn as lines on a canvas over the plot, in its current
 * axes, with the plot itself greyed: a few milliseconds instead of a Plotly redraw.
 */

import { isFolded } from "./fold.js";
import { proseHTML, proseReadout } from "./prose.js";

export const COARSE = typeof matchMedia === "function" && matchMedia("(pointer: coarse)").matches;

export const CONFIG = {
  responsive: true, displaylogo: false, showSendToCloud: false, showEditInChartStudio: false, showLink: false,
  // no tool bar on any plot (a book's figure carries no camera or home icons): a double click
  // resets the axes after a zoom
  scrollZoom: false, displayModeBar: false, doubleClick: "reset+autosize",
};
export const COLORS = { T: "#0b5cad", U: "#b34700", E: "#1b1f24", h: "#2e7d32", a: "#6a1b9a", b: "#00838f" };
export const PALETTE = ["#0b5cad", "#b34700", "#2e7d32", "#6a1b9a", "#00838f", "#8d6e00"];
// each colour of PALETTE as a reader names it (a caption says which orbit by its colour)
export const PALETTE_NAMES = ["blue", "orange", "green", "purple", "teal", "ochre"];

export function layout(extra = {}) {
  return {
    margin: { l: 64, r: 16, t: 34, b: 44 }, height: 320, font: { size: 13 },
    paper_bgcolor: "#fff", plot_bgcolor: "#fff", legend: { orientation: "h", x: 0, y: 1.02, yanchor: "bottom" },
    hovermode: COARSE ? false : "x unified", dragmode: COARSE ? false : "zoom", ...extra,
  };
}

/**
 * Every axis: its title (with the unit in brackets) and ticks in powers of ten (2×10⁻⁶), never
 * Plotly's default SI prefixes ("1p" would read as a pico-unit).
 */
export const AXIS_FORMAT = { exponentformat: "power", showexponent: "all", separatethousands: false };
// automargin with a standoff keeps the title clear of the tick labels, however wide they are (10⁻⁹ on a phone)
// an axis title and a legend name set their subscripts as the page's sentences do (prose.js): U_eff -> U<sub>eff</sub>
// the tick labels stand outside the plotting area, past a short tick mark, so no curve runs through them
// (a curve starting at t = 0 ran through the energy plot's 0, 1, 2, 3, 4); automargin makes room for them
export const TICKS = { ticks: "outside", ticklen: 5, tickcolor: "#b8bec5", ticklabelposition: "outside" };
export const axis = (text, extra = {}) => ({ title: { text: proseHTML(text), standoff: 6 }, automargin: true, gridcolor: "#e6e8eb", zerolinecolor: "#b8bec5", ...TICKS, ...AXIS_FORMAT, ...extra });

/** The SI unit of the generalized momentum of a coordinate measured in `unit` (rad or m). */
export const momentumUnit = (unit) => (unit === "rad" ? "kg·m²/s" : unit === "m" ? "kg·m/s" : "SI units");
/** "x (m)", or "x" alone where the unit is not known (never a wrong unit; app/viz/units.py). */
export const titled = (name, unit) => (unit ? `${name} (${unit})` : name);
/** The unit of a coordinate's rate: the page's rate_units, else from its unit. */
export const rateUnit = (data, q) => (data.rate_units && data.rate_units[q]) || (data.units[q] ? `${data.units[q]}/s` : "1/s");
export const line = (x, y, name, color, dash = "solid") => ({ type: "scatter", mode: "lines", x, y, name, line: { color, width: 2, dash } });
export const diff = (arr) => Array.from(arr, (v) => v - arr[0]);
export const finite = (arr) => Array.from(arr).filter((v) => Number.isFinite(v));
export const capital = (text) => text.charAt(0).toUpperCase() + text.slice(1);

/** Panels that ask the server for work (a report, a section) do so only in view: ``panel.visible``
 *  turns true when the section nears the viewport unfolded (fold.js: a phone folds its panels), and the
 *  last run is drawn then. */
export function drawWhenVisible(panel, section) {
  panel.visible = !("IntersectionObserver" in window);
  if (panel.visible) return;
  let near = false;
  const show = () => {
    if (panel.visible || !near || isFolded(section)) return;
    observer.disconnect();
    panel.visible = true;
    if (panel.run) panel.draw(panel.run);
  };
  const observer = new IntersectionObserver((entries) => {
    near = entries[entries.length - 1].isIntersecting;
    show();
  }, { rootMargin: "200px" });
  observer.observe(section);
  section.addEventListener("lagrange:unfold", show);
}

export function parts(section) {
  return {
    plot: section.querySelector(".plot"),
    summary: section.querySelector(".data-summary .table"),
    readout: proseReadout(section.querySelector(".readout")),
    tools: section.querySelector(".panel-tools"),
  };
}

/** A panel drawn from each run in the browser (a preview while a run is dragged): its section's parts and an overlay. */
export class PreviewPanel {
  constructor(section, data) {
    this.section = section; this.data = data; Object.assign(this, parts(section));
    this.overlay = new Overlay(this.plot);
    this.preview = true;
  }
}

const SVG = "http://www.w3.org/2000/svg";

export function react(panel, traces, lay) {
  const plot = panel.plot;
  traces = traces.map((t) => (typeof t.name === "string" ? { ...t, name: proseHTML(t.name) } : t));
  if (panel.previewing && plot._fullLayout && panel.overlay) {
    panel.overlay.lines(traces);
    panel.section.classList.add("previewing");
    return null;
  }
  panel.overlay?.lines([]);
  panel.section.classList.remove("previewing");
  return Plotly.react(plot, traces, lay, CONFIG);
}

/** An SVG over a Plotly plot: a vertical time cursor, markers and level lines in data coordinates. */
export class Overlay {
  constructor(plot) {
    this.plot = plot;
    const wrap = document.createElement("div");
    wrap.className = "plot-wrap";
    plot.before(wrap);
    wrap.append(plot);
    this.svg = document.createElementNS(SVG, "svg");
    this.svg.setAttribute("class", "plot-overlay");
    this.svg.setAttribute("aria-hidden", "true");
    wrap.append(this.svg);
    this.items = {};
    if (COARSE) this.zoomToggle(plot.closest("section")?.querySelector(".panel-tools"));
  }

  zoomToggle(tools) {
    if (!tools) return;
    const button = Object.assign(document.createElement("button"), { type: "button", textContent: "Zoom" });
    button.className = "zoom-toggle";
    button.setAttribute("aria-pressed", "false");
    button.addEventListener("click", () => {
      const on = button.getAttribute("aria-pressed") !== "true";
      button.setAttribute("aria-pressed", String(on));
      this.plot.classList.toggle("zooming", on);
      Plotly.relayout(this.plot, { dragmode: on ? "zoom" : false });
    });
    tools.append(button);
  }

  /** Preview lines: traces ({x, y, line: {color, dash}, yaxis}) drawn on a canvas in the plot's axes. */
  lines(traces) {
    if (!this.canvas) {
      this.canvas = document.createElement("canvas");
      this.canvas.className = "plot-preview";
      this.canvas.setAttribute("aria-hidden", "true");
      this.svg.before(this.canvas);
    }
    const c = this.canvas, dpr = window.devicePixelRatio || 1;
    const w = this.plot.clientWidth, h = this.plot.clientHeight;
    if (c.width !== Math.round(w * dpr) || c.height !== Math.round(h * dpr)) {
      c.width = Math.round(w * dpr); c.height = Math.round(h * dpr);
    }
    const ctx = c.getContext("2d");
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, w, h);
    c.dataset.lines = String(traces.length);
    const fl = this.plot._fullLayout;
    if (!fl || !traces.length) return;
    for (const tr of traces) {
      const xa = fl.xaxis, ya = fl[tr.yaxis ? `yaxis${tr.yaxis.slice(1)}` : "yaxis"];
      if (!xa || !ya || !tr.x || !tr.y) continue;
      ctx.save();
      ctx.beginPath();
      ctx.rect(xa._offset, ya._offset, xa._length, ya._length);
      ctx.clip();
      ctx.strokeStyle = (tr.line && tr.line.color) || (tr.marker && tr.marker.color) || "#1b1f24";
      ctx.lineWidth = 2;
      ctx.setLineDash(tr.line && tr.line.dash === "dash" ? [6, 4] : []);
      ctx.beginPath();
      let pen = false;
      for (let i = 0; i < tr.x.length; i++) {
        const x = xa._offset + xa.l2p(tr.x[i]), y = ya._offset + ya.l2p(tr.y[i]);
        if (!Number.isFinite(x) || !Number.isFinite(y)) { pen = false; continue; }
        if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
        pen = true;
      }
      ctx.stroke();
      ctx.restore();
    }
  }

  item(key, tag, attrs) {
    let el = this.items[key];
    if (!el) {
      el = this.items[key] = document.createElementNS(SVG, tag);
      for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
      this.svg.append(el);
    }
    return el;
  }

  axes(x = "xaxis", y = "yaxis") {
    const fl = this.plot._fullLayout;
    if (!fl || !fl[x] || !fl[y]) return null;
    return { fl, xa: fl[x], ya: fl[y] };
  }

  /** A vertical dotted line at x = value over the whole plot area (the time cursor). */
  cursor(value) {
    const a = this.axes();
    if (!a || !Number.isFinite(value)) return;
    const px = a.xa._offset + a.xa.l2p(value);
    const el = this.item("cursor", "line", { class: "cursor", stroke: "#57606a", "stroke-width": "1.5", "stroke-dasharray": "3 3" });
    el.setAttribute("x1", px); el.setAttribute("x2", px);
    el.setAttribute("y1", a.fl._size.t); el.setAttribute("y2", a.fl._size.t + a.fl._size.h);
    el.dataset.value = String(value);
  }

  /** Filled markers at data points [[x, y], ...] (the current state). */
  points(key, pts, { color = "#c62828", r = 6, shape = "circle" } = {}) {
    const a = this.axes();
    if (!a) return;
    const group = this.item(key, "g", { class: key, fill: color, stroke: "#1b1f24", "stroke-width": "1" });
    while (group.childNodes.length > pts.length) group.lastChild.remove();
    while (group.childNodes.length < pts.length) {
      group.append(document.createElementNS(SVG, shape === "diamond" ? "path" : "circle"));
    }
    pts.forEach(([x, y], k) => {
      const el = group.childNodes[k];
      const px = a.xa._offset + a.xa.l2p(x), py = a.ya._offset + a.ya.l2p(y);
      const visible = Number.isFinite(px) && Number.isFinite(py);
      el.setAttribute("visibility", visible ? "visible" : "hidden");
      if (!visible) return;
      if (shape === "diamond") el.setAttribute("d", `M${px},${py - r}L${px + r},${py}L${px},${py + r}L${px - r},${py}Z`);
      else { el.setAttribute("cx", px); el.setAttribute("cy", py); el.setAttribute("r", r); }
    });
    group.dataset.points = JSON.stringify(pts);
  }

  /** A horizontal dashed line at y = value across the plot area (an energy level). */
  level(key, value, color = "#1b1f24") {
    const a = this.axes();
    if (!a) return;
    const el = this.item(key, "line", { class: key, stroke: color, "stroke-width": "1.5", "stroke-dasharray": "6 4" });
    const py = a.ya._offset + a.ya.l2p(value);
    el.setAttribute("x1", a.fl._size.l); el.setAttribute("x2", a.fl._size.l + a.fl._size.w);
    el.setAttribute("y1", py); el.setAttribute("y2", py);
    el.dataset.value = String(value);
  }
}
