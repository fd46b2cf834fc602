/**
 * plotkit.js — shared pieces of the plot panels (plots.js, reduction.js): Plotly config,
 * colours, a base layout, axes, the time-cursor shape, and the parts of a panel section
 * (.plot, .data-summary .table, .readout, .panel-tools).
 */

export const CONFIG = { responsive: true, displaylogo: false };
export const COLORS = { T: "#0b5cad", U: "#b34700", E: "#1b1f24", h: "#2e7d32", a: "#6a1b9a", b: "#00838f" };
export const PALETTE = ["#0b5cad", "#b34700", "#2e7d32", "#6a1b9a", "#00838f", "#8d6e00"];

export function layout(extra = {}) {
  return {
    margin: { l: 64, r: 16, t: 24, b: 44 }, height: 340, font: { size: 13 },
    paper_bgcolor: "#fff", plot_bgcolor: "#fff", legend: { orientation: "h", x: 0, y: 1.02, yanchor: "bottom" },
    hovermode: "x unified", ...extra,
  };
}

export const axis = (text, extra = {}) => ({ title: { text }, gridcolor: "#e6e8eb", zerolinecolor: "#b8bec5", ...extra });
export const cursorShape = (t) => ({ type: "line", xref: "x", yref: "paper", x0: t, x1: t, y0: 0, y1: 1, line: { color: "#57606a", width: 1.5, dash: "dot" } });
export const line = (x, y, name, color, dash = "solid") => ({ type: "scatter", mode: "lines", x, y, name, line: { color, width: 2, dash } });
export const diff = (arr) => Array.from(arr, (v) => v - arr[0]);
export const finite = (arr) => arr.filter((v) => Number.isFinite(v));
export const capital = (text) => text.charAt(0).toUpperCase() + text.slice(1);

export function parts(section) {
  return {
    plot: section.querySelector(".plot"),
    summary: section.querySelector(".data-summary .table"),
    readout: section.querySelector(".readout"),
    tools: section.querySelector(".panel-tools"),
  };
}

