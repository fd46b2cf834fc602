/**
 * scrollboxes.js — boxes that scroll sideways (a long formula, a wide table) can be scrolled from the keyboard.
 *
 *   keyboardScroll(root = document)   watch root: every box whose content overflows it sideways gets
 *                                     tabindex="0", role="group" and a label ("Formula, scrolls sideways"),
 *                                     so Tab reaches it and the arrow keys scroll it; a box that stops
 *                                     overflowing (a wider window) loses them again
 *
 * Every such box also shows that it scrolls: data-more says on which sides content is hidden ("right",
 * "left", "left right"), kept up to date as the box scrolls, and site.css fades that edge and puts an
 * arrow there (a phone has no scroll bar to tell the reader).
 *
 * Checked after the page has loaded (KaTeX has typeset by then), when the window is resized, when a
 * <details> opens, when a hidden box is shown (practice's "Show this step": a box measured while hidden has no
 * width to overflow), and when elements are added under root (tables built from a server answer): at the
 * next frame, then at most twice a second while elements keep coming (readouts change every frame).
 */
const BOXES = ".math-display, .table-scroll, .summary-box dd, .data-summary .table, .frequencies, .practice-engine, "
  + ".practice-preview, .verdict-difference, .verdict-piece";

// what draws itself (Plotly's charts, a canvas): its subtree is never watched
const PLOTS = ".plot, .js-plotly-plot, svg, canvas";

function label(box) {
  if (box.matches(".math-display, .summary-box dd, .practice-preview, .verdict-difference, .verdict-piece")) {
    return "Formula, scrolls sideways";
  }
  const caption = box.querySelector("caption");
  return `${caption ? caption.textContent.trim() : "Table"}, scrolls sideways`;
}

/** Which sides of a box hide content: "left", "right", both, or "" (1 px of rounding allowed). */
function hidden(box) {
  const sides = [];
  if (box.scrollLeft > 1) sides.push("left");
  if (box.scrollLeft + box.clientWidth < box.scrollWidth - 1) sides.push("right");
  return sides.join(" ");
}

function mark(box) {
  const more = hidden(box);
  if (box.dataset.more !== more) box.dataset.more = more;
}

function check(root, watch = () => {}) {
  for (const box of root.querySelectorAll(BOXES)) {
    watch(box);
    const overflows = box.scrollWidth > box.clientWidth + 1;
    // a box holding something focusable is reached through it already
    const inner = box.querySelector("a[href], button, input, select, textarea, [tabindex]:not([data-scroll-box])");
    // the cue, whether or not the box is reached by the keyboard through something inside it
    if (overflows) {
      mark(box);
      if (!box.dataset.cue) { box.dataset.cue = "true"; box.addEventListener("scroll", () => mark(box), { passive: true }); }
    } else if (box.dataset.more) {
      delete box.dataset.more;
    }
    if (overflows && !inner) {
      if (!box.hasAttribute("tabindex")) {
        box.tabIndex = 0;
        box.dataset.scrollBox = "true";
        box.setAttribute("role", "group");
        box.setAttribute("aria-label", label(box));
      }
    } else if (box.dataset.scrollBox) {
      box.removeAttribute("tabindex");
      box.removeAttribute("role");
      box.removeAttribute("aria-label");
      delete box.dataset.scrollBox;
    }
  }
}

export function keyboardScroll(root = document) {
  let pending = false;
  const soon = () => {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => { pending = false; check(root, watch); });
  };
  // a formula whose own width changes (broken again across lines, typeset again, set in a web font once it
  // loads) is measured again: its box keeps its size, so nothing else says so, and a cue could stay on a formula
  // that now fits (the widths test's "a formula that fits shows no cue", seen now and then)
  const resized = typeof ResizeObserver === "function" ? new ResizeObserver(() => soon()) : null;
  const watched = new WeakSet();
  const watch = (box) => {
    const content = box.firstElementChild;
    if (!resized || !content || watched.has(content)) return;
    watched.add(content);
    resized.observe(content);
  };
  if (document.readyState === "complete") soon(); else window.addEventListener("load", soon, { once: true });
  window.addEventListener("resize", soon);
  document.addEventListener("toggle", soon, true);
  // elements added: a check at the next frame (a table just built is a keyboard region at once), then at
  // most one more per half second however often elements come (readouts redrawn every frame)
  let timer = null;
  let again = false;
  const later = () => {
    if (timer !== null) { again = true; return; }
    soon();
    timer = setTimeout(() => { timer = null; if (again) { again = false; later(); } }, 500);
  };
  // a plot redraws its own SVG at every frame while it is dragged or played: nothing in it is a box, and a
  // check then would force a layout in the middle of Plotly's (it would cost the all-plots frame time)
  const inPlot = (node) => node.nodeType === 1 && node.closest(PLOTS) !== null;
  const added = (r) => !inPlot(r.target) && [...r.addedNodes].some((n) => n.nodeType === 1 && !n.matches(PLOTS));
  // an element shown (its hidden attribute removed): the boxes in it now have a width to measure
  const shown = (r) => r.type === "attributes" && !inPlot(r.target) && !r.target.hidden;
  new MutationObserver((records) => { if (records.some((r) => added(r) || shown(r))) later(); })
    .observe(root === document ? document.body : root, { childList: true, subtree: true, attributes: true, attributeFilter: ["hidden"] });
  // KaTeX may finish after load (fonts): look once more a little later, and whenever a web font finishes
  // loading (a formula measured in the fallback font is wider: its cue would stay on a formula that now fits)
  setTimeout(soon, 1500);
  document.fonts?.ready.then(soon);
  document.fonts?.addEventListener?.("loadingdone", soon);
  return soon;
}
