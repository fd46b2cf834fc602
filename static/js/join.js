/**
 * join.js — a student's page (templates/join.html): join with the class code and a pseudonym, then
 * practise the assignment's steps. Each answer goes to POST /api/classes/{code}/check (practice
 * mode's checker; the verdict is recorded for the instructor) and the verdict, the difference
 * typeset and the hint come back as in practice mode. The student's own progress is counted from
 * the server's record. The class's assignments come in order, each with its title, due time and the
 * student's own progress on it; "Show this step" shows a step's answer and is recorded (a hint used,
 * in the gradebook). The student key stays in localStorage; a reload goes on where it was.
 */
import { answerBox } from "./answer-box.js";
import { api, el, exerciseOf, practiceOf, showPanes, stepTex, stored, typeset } from "./classroom.js";
import { setMathProse } from "./prose.js";
import { correctPartWords, howTo, numbered, refusalWords, verdictWords } from "./verdict-words.js";

const memory = stored("lagrange-join");
const scenes = JSON.parse(document.getElementById("class-scenes").textContent);
const titleOf = Object.fromEntries(scenes.map((s) => [s.id, s.title]));
const unitsOf = Object.fromEntries(scenes.map((s) => [s.id, s.units || {}]));
const $ = (id) => document.getElementById(id);
// a student's key that no longer opens its class: the class was deleted (by its instructor, or past its retention)
const CLOSED = "This class was closed by your instructor: its page and your answers in it are gone. To join another "
  + "class, type its code.";

let current = memory.get(); // {code, key, name, title, recovery}: recovery until "I have kept it" is pressed
let series = null; // the class's assignments, in order: {n, title, due, items}
// per step ("assignment|item|step|coordinate"), from the server's record: right (answered right at some time),
// counted (right on one's own by the due time: what the grade counts, reports.on_own), late, shown ("Show this step"
// pressed at any time), and the last answer with what it was answered
const record = new Map();
const recordOf = (key) => record.get(key) || {};
// the text being typed in each box, kept in this browser until it is checked: nothing typed is lost on a reload
const drafts = () => stored(`lagrange-join-drafts:${current.code}:${current.name}`);
// one check at a time from this page: an answer sent while another is being checked waits for it here, rather
// than being turned away by the server (one job per student) with "Busy"
let checking = Promise.resolve();

const stepId = (n, item, step, coordinate) => `${n}|${item}|${step}|${coordinate || ""}`;
const keysOf = (a) => a.items.flatMap((item) => item.steps.map((s) => stepId(a.n, item.scene || item.name, s.step, s.coordinate)));

/** A new attempt id (22 random URL-safe characters): the server records one answer per id, so a press of
 * Check sent twice (a retry after a lost answer) is judged and counted once. */
function attemptId() {
  const bytes = crypto.getRandomValues(new Uint8Array(16));
  return btoa(String.fromCharCode(...bytes)).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

function show() {
  showPanes("join-start", "join-live", current && { "joined-title": current.title, "joined-name": current.name });
}

/** Steps done as the grade counts them ("2 of 8 steps done", the dashboard's "done"), then the steps answered right
 *  that it does not count, by why: "· 1 right after it was shown · 1 right but late". */
function progressWords(steps) {
  const counted = steps.filter((s) => recordOf(s).counted).length;
  const shown = steps.filter((s) => recordOf(s).right && !recordOf(s).counted && !recordOf(s).late).length;
  const late = steps.filter((s) => recordOf(s).late).length;
  return [`${counted} of ${steps.length} steps done`,
    ...(shown ? [`${shown} right after it was shown`] : []), ...(late ? [`${late} right but late`] : [])].join(" · ");
}

function progress() {
  const steps = (series || []).flatMap(keysOf);
  $("joined-progress").textContent = steps.length ? progressWords(steps) : "";
  for (const a of series || []) {
    const mine = keysOf(a);
    const line = document.querySelector(`[data-assignment="${a.n}"] .join-assignment-progress`);
    if (line) line.textContent = progressWords(mine);
    const due = document.querySelector(`[data-assignment="${a.n}"] .join-assignment-due`);
    if (due) due.replaceChildren(...dueWords(a));
  }
}

const STEP_WORDS = {
  counted: "Done: this step is answered right.",
  shown: "Right — but this step was shown before you answered it, so it does not count as done for the grade.",
  late: "Right, but late: it is recorded after the due time and does not count toward the grade.",
  seen: "You were shown this step: an answer you type now is recorded, but it does not count as done for the grade.",
};

/** A step's card says where it stands, from the record: done (as the grade counts it), right but shown first,
 *  right but late, or shown and not answered right yet; the border is green only when done. */
function stepMark(form) {
  const mine = recordOf(form.dataset.key);
  const state = mine.counted ? "counted" : mine.late ? "late" : mine.right ? "shown" : mine.shown ? "seen" : null;
  const label = form.querySelector(".practice-done-label");
  label.hidden = !state;
  label.textContent = state ? STEP_WORDS[state] : "";
  label.dataset.state = state || "";
  form.classList.toggle("step-done", state === "counted");
  form.classList.toggle("step-right-uncounted", state === "shown" || state === "late");
}

/** An assignment's due time, and once it has passed, that an answer now is late and does not count. */
function dueWords(a) {
  if (!a.due) return [];
  const words = [`Due ${when(a.due)} · `];
  if (new Date(a.due) < new Date()) {
    words.push(el("strong", { className: "join-late", text: "past due" }),
      ": an answer now is recorded as late and does not count toward the grade · ");
  }
  return words;
}

/** A verdict in the words a scene page's practice mode uses for it (verdict-words.js): the same answer reads the
 *  same on both pages. */
function verdictView(box, r) {
  box.replaceChildren();
  box.setAttribute("aria-busy", "false");
  if (r.status === 200) {
    const v = r.data;
    box.dataset.verdict = v.verdict;
    const words = verdictWords(v);
    // the formulas the words quote typeset, the rest with its subscripts set, as on a scene page (prose.js)
    const said = (node, text) => setMathProse(node, text, v.formulas);
    box.append(el("p", {}, el("strong", { text: words.head[0] }), said(el("span"), words.head[1])));
    if (v.difference) box.append(el("p", { className: "verdict-difference" }, typeset(el("span"), v.difference.latex, true)));
    if (words.mistake) {
      const mistake = el("div", { className: "verdict-mistake", "data-key": v.mistake.key },
        el("p", {}, el("strong", { text: words.mistake[0] }), said(el("span"), words.mistake[1])));
      if (v.mistake.latex) mistake.append(typeset(el("div", { className: "verdict-piece" }), v.mistake.latex, true));
      box.append(mistake);
    }
    if (words.reason) box.append(said(el("p", { className: "verdict-hint" }), words.reason));
    if (words.partial) box.append(said(el("p", { className: "verdict-partial" }), words.partial));
    // the correct part the mistake points at, closed until asked for (as in practice mode)
    const correct = correctPartWords(v);
    if (correct) {
      const math = el("div", { className: "verdict-correct-math", "aria-label": correct.text });
      const part = el("details", { className: "verdict-correct" }, el("summary", { text: correct.summary }), math);
      if (correct.note) part.append(el("p", { className: "help", text: correct.note }));
      part.addEventListener("toggle", () => {
        if (part.open && !math.childElementCount) typeset(math, correct.latex, true);
      });
      box.append(part);
    }
    return;
  }
  box.dataset.verdict = "refused";
  // a busy server is no fault of the answer: said as what to do, never as the server's words about derivations
  const [label, said] = refusalWords(r.status, r.data?.detail || `the answer could not be checked (${r.status})`,
    "the server is still busy with your earlier work; press Check again in a moment (an answer is never counted twice).");
  box.append(el("p", {}, el("strong", { text: label }), said));
}

/** A message shown alone, as a sentence: its first letter a capital only when it opens with a word of the language
 *  (two or more small letters then a space), never a symbol the student typed (x, theta_dot); the one place a
 *  message of the server is capitalised on this page. */
function sentence(text) {
  return /^[a-z]{2,} /.test(text) ? `${text.charAt(0).toUpperCase()}${text.slice(1)}` : text;
}

/** The names a step's answer may use, each as typed and, where it prints otherwise, as the page prints it. */
function namesLine(practice, exercise, names) {
  // what the box takes, in the scene page's words ("Type only the right-hand side.")
  const line = el("p", { className: "practice-names help" }, `${howTo(exercise)} Names you may use: `);
  names.forEach((name, i) => {
    if (i) line.append(", ");
    line.append(el("code", { text: name }));
    const tex = practice?.symbols?.[name];
    if (tex && tex !== name) line.append(" (", typeset(el("span"), tex), ")");
  });
  line.append(", ", el("code", { text: "pi" }), `.${numbered(names)}`);
  return line;
}

/** Typeset ``input``'s text into ``preview`` 200 ms after the last keystroke (POST /api/typeset, the checker's
 *  parser), or say in ``note`` why it cannot be read yet; a reply for a text typed on since is dropped. */
function previewAsTyped(input, preview, note, item, s) {
  const names = item.scene ? { scene: item.scene }
    : { coordinates: item.system?.coordinates || [], parameters: (item.system?.parameters || []).map((p) => (typeof p === "string" ? p : p.name)) };
  let timer = null;
  input.addEventListener("input", () => {
    clearTimeout(timer);
    timer = setTimeout(async () => {
      const text = input.value;
      if (!text.trim()) { preview.replaceChildren(); note.textContent = "What you type appears here, typeset."; return; }
      const body = { text, step: s.step, ...names, ...(s.coordinate ? { coordinate: s.coordinate } : {}) };
      const r = await api("POST", "/api/typeset", { body }).catch(() => null);
      if (!r || input.value !== text) return;
      if (r.status === 200 && r.data?.latex) {
        preview.replaceChildren(typeset(el("div"), r.data.latex, true));
        note.textContent = "";
      } else if (r.status === 422) {
        preview.replaceChildren();
        const detail = String(r.data?.detail || "the checker cannot read this yet").replace(/^(answer|text): /, "");
        note.textContent = `Not read yet: ${detail}`;
      }
    }, 200);
  });
}

function stepView(a, item, practice, s, index) {
  const exercise = exerciseOf(practice, s.step, s.coordinate);
  const id = `answer-${index}`;
  const input = answerBox({ id, inputmode: "text" });
  const button = el("button", { type: "submit", text: "Check" });
  const reveal = el("button", { type: "button", className: "join-reveal", "aria-expanded": "false", text: "Show this step" });
  const shown = el("div", { className: "practice-engine", hidden: "" });
  const box = el("div", { className: "practice-verdict", role: "status", "aria-live": "polite" });
  // the answer typeset as it is typed, by the checker's own reading (as on a scene page in practice mode): a student
  // sees how ^, ' and a fraction were read before the answer is recorded
  const preview = el("div", { className: "practice-preview", id: `${id}-preview`, "aria-label": "Your answer, typeset" });
  const note = el("p", { className: "help practice-preview-note", text: "What you type appears here, typeset." });
  input.setAttribute("aria-describedby", `${id}-preview`);
  previewAsTyped(input, preview, note, item, s);
  // an equation is typed whole (lhs = rhs) or as one expression equal to zero: its box is labelled by its name
  const lhs = s.step === "equation" ? `${stepTex(practice, s.step, s.coordinate)}:` : `${stepTex(practice, s.step, s.coordinate)} =`;
  const form = el("form", { className: "practice-step", "data-step": s.step },
    el("h3", { text: exercise ? exercise.title : s.step }),
    el("label", { for: id }, typeset(el("span", { className: "practice-lhs" }), lhs)),
    el("div", { className: "practice-row" }, input, button, exercise ? reveal : null),
    exercise ? namesLine(practice, exercise, exercise.names) : null,
    preview, note, box, shown);
  const key = stepId(a.n, item.scene || item.name, s.step, s.coordinate);
  const target = { ...(item.scene ? { scene: item.scene } : { system: item.name }), step: s.step, assignment: a.n,
    ...(s.coordinate ? { coordinate: s.coordinate } : {}) };
  // the step's answer, shown on demand; the instructor's gradebook counts it as a hint used (recorded first)
  reveal.addEventListener("click", async () => {
    if (shown.hidden) {
      const r = await api("POST", `/api/classes/${current.code}/shown`, { key: current.key, body: target, tries: 3, patience: 5 });
      if (r.status !== 200) {
        verdictView(box, r);
        return;
      }
      // ω²'s answer names its equilibrium; its notes (stability, the other equilibria) are sentences that wrap
      shown.replaceChildren(el("p", { className: "help", text: "The step, derived:" }), typeset(el("div"), exercise.answer.latex, true),
        ...(exercise.answer.notes || []).map((note) => el("p", { className: "join-step-note", text: note })));
    }
    shown.hidden = !shown.hidden;
    reveal.setAttribute("aria-expanded", String(!shown.hidden));
    reveal.textContent = shown.hidden ? "Show this step" : "Hide this step";
    if (!recordOf(key).shown) await load(); // recorded as shown: the step's words and the count say so
  });
  // where the step stands, in words, not by the border's colour alone; from the record (stepMark)
  const doneLabel = el("p", { className: "practice-done-label" });
  form.insertBefore(doneLabel, form.querySelector(".practice-row"));
  form.dataset.key = key;
  // the page as the student left it: the text being typed (this browser), else the last answer and its verdict
  const mine = recordOf(key);
  const draft = drafts().get()?.[key];
  input.value = draft ?? mine.answer ?? "";
  if (mine.answered) verdictView(box, { status: mine.answered.status, data: mine.answered.body });
  // a text typed since the last check: the verdict kept below is said to be of that answer, not of this text
  if (mine.answered && draft != null && draft !== mine.answer) {
    box.prepend(el("p", { className: "help join-last-checked" }, "Your last answer checked, ", el("code", { text: mine.answer }), ":"));
  }
  if (input.value) input.dispatchEvent(new Event("input"));
  input.addEventListener("input", () => {
    const kept = drafts().get() || {};
    kept[key] = input.value;
    drafts().set(kept);
  });
  stepMark(form);
  let pending = null; // {answer, attempt}: a press of Check not yet answered; pressing again sends the same id
  form.addEventListener("submit", async (event) => {
    event.preventDefault();
    const answer = input.value.trim();
    if (!answer) {
      // nothing to check: the old verdict goes, and the box says what to do
      box.dataset.verdict = "empty";
      box.replaceChildren(el("p", { text: "Type an answer first." }));
      input.focus();
      return;
    }
    button.disabled = true;
    if (!pending || pending.answer !== answer) pending = { answer, attempt: attemptId() };
    const body = { ...target, answer, attempt: pending.attempt };
    try {
      delete box.dataset.verdict; // no verdict while it is being checked
      box.setAttribute("aria-busy", "true");
      box.replaceChildren(el("p", { text: "Checking your answer…" }));
      // after this page's previous check; the server may still ask to wait (a first derivation of a typed system
      // takes seconds): its Retry-After is followed, up to a quarter of a minute in all
      const turn = checking.then(() => api("POST", `/api/classes/${current.code}/check`, { key: current.key, body, tries: 6, patience: 5 }));
      checking = turn.catch(() => null);
      const r = await turn;
      verdictView(box, r);
      if (r.status !== 429 && r.status !== 503) pending = null; // answered: the next press is a new attempt
      if (r.status === 200 || r.status === 422) {
        // checked and recorded: the box's text is the record's last answer now, no longer a draft of this browser
        const kept = drafts().get() || {};
        if (kept[key] === input.value) delete kept[key];
        drafts().set(kept);
      }
      // where the step stands now (done, right after it was shown, late) is the record's word, as the grade's
      if (r.status === 200) await load();
      if (r.status === 403) leave(CLOSED);
    } catch {
      verdictView(box, { status: 0, data: { detail: "the server cannot be reached; press Check again (an answer is never counted twice)." } });
    } finally {
      button.disabled = false;
    }
  });
  return form;
}

const when = (iso) => new Date(iso).toLocaleString([], { dateStyle: "medium", timeStyle: "short" });

/** A typed system's set-up, above its boxes: the instructor's words (its coordinates, from where, the zero of U),
 *  then what the system is defined by, typeset (the server leaves out what a step asks for). */
function setupView(item) {
  const box = el("div", { className: "join-setup" });
  if (item.setup) {
    box.append(el("h4", { text: "The set-up" }),
      ...item.setup.split(/\n+/).map((line) => el("p", { text: line })));
  }
  const given = item.given || [];
  if (given.length) {
    box.append(el("p", { className: "help", text: "The system:" }),
      el("ul", { className: "join-given" }, ...given.map((g) => el("li", {},
        g.label ? el("span", { text: `${g.label}: ` }) : "", typeset(el("span"), g.latex)))));
  }
  return box;
}

/** The values the instructor set, each letter as the page prints it and, for a scene, with its unit:
 *  "Take m₁ = 2 kg, l₂ = 0.5 m." (a typed system's parameters carry no unit). */
function valuesView(item, symbols) {
  const values = Object.entries(item.parameters || {});
  if (!values.length) return [];
  const units = (item.scene && unitsOf[item.scene]) || {};
  const tex = values.map(([k, v]) => `${symbols[k] || k} = ${v}${units[k] || ""}`).join(",\\quad ");
  return [el("p", { className: "help join-values" }, "Take ", typeset(el("span"), tex), ".")];
}

async function drawItems() {
  const holder = $("join-items");
  const parts = [];
  let index = 0;
  for (const a of series) {
    const part = el("section", { className: "join-assignment", "data-assignment": a.n },
      el("h2", { className: "join-assignment-title", text: `${a.n}. ${a.title}` }),
      el("p", { className: "help" }, el("span", { className: "join-assignment-due" }, ...dueWords(a)),
        el("span", { className: "join-assignment-progress" })));
    for (const item of a.items) {
      const section = el("section", { className: "class-panel join-item" });
      const heading = item.scene ? titleOf[item.scene] || item.scene : item.name;
      section.append(el("h3", { text: heading }));
      // the page in practice mode, in a tab of its own: the set-up and the figure, the derivation hidden (
      // the plain page printed every answer of the assignment), and the class page stays where it was
      if (item.scene) section.append(el("p", {}, el("a", { href: `/scenes/${item.scene}#practice=on`, target: "_blank", rel: "noopener", text: "The scene's set-up and figure" }), " (in a new tab, the derivation hidden)."));
      else section.append(setupView(item));
      try {
        const practice = await practiceOf(item);
        section.append(...valuesView(item, practice.symbols || {}));
        const steps = item.steps.length ? item.steps : practice.exercises.map((e) => ({ step: e.step, coordinate: e.coordinate }));
        item.steps = steps;
        for (const s of steps) section.append(stepView(a, item, practice, s, index++));
      } catch (error) {
        section.append(el("p", { className: "class-status", text: error.message }));
      }
      part.append(section);
    }
    parts.push(part);
  }
  holder.replaceChildren(...parts);
  progress();
}

async function load() {
  let r;
  try {
    r = await api("GET", `/api/classes/${current.code}/me`, { key: current.key });
  } catch {
    $("joined-progress").textContent = "The server cannot be reached; retrying…";
    setTimeout(load, 5000);
    return;
  }
  if (r.status === 403 || r.status === 401) {
    leave(CLOSED);
    return;
  }
  if (r.status !== 200) {
    setTimeout(load, 5000);
    return;
  }
  record.clear();
  for (const s of r.data.record || []) {
    record.set(stepId(s.assignment, s.item, s.step, s.coordinate), { answer: s.answer, answered: s.answered, shown: s.shown });
  }
  for (const s of r.data.progress?.steps || []) {
    const key = stepId(s.assignment, s.item, s.step, s.coordinate);
    record.set(key, { ...recordOf(key), right: s.done, counted: s.counted, late: s.late });
  }
  const changed = JSON.stringify(r.data.assignments) !== JSON.stringify(series);
  series = r.data.assignments;
  const any = series.some((a) => a.items.length);
  $("join-waiting").hidden = any;
  if (changed) await drawItems();
  for (const form of document.querySelectorAll("#join-items .practice-step")) stepMark(form);
  progress();
  if (!any) setTimeout(load, 5000); // until the instructor sets one
}

function leave(message) {
  $("join-recovery").hidden = true;
  $("join-recovery-code").textContent = "";
  current = null;
  memory.set(null);
  show();
  $("join-status").textContent = message || "";
}

const JOIN_TRIES = 12; // a full minute of waiting and more: a hall of students joining at once is let in

/** Count down the seconds the server asked to wait before the next try, in the status line. */
async function waitShown(seconds, why) {
  for (let left = seconds; left > 0; left--) {
    $("join-status").textContent = `${why} Trying again in ${left} s…`;
    await new Promise((resolve) => setTimeout(resolve, 1000));
  }
  $("join-status").textContent = "Joining…";
}

$("join-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  const code = $("join-code").value.trim();
  const name = $("join-name").value.trim();
  const button = $("join-form").querySelector("button[type=submit]");
  // said here, in the form's own words, before anything is sent: a pseudonym of spaces is no pseudonym (the
  // server's "name: String should have …", or an earlier message about the code, stayed)
  if (!name) {
    $("join-status").textContent = "Type a pseudonym: the name your teacher will see (not your real name unless you wish).";
    $("join-name").focus();
    return;
  }
  // the institution login, once the class has asked for it (the server says so at the first press of Join)
  const asking = !$("join-login-field").hidden;
  const login = $("join-login").value.trim();
  if (asking && !login) {
    $("join-status").textContent = "Type your institution login above first: this class asks for it.";
    $("join-login").focus();
    return;
  }
  button.disabled = true;
  $("join-status").textContent = "Joining…";
  let r;
  try {
    // a 429 or 503 (many joining at once) is tried again after the Retry-After the server gives, shown counting down
    for (let attempt = 1; ; attempt++) {
      r = await api("POST", `/api/classes/${encodeURIComponent(code)}/join`, { body: { name, ...(asking ? { login } : {}) } });
      if ((r.status !== 429 && r.status !== 503) || attempt >= JOIN_TRIES) break;
      await waitShown(Math.max(1, r.retryAfter || 2), r.status === 429 ? "Many are joining at once." : "The server is busy.");
    }
  } catch {
    $("join-status").textContent = "The server cannot be reached.";
    return;
  } finally {
    button.disabled = false;
  }
  if (r.status === 422 && r.data?.loc?.[1] === "login") {
    if (asking && String(r.data.detail).startsWith("This class does not ask")) {
      // another class's code, which asks for none: the field goes, and the join is sent again without it
      $("join-login-field").hidden = true;
      $("join-login").value = "";
      $("join-form").requestSubmit();
      return;
    }
    // the class asks for it (or it is not one): the field is shown, said what to type, and focused
    $("join-login-field").hidden = false;
    // what to type is said under the field; the status line says what to do next (or what is wrong with it)
    if (!asking) $("join-login-help").textContent = r.data.detail;
    $("join-status").textContent = asking ? r.data.detail : "Type your institution login above, then press Join again.";
    $("join-login").focus();
    return;
  }
  if (r.status !== 200) {
    $("join-status").textContent = sentence(r.data?.detail || `Not joined (${r.status}).`);
    if (r.status === 422 && String(r.data?.detail).includes(" is taken in this class")) {
      // the name is taken: perhaps it is theirs, from another device; the way back is opened, filled in
      $("rejoin-code").value = code;
      $("rejoin-name").value = name;
      $("join-again").open = true;
    }
    return;
  }
  // shown once by the server (it keeps only its hash): this browser keeps it, through reloads, until "I have kept it"
  await enter(r, r.data.recovery_code);
});

/** Joined (or back on another device): the key kept in this browser, the class loaded. */
async function enter(r, recovery) {
  $("join-status").textContent = "";
  current = { code: r.data.code, key: r.data.student_key, name: r.data.name, title: r.data.title,
    ...(recovery ? { recovery } : {}) };
  memory.set(current);
  show();
  recoveryView();
  await load();
}

/** The student's recovery code, while it is kept in this browser (from joining until "I have kept it"). */
function recoveryView() {
  $("join-recovery-code").textContent = current?.recovery || "";
  $("join-recovery").hidden = !current?.recovery;
}

$("join-recovery-done").addEventListener("click", () => {
  delete current.recovery;
  memory.set(current);
  recoveryView();
});

$("rejoin-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  const code = $("rejoin-code").value.trim();
  const body = { name: $("rejoin-name").value.trim(), recovery_code: $("rejoin-recovery").value.trim() };
  $("join-status").textContent = "Opening your record…";
  let r;
  try {
    r = await api("POST", `/api/classes/${encodeURIComponent(code)}/rejoin`, { body });
  } catch {
    $("join-status").textContent = "The server cannot be reached.";
    return;
  }
  if (r.status !== 200) {
    const detail = r.data?.detail || `Not opened (${r.status}).`;
    $("join-status").textContent = sentence(detail);
    return;
  }
  await enter(r);
});

$("leave-class").addEventListener("click", () => leave("You left the class on this device."));

const asked = new URLSearchParams(window.location.search).get("code");
if (asked) $("join-code").value = $("rejoin-code").value = asked;
if (asked && current && current.code !== asked.trim().toUpperCase()) leave(""); // a link to another class
show();
if (current) {
  recoveryView();
  load();
}
