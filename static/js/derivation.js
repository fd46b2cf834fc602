/**
 * derivation.js — typeset and render derivations with KaTeX (loaded by base.html).
 *
 *   typeset(root)                 render every .math element under root (its text
 *                                 is the LaTeX; .math-display for display math); prose
 *                                 with $…$ inside .prose-math elements goes through
 *                                 KaTeX's auto-render.  Returns the number of errors.
 *   renderDerivation(el, doc)     build the steps and the summary of a derivation
 *                                 JSON (GET /api/scenes/{id}/derivation, or a user
 *                                 system's) into el, with the same markup the server
 *                                 renders for scene pages, then typeset it.
 *   printReady()                  open every collapsed step while printing.
 *   whenTypeset(root)             typeset once KaTeX's deferred script has run, and record
 *                                 the error count in document.body.dataset.katexErrors.
 *   foldSteps(root)               show the core steps (li.step without .bookkeeping) and put
 *                                 the others behind one "all steps" toggle button.
 *
 * KaTeX errors never throw: a bad formula shows as a .katex-error element, which
 * the browser tests look for.
 */

const LONG_STEP = 320; // characters of LaTeX beyond which a step's math starts collapsed

export function typeset(root = document) {
  const katex = window.katex;
  if (!katex) return 0;
  for (const el of root.querySelectorAll(".math")) {
    if (el.dataset.typeset === "1") continue;
    // the server sends MathML (readable without JavaScript) with the TeX in data-tex
    const tex = el.dataset.tex ?? el.textContent;
    el.setAttribute("data-tex", tex);
    katex.render(tex, el, { displayMode: el.classList.contains("math-display"), throwOnError: false });
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
  const again = (el) => { fitOrScroll(el); if (document.fonts) document.fonts.ready.then(() => fitOrScroll(el)); };
  widths ??= new ResizeObserver((entries) => { for (const e of entries) again(e.target); });
  const boxes = [...root.querySelectorAll(".math-display")];
  for (const el of boxes) widths.observe(el);
  // KaTeX's fonts widen a formula without resizing its box: decide again once they are in
  if (document.fonts) document.fonts.ready.then(() => boxes.forEach(fitOrScroll));
}

function fitOrScroll(el) {
  if (el.offsetParent === null) return; // hidden: decided when it shows
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

function h(tag, attrs = {}, ...children) {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === "class") el.className = v;
    else if (k === "text") el.textContent = v;
    else el.setAttribute(k, v);
  }
  for (const c of children) if (c) el.append(c);
  return el;
}

export function math(tex, display = false) {
  return h(display ? "div" : "span", { class: display ? "math math-display" : "math", text: tex });
}

function stepItem(step, number) {
  const li = h("li", { class: "step", id: `step-${number}` });
  li.append(h("h3", { class: "step-title", text: step.title }));
  li.append(h("p", { class: "explanation", text: step.explanation }));
  if (step.latex.length > LONG_STEP) {
    const details = h("details", { class: "long-step" });
    details.append(h("summary", { text: `Show the full expression (${step.latex.length} characters of LaTeX)` }));
    details.append(math(step.latex, true));
    li.append(details);
  } else {
    li.append(math(step.latex, true));
  }
  return li;
}

function listOf(items) {
  const ul = h("ul", { class: "math-list" });
  for (const tex of items) ul.append(h("li", {}, math(tex, true)));
  return ul;
}

/** A name as LaTeX, from the document's symbol table (the engine's one home of display names). */
export function texName(doc, name) {
  return (doc.symbols && doc.symbols[name] && doc.symbols[name].latex) || name;
}

/** The summary box of a derivation JSON, as a <section class="summary-box">. */
export function summaryBox(doc) {
  const box = h("section", { class: "summary-box", "aria-labelledby": "results-title" });
  box.append(h("h2", { id: "results-title", text: "Results" }));
  const dl = h("dl");
  const add = (term, ...content) => { dl.append(h("dt", { text: term })); dl.append(h("dd", {}, ...content)); };
  add("Equations of motion", listOf(doc.equations_of_motion.map((e) => e.latex)));
  // a large system keeps M⁻¹f factored (its closed form is listed in doc.skipped)
  add("Accelerations", listOf(Object.keys(doc.accelerations).length
    ? doc.coordinates.map((q) => `${texName(doc, q + "_ddot")} = ${doc.accelerations[q].latex}`)
    : ["\\ddot{q} = M^{-1} f"]));
  add("Generalized momenta", listOf(doc.coordinates.map((q) => `${texName(doc, "p_" + q)} = ${doc.momenta[q].latex}`)));
  // members of the document left out within their own time bounds, each with its reason (issue 35)
  if ((doc.skipped || []).length) add("Left out", h("ul", { class: "skipped" }, ...doc.skipped.map((s) => h("li", { text: s.reason }))));
  const conserved = h("ul", { class: "conserved" });
  for (const c of doc.conserved || []) {
    conserved.append(h("li", {}, math(`${c.latex_name || c.name} = ${c.latex}`, true), h("p", { class: "reason", text: c.reason })));
  }
  if (!(doc.conserved || []).length) conserved.append(h("li", { text: "Nothing is conserved in general." }));
  add("Conserved quantities", conserved);
  // true, false, or null when it cannot be decided (only L was given)
  const verdict = { true: "h = E.", false: "h ≠ E.", null: "Whether h = E cannot be decided." }[doc.hamiltonian_equals_energy];
  const hv = h("div", {}, h("p", { text: verdict }), h("p", { class: "reason", text: doc.hamiltonian_energy_reason }));
  if (doc.hamiltonian_conserved !== undefined) {
    hv.append(h("p", { text: doc.hamiltonian_conserved ? "h is conserved." : "h is not conserved." }),
      h("p", { class: "reason", text: doc.hamiltonian_conserved_reason }));
  }
  if (doc.hamiltonian_equals_energy === false && doc.energy_minus_hamiltonian) hv.append(math(`E - h = ${doc.energy_minus_hamiltonian.latex}`, true));
  add("Hamiltonian and energy", hv);
  box.append(dl);
  return box;
}

/** Render a derivation JSON's steps and summary into container; returns the KaTeX error count. */
export function renderDerivation(container, doc) {
  container.replaceChildren();
  const ol = h("ol", { class: "steps" });
  doc.steps.forEach((s, i) => ol.append(stepItem(s, i + 1)));
  container.append(h("section", { class: "derivation", "aria-labelledby": "derivation-title" },
    h("h2", { id: "derivation-title", text: "Derivation, step by step" }), ol));
  container.append(summaryBox(doc));
  return typeset(container);
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
