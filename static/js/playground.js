/**
 * playground.js — the entry module of /playground (templates/playground.html).
 *
 * The page arrives server-rendered: the form as typed, the derivation (or the
 * refusal, next to its field) and the simulation controls and panels.  This module
 *   - typesets the math (derivation.js) and prepares it for printing;
 *   - shows only the fields of the chosen form (L, T and U, or particles and U),
 *     adds rows to the parameter, particle and force tables, copies a link to the system;
 *   - moves focus to the field a refusal points at;
 *   - simulates the derived system through POST /api/simulate (the declared system with
 *     the controls' parameter values, plus initial, t_end, method, rtol, samples) and draws
 *     it with simulation.js's connectSimulation (the same live preview as a scene page);
 *     a 429/503 is retried (api.js fetchJSON), and the page's jobs go to the server one at a time (api.js inTurn).
 * Everything it needs is in the page: #scene-data (the client JSON of app/viz/page_model.py)
 * and #playground-system (the request the page derived).
 *
 * The derivation comes in two stages: when the whole document is not ready, the page
 * arrives with the equations and accelerations in #derived[data-stage="equations"] and a "still
 * working on" line; this module asks for the same address with stage=whole and puts its #derived
 * (steps, results, simulation, skipped notes) in place, or shows its refusal at the field it
 * concerns.  The form is never touched: whatever the reader typed meanwhile stays.
 */
import { foldSteps, printReady, whenTypeset } from "./derivation.js";
import { fetchJSON, fetchRetrying, inTurn } from "./api.js";
import { connectSimulation } from "./simulation.js";
import { bindViewLink, restoreControls, restoreView } from "./statelink.js";
import { keyboardScroll } from "./scrollboxes.js";

foldSteps(document);
printReady();
whenTypeset(document);
keyboardScroll(document);

// ---- the system form -----------------------------------------------------------------------

const systemForm = document.getElementById("system-form");

function showKind() {
  const kind = systemForm.querySelector('input[name="form"]:checked')?.value || "energies";
  for (const block of systemForm.querySelectorAll("[data-kind]")) {
    block.hidden = !block.dataset.kind.split(" ").includes(kind);
  }
}

function addRow(tableId) {
  const body = document.getElementById(tableId).tBodies[0];
  const last = body.rows[body.rows.length - 1];
  const row = last.cloneNode(true);
  const index = body.rows.length;
  for (const input of row.querySelectorAll("input")) {
    input.value = "";
    input.placeholder = "";
    input.removeAttribute("aria-invalid");
    input.removeAttribute("aria-describedby");
    input.id = input.id.replace(/-\d+-/, `-${index}-`);
  }
  for (const note of row.querySelectorAll(".field-error")) note.remove();
  body.appendChild(row);
  row.querySelector("input")?.focus();
}

if (systemForm) {
  for (const radio of systemForm.querySelectorAll('input[name="form"]')) radio.addEventListener("change", showKind);
  showKind();
  for (const button of systemForm.querySelectorAll('[data-action="add-row"]')) {
    button.addEventListener("click", () => addRow(button.dataset.target));
  }
  // empty rows would only lengthen the shareable address
  systemForm.addEventListener("submit", () => {
    for (const row of systemForm.querySelectorAll("tr.row")) {
      const inputs = [...row.querySelectorAll("input")];
      if (inputs.every((i) => !i.value.trim())) inputs.forEach((i) => { i.disabled = true; });
    }
    for (const block of systemForm.querySelectorAll("[data-kind][hidden]")) {
      block.querySelectorAll("input, textarea").forEach((i) => { i.disabled = true; });
    }
  });
  const copy = systemForm.querySelector('[data-action="copy-link"]');
  copy?.addEventListener("click", async () => {
    const status = document.getElementById("copy-status");
    try {
      await navigator.clipboard.writeText(window.location.href);
      status.textContent = "Link copied.";
    } catch {
      status.textContent = `Link: ${window.location.href}`;
    }
  });
  const invalid = systemForm.querySelector('[aria-invalid="true"]');
  if (invalid) {
    const kindBlock = invalid.closest("[data-kind]");
    if (kindBlock && kindBlock.hidden) kindBlock.hidden = false;
    invalid.focus();
  }
}

// ---- the simulation ------------------------------------------------------------------------

let root = document.getElementById("simulation");
const system = JSON.parse(document.getElementById("playground-system").textContent || "{}");

function body(request) {
  // the declared system, with the parameter values the controls now hold
  const parameters = (system.parameters || []).map((p) => ({
    ...p, value: request.parameters[p.name] ?? p.value,
  }));
  const { initial, t_end, method, rtol, samples } = request;
  // series rounded to what a plot shows; stats stay exact
  return { ...system, parameters, initial, t_end, method, rtol, samples, precision: "display" };
}

function post(request, signal) {
  // in the session's turn, after the derivation being fetched: the server would answer it 429 meanwhile
  return inTurn(() => fetchJSON(root.dataset.simulateUrl, { body: body(request), signal }));
}

function connect() {
  root = document.getElementById("simulation");
  const dataNode = document.getElementById("scene-data");
  if (!root || !dataNode) return;
  // a link to a view of this system: its settings before the first run, the rest after
  restoreControls(document.getElementById("controls"));
  connectSimulation({
    form: document.getElementById("controls"),
    root,
    data: JSON.parse(dataNode.textContent),
    status: document.getElementById("run-status"),
    fetchRun: post,
    serial: true,
    urls: {
      // the modes are the declared system's (its parameter values); a section is at the run's values.
      // One at a time: the worker pool runs one job per session.
      modes: () => inTurn(() => fetchJSON(root.dataset.modesUrl, { body: system })),
      modesFollow: false,
      poincare: ({ parameters, initial }) => inTurn(() =>
        fetchJSON(root.dataset.poincareUrl, { body: { ...system, parameters: body({ parameters }).parameters, initial } })),
    },
  });
  restoreView();
  bindViewLink();
}

// ---- the derivation, in stages -------------------------------------------------------------

const derived = document.getElementById("derived");

/** Run the module scripts of a fragment put in with innerHTML (the browser runs none of those). */
function runScripts(container) {
  for (const old of container.querySelectorAll('script[type="module"][src]')) {
    const script = document.createElement("script");
    script.type = "module";
    script.src = old.src;
    old.replaceWith(script);
  }
}

/** Show a refusal of the whole derivation as the server renders it: the box above the form and the note at its field. */
function showRefusal(page, status) {
  const box = page.getElementById("form-error");
  const progress = document.getElementById("derive-progress");
  if (!box) {
    progress.textContent = `The rest of the derivation could not be fetched (the server answered ${status}); reload the page to try again.`;
    return;
  }
  document.getElementById("form-error")?.remove();
  systemForm.before(document.importNode(box, true));
  const invalid = page.querySelector('[aria-invalid="true"]');
  const field = invalid && document.getElementById(invalid.id);
  const note = invalid && page.getElementById(`${invalid.id}-error`);
  if (field && note && !document.getElementById(note.id)) {
    field.setAttribute("aria-invalid", "true");
    field.setAttribute("aria-describedby", note.id);
    field.insertAdjacentElement("afterend", document.importNode(note, true));
    const kindBlock = field.closest("[data-kind]");
    if (kindBlock && kindBlock.hidden) kindBlock.hidden = false;
  }
  progress.textContent = "The rest of the derivation was refused: the reason is shown above the form, at the field it concerns.";
  progress.setAttribute("role", "alert");
}

/** The same address with stage=whole: the whole derivation, or its refusal, as a page. */
async function fetchWhole() {
  const url = derived.dataset.wholeUrl.split("#")[0];
  // in the session's turn: the practice steps, modes and sections asked for meanwhile follow it, not race it
  const res = await inTurn(() => fetchRetrying(url, { headers: { Accept: "text/html" } }, { tries: 9 }));
  return { status: res.status, page: new DOMParser().parseFromString(await res.text(), "text/html") };
}

/** While the rest is worked out: which part the server is on and for how long, each second, with a button that
 *  stops it (app/web/api/staged.py).  Returns what ends the watch, and whether the reader stopped it. */
function watchProgress() {
  const line = document.getElementById("derive-now");
  const part = document.getElementById("derive-part");
  const stop = document.getElementById("derive-cancel");
  const state = { stopped: false, timer: null, ended: false };
  if (!line || !derived.dataset.progressUrl) return { end() {}, state };
  const seconds = (x) => `${Math.round(x)} s`;
  async function poll() {
    try {
      const now = await fetchJSON(derived.dataset.progressUrl);
      // an answer that arrives after the watch ended (the derivation finished or was stopped) shows nothing
      if (state.ended) return;
      if (now.running) {
        part.textContent = `Now: ${now.part} (for ${seconds(now.part_seconds)}; ${seconds(now.seconds)} in all).`;
        line.hidden = false;
      }
    } catch { /* the next second asks again */ }
    if (!state.ended) state.timer = setTimeout(poll, 1000);
  }
  stop.addEventListener("click", async () => {
    stop.disabled = true;
    state.stopped = true;
    try {
      await fetchJSON(derived.dataset.cancelUrl, { body: {} });
    } catch (err) {
      state.stopped = false;
      stop.disabled = false;
      part.textContent = `It could not be stopped: ${err.message}`;
    }
  });
  state.timer = setTimeout(poll, 1000);
  return { end() { state.ended = true; clearTimeout(state.timer); line.hidden = true; }, state };
}

async function fillIn() {
  let answer;
  const watch = watchProgress();
  try {
    answer = await fetchWhole();
  } catch {
    watch.end();
    document.getElementById("derive-progress").textContent =
      "The rest of the derivation could not be fetched (the connection failed); reload the page to try again.";
    return;
  }
  watch.end();
  const next = answer.page.getElementById("derived");
  if (watch.state.stopped && answer.status !== 200) {
    const progress = document.getElementById("derive-progress");
    progress.textContent = "Stopped, as you asked: the equations above stay. Press Derive to work out the rest.";
    derived.dataset.stage = "stopped";
    return;
  }
  if (answer.status !== 200 || !next) {
    showRefusal(answer.page, answer.status);
    return;
  }
  const left = next.querySelectorAll(".skipped li").length;
  derived.replaceWith(next);
  runScripts(next);
  // a line in place of "still working on": what was left out is listed under Results, each with its reason
  const done = Object.assign(document.createElement("p"), {
    id: "derive-progress", className: "derive-progress",
    textContent: "The rest of the derivation is below." + (left ? ` ${left === 1 ? "One part was" : `${left} parts were`} left out; `
      + "the reason for each is under Results, “Left out”." : ""),
  });
  done.setAttribute("role", "status");
  next.prepend(done);
  foldSteps(next);
  whenTypeset(next);
  connect();
}

if (derived?.dataset.stage === "equations") fillIn();
else connect();
