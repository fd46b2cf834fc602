/**
 * derivation.js — typeset and render derivations with KaTeX (loaded by base.html).
 *
 *   typeset(root)                 render every .math element under root (its text
 *                                 is the LaTeX; .math-display for display math); prose
 *                                 with $…$ inside .prose-math elements goes through
 *                                 KaTeX's auto-render.  Returns the number of errors.
 *   printReady()                  open every collapsed step while printing.
 *   whenTypeset(root)             typeset once KaTeX's deferred script has run, and record
 *                                 the error count in document.body.dataset.katexErrors.
 *   foldSteps(root)               show the core steps (li.step without .bookkeeping) and put
 *                                 the others behind one "all steps" toggle button.
 *
 * KaTeX errors never throw: a bad formula shows as a .katex-error element, which
 * the browser tests look for.
 */

import { breakDisplay, spacedRows } from "./breaking.js";

export function typeset(root = document) {
  const katex = window.katex;
  if (!katex) return 0;
  for (const el of root.querySelectorAll(".math")) {
    if (el.dataset.typeset === "1") continue;
    // the server sends MathML (readable without JavaScript) with the TeX in data-tex
    const tex = el.dataset.tex ?? el.textContent;
    el.setAttribute("data-tex", tex);
    const display = el.classList.contains("math-display");
    katex.render(display ? spacedRows(tex) : tex, el, { displayMode: display, throwOnError: false });
    el.dataset.typeset = "1";
  }
  if (window.renderMathInElement) {
    for (const el of root.querySelectorAll(".prose-math")) {
      if (el.dataset.typeset === "1") continue;
      window.renderMathInElement(el, {
        delimiters: [{ left: "$$", right: "$$", display: true }, { left: "$", right: "$", display: false }],
        throwOnError: false,
      });
      el.dataset.typeset = "1";
    }
  }
  markWide(root);
  return root.querySelectorAll(".katex-error").length;
}

const WIDE_LABEL = "Wide formula: scroll sideways to read all of it";
let widths = null;

/**
 * A display formula wider than its box (on a phone) scrolls inside that box: the box is then a labelled
 * region the keyboard can reach (tabindex 0), and stops being one when it fits again.  Boxes are watched
 * as they appear (a step unfolded, an "all steps" toggle) and as the window changes width.
 */
export function markWide(root = document) {
  if (typeof ResizeObserver === "undefined") return;
  // a box that just appeared may first be typeset with a font still loading: decide again once it is in
  const again = (el) => { fitOrScroll(el); if (document.fonts) document.fonts.ready.then(() => fitOrScroll(el, true)); };
  widths ??= new ResizeObserver((entries) => { for (const e of entries) again(e.target); });
  const boxes = [...root.querySelectorAll(".math-display")];
  // decided at once as well (the observer reports only at the next frame): a box typeset here is a keyboard
  // region by the time typeset() returns, not a frame later
  for (const el of boxes) { widths.observe(el); fitOrScroll(el); }
  // KaTeX's fonts widen a formula without resizing its box: decide again once they are in
  if (document.fonts) document.fonts.ready.then(() => boxes.forEach((el) => fitOrScroll(el, true)));
}

/**
 * A formula wider than its box is broken across lines (breaking.js), decided again whenever the box's width
 * changes (a phone turned, a window resized) or the fonts arrive; what still overflows scrolls.
 */
function fitOrScroll(el, fonts = false) {
  if (el.offsetParent === null) return; // hidden: decided when it shows
  const width = String(el.clientWidth);
  // the new typesetting changes the box's height, which the observer reports: decided once per width
  if (el.dataset.typeset === "1" && (fonts || el.dataset.fitWidth !== width)) {
    el.dataset.fitWidth = width;
    breakDisplay(el, window.katex);
  }
  const wide = el.scrollWidth > el.clientWidth + 1;
  if (wide) {
    el.tabIndex = 0;
    el.setAttribute("role", "region");
    el.setAttribute("aria-label", WIDE_LABEL);
  } else if (el.getAttribute("aria-label") === WIDE_LABEL) {
    el.removeAttribute("tabindex");
    el.removeAttribute("role");
    el.removeAttribute("aria-label");
  }
}

/** Open collapsed steps for printing, and close them again afterwards. */
export function printReady() {
  // beforeprint may fire more than once before afterprint (a print preview, then the print)
  const opened = new Set();
  window.addEventListener("beforeprint", () => {
    for (const d of document.querySelectorAll("details:not([open])")) { d.open = true; opened.add(d); }
  });
  window.addEventListener("afterprint", () => {
    for (const d of opened) d.open = false;
    opened.clear();
  });
}

/** Typeset as soon as KaTeX has loaded (it is deferred; module scripts may run first). */
export function whenTypeset(root = document) {
  const go = () => { document.body.dataset.katexErrors = String(typeset(root)); };
  if (window.katex) go();
  else if (document.readyState === "complete") go();
  else window.addEventListener("load", go, { once: true });
}

/** Fold the bookkeeping steps of each derivation under root behind one toggle. */
export function foldSteps(root = document) {
  for (const list of root.querySelectorAll("ol.steps")) {
    const hidden = list.querySelectorAll("li.step.bookkeeping").length;
    if (!hidden || list.dataset.folded) continue;
    list.dataset.folded = "true";
    const total = list.querySelectorAll("li.step").length;
    const button = Object.assign(document.createElement("button"), { type: "button", className: "all-steps" });
    const show = (all) => {
      list.classList.toggle("core-only", !all);
      button.setAttribute("aria-expanded", String(all));
      button.textContent = all ? `Show the core steps only` : `Show all ${total} steps (${hidden} more: positions, velocities, derivatives, …)`;
    };
    button.addEventListener("click", () => show(list.classList.contains("core-only")));
    list.before(button);
    show(false);
  }
}
