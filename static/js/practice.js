/**
 * practice.js — "Try it yourself" on scene pages and in the playground (templates/_practice.html).
 *
 * With the switch on, the page's derivation and results are hidden (body.practising) and a box
 * per step takes the student's own expression, in the chapter's order. As they type, the
 * expression is typeset live by the checker's own parser (POST /api/typeset, 150 ms after the
 * last keystroke: the LaTeX as the checker reads it, or the parser's refusal in the checker's
 * words, the last good rendering kept while the server answers); the browser has no expression grammar of its
 * own. Enter or "Check" sends it to the checker and shows the verdict, the
 * hint; a named mistake in the student's own terms, what else is right, and a follow-up question answered in
 * place; "Show this step" reveals the engine's step, and under it how the last answer checked differs from it.
 *
 * What the student typed, the verdicts and the switch are kept in localStorage, one record per
 * scene and per declared system, so a reload loses nothing. A link with ?practice opens the
 * page in practice mode; on a scene page it also carries the simulation's parameter values
 * (?practice&m=2&R=0.5), which are set on the controls before the first run.
 */
import { answerBox, fit } from "./answer-box.js";
import { RequestError, fetchJSON, inTurn } from "./api.js";
import { readRequest, setControl } from "./controls.js";
import { setMathProse } from "./prose.js";
import { correctPartWords, endOf, howTo, namesSaid, numbered, refusalWords, verdictWords, wordsOf } from "./verdict-words.js";

const root = document.getElementById("practice");
const query = new URLSearchParams(window.location.search);
const sceneId = root?.dataset.scene || "";
const systemNode = document.getElementById("playground-system");
const system = sceneId ? null : JSON.parse(systemNode?.textContent || "{}");
const controls = document.getElementById("controls");

// ---- storage ------------------------------------------------------------------------------------

function storageKey() {
  if (sceneId) return `lagrange-practice:scene:${sceneId}`;
  // a declared system is keyed on its declaration, so each system keeps its own answers
  const text = JSON.stringify(system);
  let hash = 5381;
  for (let k = 0; k < text.length; k++) hash = ((hash * 33) ^ text.charCodeAt(k)) >>> 0;
  return `lagrange-practice:system:${hash.toString(36)}`;
}

const KEY = storageKey();

function load() {
  try {
    return JSON.parse(window.localStorage.getItem(KEY) || "{}") || {};
  } catch {
    return {};
  }
}

function save(record) {
  try {
    window.localStorage.setItem(KEY, JSON.stringify(record));
  } catch {
    /* storage full or disabled: practice still works, it just is not kept */
  }
}

const record = Object.assign({ on: false, answers: {}, verdicts: {} }, load());

// ---- the page -----------------------------------------------------------------------------------

/** The API's answer {ok, status, answer}: a refusal's JSON is an answer too (its message is shown in place). */
async function request(url, body, signal, onWait) {
  try {
    return { ok: true, status: 200, answer: await fetchJSON(url, { body, signal, onWait }) };
  } catch (error) {
    if (!(error instanceof RequestError)) throw error;
    return { ok: false, status: error.status, answer: error.answer };
  }
}

// The session runs one job at a time on the server: the page's typesetting and checking wait their turn in the
// page's one queue (api.js inTurn, shared with the playground's derivation) rather than be told to wait there.

function katexInto(el, latex, display = false) {
  if (window.katex) window.katex.render(latex, el, { displayMode: display, throwOnError: false });
  else el.textContent = latex;
}

/** A formula of the student's length (the preview, a difference, a piece), typeset as a display is but
 * breaking across lines after its top-level signs (= + −), as a textbook breaks a long line: on a phone none of
 * it is cut at the screen's edge. (KaTeX breaks lines only in its inline mode.) */
function katexBreaking(el, latex) {
  katexInto(el, `\\displaystyle ${latex}`);
  el.classList.add("math-breaking");
  // a sum inside sized parentheses (\left( … \right)) is one unbreakable group: where the formula is still
  // wider than its box (a double pendulum's T on a phone), its parentheses are set at text size, which lets
  // KaTeX break after the signs inside them too, so the whole answer can be read without scrolling sideways
  if (el.scrollWidth > el.clientWidth + 1 && /\\left[([]/.test(latex)) {
    katexInto(el, `\\displaystyle ${unsized(latex)}`);
  }
}

/** LaTeX with its sized delimiters written plain: \left( a + b \right) → ( a + b ). */
function unsized(latex) {
  return latex.replace(/\\left\s*([([.])/g, (_, d) => (d === "." ? "" : d)).replace(/\\right\s*([)\].])/g, (_, d) => (d === "." ? "" : d));
}

function keyOf(exercise) {
  return exercise.coordinate ? `${exercise.step}:${exercise.coordinate}` : exercise.step;
}

function element(tag, attrs = {}, text = "") {
  const el = document.createElement(tag);
  for (const [name, value] of Object.entries(attrs)) el.setAttribute(name, value);
  if (text) el.textContent = text;
  return el;
}

/** A verdict's words: the formulas they quote typeset, the rest with its subscripts set (prose.js). */
function wordsEl(tag, attrs, text, formulas) {
  return setMathProse(element(tag, attrs), text, formulas);
}

function showVerdict(item, result, answer) {
  const box = item.querySelector(".practice-verdict");
  box.replaceChildren();
  box.classList.remove("verdict-stale");
  box.dataset.verdict = result.verdict || "refused";
  if (result.verdict) {
    // the message opens with the verdict ("Correct: …"): that word in bold (the words: verdict-words.js, as on a
    // class page)
    const words = verdictWords(result);
    const head = element("p", { class: "verdict-head" });
    const formulas = result.formulas || [];
    head.append(element("strong", {}, words.head[0]), wordsEl("span", {}, words.head[1], formulas));
    box.append(head);
    if (result.mistake) box.append(mistakeBox(result.mistake, words.mistake, formulas));
    if (words.reason) box.append(wordsEl("p", { class: "verdict-hint" }, words.reason, formulas));
    if (words.partial) box.append(wordsEl("p", { class: "verdict-partial" }, words.partial, formulas));
    const correct = correctPartWords(result);
    if (correct) box.append(correctBox(correct));
    if (result.follow_up && result.verdict === "incorrect") box.append(followUpBox(item, result.follow_up, formulas));
  } else {
    // a refusal: say what was wrong and mark the offending part of what was typed
    const head = element("p", { class: "verdict-head" });
    // said once: the preview's note of the same text gives way to this
    // a busy server (503, or the session's own job under way: 429) is not a refusal of the answer
    const [label, said] = refusalWords(result.status, result.detail);
    head.append(element("strong", {}, label), said);
    const note = item.querySelector(".practice-preview-note");
    if (note) note.textContent = "";
    box.append(head);
    if (Number.isInteger(result.start) && Number.isInteger(result.end) && result.end <= answer.length) {
      const typed = element("code", { class: "typed", "aria-label": "What you typed, with the offending part marked" });
      typed.append(answer.slice(0, result.start), element("mark", {}, answer.slice(result.start, result.end)), answer.slice(result.end));
      box.append(typed);
    }
  }
  showReveal(item, result.reveal);
  const input = item.querySelector(".answer-box");
  const stale = record.verdicts[item.dataset.key]?.answer !== undefined && record.verdicts[item.dataset.key].answer !== input.value;
  if (stale) box.append(element("p", { class: "help" }, `(for your earlier answer: ${record.verdicts[item.dataset.key].answer})`));
  input.setAttribute("aria-invalid", result.verdict ? String(result.verdict === "incorrect") : "true");
}

/** What a wrong answer's verdict keeps back, since it would give the step away: the difference between the
 * answer and the correct one, and the correct piece the mistake is in. It goes under the derived step, seen only
 * once the student presses "Show this step". */
function showReveal(item, reveal) {
  const engine = item.querySelector(".practice-engine");
  engine.querySelector(".practice-reveal")?.remove();
  if (!reveal || (!reveal.difference && !reveal.piece)) return;
  const more = element("div", { class: "practice-reveal" });
  more.append(element("p", { class: "help" }, "Your last answer checked, against it:"));
  if (reveal.difference) {
    const diff = element("div", { class: "verdict-difference", "aria-label": `difference: ${reveal.difference.sympy}` });
    katexBreaking(diff, `\\text{yours} - \\text{correct} = ${reveal.difference.latex}`);
    more.append(diff);
  }
  if (reveal.piece) {
    const piece = element("div", { class: "verdict-piece", "aria-label": "the correct piece" });
    katexBreaking(piece, reveal.piece);
    more.append(piece);
  }
  engine.append(more);
}

/** A verdict shown for an answer since edited says so, until the new one is checked. */
function markStale(item, checkedAnswer) {
  const box = item.querySelector(".practice-verdict");
  const stale = Boolean(box.dataset.verdict) && checkedAnswer !== undefined && checkedAnswer.trim() !== item.querySelector(".answer-box").value.trim();
  box.classList.toggle("verdict-stale", stale);
  let line = box.querySelector(".verdict-stale-note");
  if (stale && !line) {
    line = element("p", { class: "verdict-stale-note" }, "This verdict is for your earlier answer: press Enter to check the new one.");
    box.prepend(line);
  } else if (!stale && line) {
    line.remove();
  }
}

/** The named mistake: its name, and the piece it speaks of typeset. */
function mistakeBox(mistake, [label, name], formulas = []) {
  const box = element("div", { class: "verdict-mistake", "data-key": mistake.key });
  const head = element("p");
  head.append(element("strong", {}, label), wordsEl("span", {}, name, formulas));
  box.append(head);
  // the piece, labelled by the server; none when it would only repeat the difference above
  if (mistake.latex) {
    const piece = element("div", { class: "verdict-piece", "aria-label": `the piece: ${mistake.name}` });
    katexBreaking(piece, mistake.latex);
    box.append(piece);
  }
  return box;
}

/** The correct part the named mistake points at, closed until the student opens it ("Show the correct
 * denominator"), typeset as the other formulas of a verdict are once it is open (its width known then). */
function correctBox(correct) {
  const box = element("details", { class: "verdict-correct" });
  box.append(element("summary", {}, correct.summary));
  const math = element("div", { class: "verdict-correct-math", "aria-label": correct.text });
  box.append(math);
  if (correct.note) box.append(element("p", { class: "help" }, correct.note));
  box.addEventListener("toggle", () => {
    if (box.open && !math.childElementCount) katexBreaking(math, correct.latex);
  });
  return box;
}

/** A follow-up question after a named mistake, answered and checked by the same checker (not a nested form:
 * Enter in its box or its button sends it). */
function followUpBox(item, followUp, formulas = []) {
  const id = `${item.querySelector(".answer-box").id}-follow`;
  const box = element("div", { class: "verdict-follow-up", "data-key": followUp.key });
  const label = wordsEl("label", { for: id }, followUp.question, formulas);
  const row = element("div", { class: "practice-row" });
  // (Enter in its box sends it: not a nested form)
  const input = answerBox({ id }, () => ask());
  const send = element("button", { type: "button" }, "Answer");
  const status = element("p", { class: "follow-up-verdict", role: "status", "aria-live": "polite" });
  row.append(input, send);
  // the reply typeset as it is typed, as every answer box's is
  const shown = element("div", { class: "practice-preview", id: `${id}-preview`, "aria-label": "Your reply, typeset" });
  const math = element("div", { class: "practice-preview-math" });
  const note = element("p", { class: "help practice-preview-note" }, "What you type appears here, typeset.");
  shown.append(math, note);
  input.setAttribute("aria-describedby", `${id}-preview`);
  let timer = null;
  let typing = new AbortController();
  input.addEventListener("input", () => {
    clearTimeout(timer);
    timer = setTimeout(() => {
      typing.abort();
      typing = new AbortController();
      typesetInto(input, math, note, followUp.kind || item.dataset.step, typing.signal, (latex) => latex);
    }, TYPESET_DELAY_MS);
  });
  // the names, folded to one line: the step's own list stands just above, and a wrong answer's verdict on a phone
  // grew two screens tall with it said again
  const names = element("details", { class: "help follow-up-names" });
  names.append(element("summary", {}, "Names you may use"), element("p", {}, `${namesSaid(followUp)}, pi.`));
  box.append(label, row, names, shown, status);
  const ask = async () => {
    const answer = input.value.trim();
    if (!answer) {
      status.textContent = "Type an expression first.";
      return;
    }
    send.disabled = true;
    status.textContent = "Checking…";
    const body = { step: item.dataset.step, follow_up: followUp.key, answer };
    if (item.dataset.coordinate) body.coordinate = item.dataset.coordinate;
    if (system) body.system = system;
    try {
      const { answer: result } = await inTurn(() => request(root.dataset.checkUrl, body));
      status.dataset.verdict = result?.verdict || "refused";
      // the reply's verdict, its formulas typeset (a right reply is echoed as it was typed: M (ẏ₁ + ẏ₂)²/8)
      if (result?.verdict) setMathProse(status, `${result.message}${result.hint ? ` ${result.hint}` : ""}`, result.formulas);
      else status.textContent = endOf(wordsOf(result?.detail) || "No answer from the server");
    } catch {
      status.textContent = "The server could not be reached; try again.";
    } finally {
      send.disabled = false;
    }
  };
  send.addEventListener("click", ask);
  return box;
}

// ---- panels that give away a step ---------------------------------------------------------------

// A panel's part marked data-gives-away="step …" (the constraint forces' formulas, a predicted ω) is folded
// while practising, behind a button naming the step it gives away, until that step is checked right or shown.
const giveaways = new Map(); // step -> its button, per panel

function unfold(step) {
  for (const el of document.querySelectorAll("[data-gives-away]")) {
    if (el.dataset.givesAway.split(" ").includes(step)) el.classList.add("unfolded");
  }
  for (const [button, steps] of giveaways) {
    if (steps.includes(step)) {
      button.remove();
      giveaways.delete(button);
    }
  }
}

function foldGiveaways(exercises) {
  const sections = new Set([...document.querySelectorAll("[data-gives-away]")].map((el) => el.closest("section") || el.parentElement));
  for (const section of sections) {
    const parts = [...section.querySelectorAll("[data-gives-away]")];
    const steps = [...new Set(parts.flatMap((el) => el.dataset.givesAway.split(" ")))];
    // the first step of the list it gives away (an acceleration before an equation it also hints at)
    const index = exercises.findIndex((e) => steps.includes(e.step));
    const what = index < 0 ? "gives away the answers" : `gives away step ${index + 1}: ${exercises[index].title}`;
    const button = element("button", { type: "button", class: "gives-away" }, `Show (${what})`);
    button.addEventListener("click", () => {
      for (const el of parts) el.classList.add("unfolded");
      button.remove();
      giveaways.delete(button);
    });
    (section.querySelector("h3") || section.querySelector("h2") || section).after(button);
    giveaways.set(button, index < 0 ? [] : [exercises[index].step]);
    // a step already checked right (kept from an earlier visit) unfolds what it gives away
    if (index >= 0 && ["correct", "equivalent"].includes(record.verdicts[keyOf(exercises[index])]?.result?.verdict)) unfold(exercises[index].step);
  }
}

// what the typesetter needs besides the text: the scene, or the declared system's names
const typesetContext = sceneId
  ? { scene: sceneId }
  : { coordinates: system?.coordinates || [], parameters: (system?.parameters || []).map((p) => (typeof p === "string" ? p : p.name)) };

/** Typeset the text of ``input`` into ``math`` (``frame`` puts the typeset answer in its display), or say in
 * ``note`` why it cannot be read; while the server answers, the last good rendering stays. Returns "read",
 * "refused", "empty", or null (no reply for this text). */
async function typesetInto(input, math, note, step, signal, frame, said = () => false, coordinate = null) {
  const text = input.value;
  if (!text.trim()) {
    math.replaceChildren();
    note.textContent = "What you type appears here, typeset.";
    return "empty";
  }
  let reply;
  try {
    reply = await inTurn(() => (signal.aborted ? null
      : request(root.dataset.typesetUrl, { text, step, ...typesetContext, ...(coordinate ? { coordinate } : {}) }, signal)));
  } catch {
    reply = null; // aborted by the next keystroke, or the server out of reach: the last rendering stays
  }
  // the preview belongs to the text in the box now: a reply for an earlier text (one typed on since, or sent
  // before a check of the whole answer) says nothing
  if (!reply || signal.aborted || input.value !== text) return null;
  if (reply.ok) {
    katexBreaking(math, frame(reply.answer.latex, reply.answer));
    note.textContent = "";
    return "read";
  }
  if (reply.status === 422) {
    // said once: when the check of this same text was refused, its verdict below says why
    note.textContent = said(text) ? "" : `Not read yet: ${endOf(wordsOf(reply.answer?.detail) || "the checker could not read this")}`;
    // the rendering of an earlier text would show something not typed: it goes
    math.replaceChildren();
    return "refused";
  }
  return null;
}

/** Typeset what is typed in a step's box, as the checker reads it. */
async function preview(item, signal) {
  const lhs = item.dataset.lhs;
  const step = item.dataset.step;
  // an equation typed lhs = rhs comes back whole
  const frame = (latex, answer) => (answer.equation ? answer.latex : step === "equation" ? `${latex} = 0` : `${lhs} = ${latex}`);
  const said = (text) => {
    const checked = record.verdicts[item.dataset.key];
    return Boolean(checked && checked.answer === text && !checked.result?.verdict);
  };
  const input = item.querySelector(".answer-box");
  const state = await typesetInto(input, item.querySelector(".practice-preview-math"), item.querySelector(".practice-preview-note"), step, signal, frame, said, item.dataset.coordinate || null);
  if (state === "empty") delete item.dataset.typeset;
  else if (state) item.dataset.typeset = state;
}

const TYPESET_DELAY_MS = 150; // after the last keystroke

/** ``folded``: a position's note said in full on an earlier box, folded here under "How to write a position"
 * (on a phone the same paragraph under every position box was screens of scrolling). */
function buildItem(exercise, index, folded = false) {
  const key = keyOf(exercise);
  const id = `practice-${index}`;
  const item = element("li", { class: "practice-step", "data-key": key, "data-step": exercise.step, "data-lhs": exercise.lhs });
  if (exercise.coordinate) item.dataset.coordinate = exercise.coordinate;
  const form = element("form", { class: "practice-form", novalidate: "" });
  // numbered as a panel that gives a step away names it ("Show (gives away step 6: Potential energy U)")
  const title = element("h3", { id: `${id}-title` });
  title.append(element("span", { class: "practice-number" }, `Step ${index + 1}:`), " ",
    element("span", { class: "practice-title" }, exercise.title));
  // the heading shows the title: the label says it to a screen reader only (18)
  const label = element("label", { for: `${id}-answer`, class: "visually-hidden" }, `Your answer: ${exercise.title}`);
  const row = element("div", { class: "practice-row" });
  const lhs = element("span", { class: "practice-lhs", "aria-hidden": "true" });
  katexInto(lhs, exercise.step === "equation" ? "" : `${exercise.lhs} =`);
  const input = answerBox({ id: `${id}-answer`, name: key, "aria-describedby": `${id}-names ${id}-preview` });
  input.value = record.answers[key] || "";
  requestAnimationFrame(() => fit(input));
  const rhs = element("span", { class: "practice-lhs", "aria-hidden": "true" });
  if (exercise.step === "equation") katexInto(rhs, "= 0");
  row.append(lhs, input, rhs);
  const names = element("p", { class: "help practice-names", id: `${id}-names` }, `${howTo(exercise, !folded)} Names you may use: ${namesSaid(exercise)}, pi.${numbered(exercise.names)}`);
  let how = null;
  if (folded && exercise.note) {
    how = element("details", { class: "help practice-how" });
    how.append(element("summary", {}, "How to write a position"), element("p", {}, exercise.note));
  }
  const previewBox = element("div", { class: "practice-preview", id: `${id}-preview`, "aria-label": "Your answer, typeset" });
  previewBox.append(element("div", { class: "practice-preview-math" }), element("p", { class: "help practice-preview-note" }));
  const actions = element("div", { class: "practice-actions" });
  const check = element("button", { type: "submit" }, "Check");
  const reveal = element("button", { type: "button", "aria-expanded": "false", "aria-controls": `${id}-engine` }, "Show this step");
  actions.append(check, reveal);
  const verdict = element("div", { class: "practice-verdict", role: "status", "aria-live": "polite", id: `${id}-verdict` });
  const engine = element("div", { class: "practice-engine", id: `${id}-engine`, hidden: "" });
  const engineMath = element("div", { class: "math-display" });
  katexInto(engineMath, exercise.answer.latex, true);
  engine.append(element("p", { class: "help" }, "The step, derived:"), engineMath);
  form.append(title, label, row, names, ...(how ? [how] : []), previewBox, actions, verdict, engine);
  item.append(form);

  let timer = null;
  let typing = new AbortController();
  const typeset = () => {
    typing.abort();
    typing = new AbortController();
    preview(item, typing.signal);
  };
  // "= 0" stands beside an equation's box only while the equation is typed as one expression
  // (and not under an empty box, where it would read as the only form taken)
  const sides = () => { rhs.hidden = exercise.step === "equation" && (input.value.includes("=") || !input.value.trim()); };
  sides();
  input.addEventListener("input", () => {
    sides();
    // a note on the text as it was (the parser's "Not read yet") is not about the text as it is now
    if (item.dataset.typeset === "refused") previewBox.querySelector(".practice-preview-note").textContent = "";
    markStale(item, record.verdicts[key]?.answer);
    record.answers[key] = input.value;
    save(record);
    showProgress(); // a right answer typed over no longer counts
    clearTimeout(timer);
    timer = setTimeout(typeset, TYPESET_DELAY_MS);
  });
  reveal.addEventListener("click", () => {
    const open = engine.hidden;
    engine.hidden = !open;
    if (open) unfold(exercise.step);
    reveal.setAttribute("aria-expanded", String(open));
    reveal.textContent = open ? "Hide this step" : "Show this step";
  });
  form.addEventListener("submit", async (event) => {
    event.preventDefault();
    const answer = input.value.trim();
    if (!answer) {
      showVerdict(item, { detail: "Type an expression first." }, "");
      input.focus();
      return;
    }
    // a second Enter (or click) while this answer is checked sends nothing
    if (item.dataset.checking) return;
    item.dataset.checking = "1";
    check.disabled = true;
    // the time so far, each second, so a slow check shows it is under way
    const started = Date.now();
    verdict.textContent = "Checking…";
    const ticking = setInterval(() => {
      verdict.textContent = `Checking… ${Math.round((Date.now() - started) / 1000)} s`;
    }, 1000);
    const body = { step: exercise.step, answer };
    if (exercise.coordinate) body.coordinate = exercise.coordinate;
    if (system) body.system = system;
    try {
      const { answer: result } = await inTurn(() => request(root.dataset.checkUrl, body));
      record.verdicts[key] = { answer: input.value, result: result || { detail: "No answer from the server." } };
      save(record);
      showVerdict(item, record.verdicts[key].result, input.value);
      if (["correct", "equivalent"].includes(result?.verdict)) unfold(exercise.step);
      showProgress();
    } catch {
      showVerdict(item, { detail: "The server could not be reached; try again." }, answer);
    } finally {
      clearInterval(ticking);
      delete item.dataset.checking;
      check.disabled = false;
    }
  });

  typeset();
  if (record.verdicts[key]) showVerdict(item, record.verdicts[key].result, record.verdicts[key].answer);
  if (record.verdicts[key]) markStale(item, record.verdicts[key].answer);
  return item;
}

// ---- progress ----------------------------------------------------------------------------------

let shownExercises = [];

/** How many steps are checked right (with the answer still as it was checked), and the end once all are. */
function showProgress() {
  const status = document.getElementById("practice-status");
  const total = shownExercises.length;
  if (!status || !total) return;
  const done = shownExercises.filter((exercise) => {
    const key = keyOf(exercise);
    const kept = record.verdicts[key];
    return kept && ["correct", "equivalent"].includes(kept.result?.verdict) && kept.answer === (record.answers[key] ?? kept.answer);
  }).length;
  status.dataset.done = String(done);
  if (done === 0) status.textContent = `${total} steps to derive, in the derivation's order.`;
  else if (done < total) status.textContent = `${done} of ${total} steps correct.`;
  else status.textContent = `All ${total} steps correct: you have done the whole derivation yourself.`;
  status.classList.toggle("practice-done", done === total);
}

async function loadSteps() {
  const status = document.getElementById("practice-status");
  const list = document.getElementById("practice-steps");
  // a busy server asks the page to come back later: say so, and when, rather than wait in silence
  const waiting = (seconds) => {
    status.textContent = `The server is busy; the steps are asked for again in ${seconds} s.`;
  };
  const { ok, answer } = await inTurn(() => request(root.dataset.practiceUrl, system || undefined, undefined, waiting));
  if (!ok) {
    status.textContent = `The steps could not be loaded: ${endOf(wordsOf(answer?.detail) || "no answer from the server")}`;
    return;
  }
  // a position's note in full on the first box that has one, folded on the others
  const first = answer.exercises.findIndex((exercise) => exercise.note);
  list.replaceChildren(...answer.exercises.map((exercise, index) => buildItem(exercise, index, index > first && Boolean(exercise.note))));
  foldGiveaways(answer.exercises);
  shownExercises = answer.exercises;
  showProgress();
}

let loaded = false;

function setPractising(on, remember = true) {
  document.body.classList.toggle("practising", on);
  document.getElementById("practice-switch").checked = on;
  document.getElementById("practice-body").hidden = !on;
  if (remember) {
    record.on = on;
    save(record);
  }
  if (on && !loaded) {
    loaded = true;
    loadSteps();
  }
}

function shareLink() {
  const url = new URL(window.location.href);
  url.searchParams.set("practice", "");
  if (sceneId && controls) {
    for (const [name, value] of Object.entries(readRequest(controls).parameters)) url.searchParams.set(name, String(value));
  } else if ([...url.searchParams.keys()].every((name) => name === "practice")) {
    // the playground's default system has no address of its own: put the declaration in the link
    url.searchParams.set("system", JSON.stringify(system));
  }
  return url.toString().replace("practice=&", "practice&").replace(/practice=$/, "practice");
}

if (root) {
  // parameters from a shared link are set before the first simulation runs
  if (sceneId && controls && query.has("practice")) {
    for (const [name, value] of query) {
      if (name !== "practice" && value.trim() !== "" && Number.isFinite(Number(value))) setControl(controls, name, Number(value));
    }
  }
  const start = () => {
    document.getElementById("practice-switch").addEventListener("change", (event) => setPractising(event.target.checked));
    document.getElementById("practice-link").addEventListener("click", async () => {
      const status = document.getElementById("practice-link-status");
      const link = shareLink();
      try {
        await navigator.clipboard.writeText(link);
        status.textContent = "Link copied.";
      } catch {
        status.textContent = `Link: ${link}`;
      }
    });
    if (query.has("practice") || record.on) setPractising(true, query.has("practice") ? true : false);
  };
  // KaTeX is loaded with defer, after this module: start once the document is ready
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
}
