/**
 * statelink.js — a link that keeps what the reader is looking at, and opening it restores all of it.
 *
 *   viewLink()            the page's address (for the playground, its query holds the whole system) with the
 *                         view in the fragment: every control changed from its default (parameters, initial
 *                         conditions, duration, method, tolerance) by its name, then
 *                           at-time        the instant the animation shows (s)
 *                           open-panels    the plot panels unfolded on a phone and the <details> opened
 *                           practice       practice mode is on; practice-step: the step being worked on
 *   restoreControls(form) set the controls from the fragment; called before the first run, so that the run
 *                         is of the linked settings
 *   restoreView()         the rest, each once its part of the page exists: the instant after the first run
 *                         is drawn, the panels at once, the practice step once practice mode has built it
 *   bindViewLink()        the "Link to this view" button: "Link copied", or where copying is refused the link
 *                         selected in a field to copy by hand
 *   bindEmbedOffer()      the scene page's course-page frames (iframe code) with this site's address
 *
 * The fragment's own keys have a hyphen, which no declared name can have, so they never meet a control's
 * name; a fragment without "=" is an ordinary anchor (#outcome) and is left alone.
 */
import { setControl } from "./controls.js";

const TIME = "at-time";
const OPEN = "open-panels";
const PRACTICE = "practice";
const STEP = "practice-step";

function fragment() {
  const hash = window.location.hash.slice(1);
  return hash.includes("=") ? new URLSearchParams(hash) : new URLSearchParams();
}

const controlsForm = () => document.getElementById("controls");

// the practice step last worked on (the button that copies the link takes the focus from it)
let lastStep = null;
document.addEventListener("focusin", (event) => {
  const step = event.target?.closest?.(".practice-step");
  if (step) lastStep = step;
});

/** The view now, as fragment fields (URLSearchParams). */
function viewFields() {
  const fields = new URLSearchParams();
  const form = controlsForm();
  if (form) {
    for (const ctl of form.querySelectorAll(".control")) {
      const value = Number(ctl.querySelector('input[type="number"]')?.value ?? ctl.dataset.default);
      if (Number.isFinite(value) && value !== Number(ctl.dataset.default)) fields.set(ctl.dataset.name, String(value));
    }
    for (const select of form.querySelectorAll("select[data-default]")) {
      if (select.value !== select.dataset.default) fields.set(select.name, select.value);
    }
  }
  const scrub = document.querySelector("input.scrub");
  const dt = Number(scrub?.closest("[data-dt]")?.dataset.dt);
  if (scrub && dt > 0 && Number(scrub.value) > 0) {
    // the instant shown: the sample index times the samples' spacing
    fields.set(TIME, String(Number((Number(scrub.value) * dt).toPrecision(6))));
  }
  const open = [];
  for (const section of document.querySelectorAll(".panels > section.panel[id]")) {
    const button = section.querySelector(":scope > h3 > button.fold");
    if (button && button.getAttribute("aria-expanded") === "true") open.push(section.id);
  }
  for (const details of document.querySelectorAll("details[id][open]")) open.push(details.id);
  if (open.length) fields.set(OPEN, open.join(","));
  const practising = document.getElementById("practice-switch");
  if (practising?.checked) {
    fields.set(PRACTICE, "on");
    if (lastStep?.isConnected && lastStep.dataset.key) fields.set(STEP, lastStep.dataset.key);
  }
  return fields;
}

export function viewLink() {
  const url = new URL(window.location.href);
  const fields = viewFields();
  url.hash = [...fields.keys()].length ? fields.toString() : "";
  return url.toString();
}

export function restoreControls(form = controlsForm()) {
  const fields = fragment();
  if (!form) return;
  const ignored = []; // what the link asked for that this page cannot show, said in words
  for (const [name, value] of fields) {
    if (name.includes("-") || name === PRACTICE) continue;
    const select = form.querySelector(`select[name="${CSS.escape(name)}"]`);
    const ctl = form.querySelector(`.control[data-name="${CSS.escape(name)}"]`);
    if (select) {
      if ([...select.options].some((o) => o.value === value)) select.value = value;
      else ignored.push(`“${value}” is not a choice of ${select.labels?.[0]?.textContent || name}`);
    } else if (!ctl) {
      ignored.push(`“${name}” is not a setting of this page`);
    } else {
      // a value is shown only when it is a number inside the control's allowed range (the form would refuse it)
      const label = ctl.dataset.label || name;
      const x = Number(value);
      const [lo, hi] = [Number(ctl.dataset.min), Number(ctl.dataset.max)];
      const allowed = ctl.dataset.allowed || `${ctl.dataset.min} to ${ctl.dataset.max} ${ctl.dataset.unit || ""}`.trim();
      if (value.trim() === "" || !Number.isFinite(x)) ignored.push(`${label} = “${value}” is not a number`);
      else if (x < lo || x > hi) ignored.push(`${label} = ${value} is outside the allowed ${allowed}`);
      else setControl(form, name, x);
    }
  }
  showIgnored(form, ignored);
}

/** A note above the controls when the link asked for values the page could not take: the defaults are shown. */
function showIgnored(form, ignored) {
  form.querySelector(".link-note")?.remove();
  if (!ignored.length) return;
  const note = document.createElement("p");
  note.className = "link-note";
  note.setAttribute("role", "status");
  note.textContent = `This link was cut or changed: ${ignored.join("; ")}. The page shows the default value instead; check the link you were given.`;
  form.prepend(note);
}

/** Resolves once selector matches under the document (at once if it does already). */
function whenPresent(selector) {
  const found = document.querySelector(selector);
  if (found) return Promise.resolve(found);
  return new Promise((resolve) => {
    const watch = new MutationObserver(() => {
      const node = document.querySelector(selector);
      if (node) { watch.disconnect(); resolve(node); }
    });
    watch.observe(document.body, { childList: true, subtree: true });
  });
}

function restoreTime(seconds) {
  const go = () => {
    const scrub = document.querySelector("input.scrub");
    const dt = Number(scrub?.closest("[data-dt]")?.dataset.dt);
    if (!scrub || !(dt > 0)) return;
    // the sample nearest that instant (the last one if the run ends before it); an input event pauses the
    // player and shows it
    scrub.value = String(Math.min(Number(scrub.max), Math.round(seconds / dt)));
    scrub.dispatchEvent(new Event("input", { bubbles: true }));
  };
  const onPainted = (event) => {
    if (event.detail?.source !== "server") return;
    document.removeEventListener("lagrange:painted", onPainted);
    requestAnimationFrame(go);
  };
  document.addEventListener("lagrange:painted", onPainted);
}

export function restoreView() {
  const fields = fragment();
  const seconds = Number(fields.get(TIME));
  if (fields.has(TIME) && Number.isFinite(seconds) && seconds > 0) restoreTime(seconds);
  for (const id of (fields.get(OPEN) || "").split(",").filter(Boolean)) {
    const node = document.getElementById(id);
    if (node instanceof HTMLDetailsElement) node.open = true;
    const button = node?.querySelector?.(":scope > h3 > button.fold");
    if (button && button.getAttribute("aria-expanded") !== "true") button.click();
  }
  const practising = document.getElementById("practice-switch");
  if (fields.get(PRACTICE) === "on" && practising) {
    if (!practising.checked) practising.click();
    const key = fields.get(STEP);
    if (key) {
      whenPresent(`.practice-step[data-key="${CSS.escape(key)}"]`).then((step) => {
        step.scrollIntoView({ block: "center" });
        step.querySelector("input, textarea")?.focus({ preventScroll: true });
      });
    }
  }
}

export function bindViewLink() {
  const button = document.getElementById("view-link");
  const status = document.getElementById("view-link-status");
  if (!button || !status || button.dataset.bound) return;
  button.dataset.bound = "true";
  button.addEventListener("click", async () => {
    const link = viewLink();
    status.dataset.link = link;
    status.dataset.copied = "";
    // the link at once; then "Link copied" if the browser lets the page copy it, or, where it refuses (or
    // never answers), the link in a field, selected, to copy by hand.  The status is a live region: a screen
    // reader hears which.
    const shown = Object.assign(document.createElement("a"), { href: link, textContent: link });
    status.replaceChildren("Link to this view: ", shown);
    try {
      await Promise.race([
        navigator.clipboard.writeText(link),
        new Promise((_, fail) => setTimeout(() => fail(new Error("no answer")), 1500)),
      ]);
      status.dataset.copied = "yes";
      status.replaceChildren(Object.assign(document.createElement("strong"), { textContent: "Link copied" }), " to the clipboard: ", shown);
    } catch {
      status.dataset.copied = "no";
      const field = Object.assign(document.createElement("input"), {
        type: "text", readOnly: true, value: link, className: "view-link-field", id: "view-link-field",
      });
      const label = Object.assign(document.createElement("label"), { htmlFor: field.id, textContent: "The browser did not let the page copy it: copy this link by hand (it is selected)" });
      status.replaceChildren(label, field);
      field.focus();
      field.select();
    }
  });
}

/** The course-page frames the scene page offers (templates/_simulation.html): each code with this site's address. */
export function bindEmbedOffer() {
  for (const code of document.querySelectorAll("textarea.embed-code[data-src]")) {
    const src = new URL(code.dataset.src, window.location.origin).toString();
    const frame = Object.assign(document.createElement("iframe"), { src, title: code.dataset.title, width: "100%", height: code.dataset.height });
    code.value = frame.outerHTML;
    code.addEventListener("focus", () => code.select());
  }
}
