/**
 * teach.js — the instructor's page (templates/teach.html): create or open a class, project its code,
 * set the assignment, and watch the class live: the summary and the students are polled every
 * two seconds. The first screen answers "which step is the class stuck on, and which mistake": the
 * step with the most students stuck (answered, not yet right) and the most common named mistake,
 * totalled over every scene, each one click from the students concerned; then the steps, most stuck
 * first (bars of right and wrong answers), every mistake, each assignment of the series (who is done,
 * who is stuck), one row per student (score, steps shown; who is behind first). The students' names are hidden
 * until the teacher shows them (hidden again on every reload); projector mode hides them again, enlarges the type and
 * hides the editing. A step shown before it was typed right is "shown", never "done" (the grade's rule). The
 * instructor key stays in localStorage. A class holds a series of assignments (title, optional due
 * time, scenes and typed systems with their steps), added and deleted here. The recovery code is
 * shown once at creation; the teacher link carries it in its fragment (#class=…&recover=…), which a
 * browser never sends to a server: opened on another machine, it restores the key there.
 */
import { api, el, mistakeWords, practiceOf, showPanes, stepTex, stored, typeset } from "./classroom.js";
import { setProse } from "./prose.js";

/** A mistake's name in bold, its symbols' subscripts set as on the students' pages (U_eff, v_centre: prose.js). */
const mistakeName = (mistake) => {
  const strong = el("strong");
  setProse(strong, mistake.name || mistakeWords(mistake.key));
  return strong;
};

const POLL_MS = 2000;
const memory = stored("lagrange-teach");
const scenes = JSON.parse(document.getElementById("class-scenes").textContent);
const titleOf = Object.fromEntries(scenes.map((s) => [s.id, s.title]));
// an answer the checker could not read, in the teacher's words (from the server: the CSV says the same)
const NOT_READ_WORDS = JSON.parse(document.getElementById("class-not-read").textContent);
const $ = (id) => document.getElementById(id);
let current = memory.get(); // {code, key, title}
let timer = null;
let assignment = []; // every item of the series (for the labels of typed systems)
let series = [];

// ---- refusals: what the API refused, in a teacher's words, at the field it concerns ------------------

const NO_KEY = "Type the recovery code or the instructor key you were given when you made the class; "
  + "a teacher link cut short (as some mail programs do) misses part of it.";
const NOTHING_SET = "Tick at least one scene or add a typed system.";
const NO_SETUP = "Write the system's set-up: what each coordinate is, where it is measured from, and where U = 0 "
  + "(students read it above the boxes).";
/** The parts of a typed system (the playground's JSON), as the page names them. */
const SYSTEM_PARTS = {
  coordinates: "The coordinates", parameters: "The parameters", lagrangian: "The Lagrangian L",
  kinetic: "The kinetic energy T", potential: "The potential U", particles: "The particles",
  forces: "The generalized forces", nonnegative: "The names that are never negative",
};
/** A due time already past, in the form's words and the picker's local time (never ISO 8601 to a teacher). */
const PAST_DUE = (value = $("assign-due").value) => `That time${value ? ` (${new Date(value).toLocaleString([],
  { dateStyle: "medium", timeStyle: "short" })})` : ""} has passed: choose a later one.`;
const capital = (text) => text.charAt(0).toUpperCase() + text.slice(1);

/**
 * The one place that maps an API refusal to words and a place: {at: the id of the status line, text}.
 * The API locates a refusal by a path (loc: items.0.system.potential) and puts it before its message;
 * the page says instead which box it concerns, at that box.
 */
function refusal(r, at) {
  const data = r && typeof r.data === "object" && r.data ? r.data : {};
  const loc = (data.loc || data.errors?.[0]?.loc || []).map(String).filter((p) => p !== "body");
  // the message without the path before it ("items.0.system.potential: the '(' …" → "the '(' …")
  const said = String(data.detail || "").replace(/^[A-Za-z_][\w.]*: /, "");
  if (r.status === 401) return { at: "start-status", text: NO_KEY };
  const system = loc.indexOf("system");
  if (system >= 0) {
    const part = loc[system + 1];
    const what = part ? SYSTEM_PARTS[part] || `The system's “${part}”` : "The system";
    return { at: "assign-system-status", text: `${what}: ${said}` };
  }
  if (loc[0] === "items" && loc.length === 1 && data.errors) return { at: "assign-status", text: NOTHING_SET };
  if (loc[0] === "items" && loc[2] === "name") return { at: "assign-system-status", text: "Name the system: students see it by its name." };
  if (loc[0] === "items" && loc[2] === "setup") return { at: "assign-system-status", text: NO_SETUP };
  if (loc[0] === "due") return { at: "assign-status", text: PAST_DUE() };
  if (loc[0] === "title") return { at: "assign-status", text: "Give the assignment a title (200 characters at most)." };
  return { at, text: said ? `${capital(said)}.`.replace(/([.!?])\.$/, "$1") : `Refused (${r.status}).` };
}

/** Say a refusal at its field, or on the status line `at` when it concerns none. */
function refuse(r, at) {
  const found = refusal(r, at);
  $(found.at).textContent = found.text;
}

function show() {
  showPanes("class-start", "class-live", current && {
    "class-title": current.title,
    "class-code": current.code,
    "class-join-url": `${window.location.host}/join`,
    "class-key-text": current.key,
    "class-short-link": `${window.location.host}/j/${current.code}`,
  });
  // the short link as a QR code, drawn by this server (GET /j/{code}/qr.svg)
  const qr = $("class-qr");
  qr.hidden = !current;
  if (current) {
    qr.src = `/j/${encodeURIComponent(current.code)}/qr.svg`;
    qr.alt = `QR code of the link ${window.location.host}/j/${current.code}`;
    $("code-badge-code").textContent = current.code;
    $("code-badge-qr").src = qr.src;
  }
}

let loginColumn = null; // the institution login the open class asks its students for ("SIS Login ID", …; null: none)

async function open(code, key) {
  let r;
  try {
    r = await api("GET", `/api/classes/${encodeURIComponent(code)}/me`, { key });
  } catch {
    $("start-status").textContent = "The server cannot be reached.";
    return "unreachable";
  }
  if (r.status !== 200 || r.data.role !== "instructor") {
    if (r.status === 200) $("start-status").textContent = "That is a student's key, not the instructor's.";
    else refuse(r, "start-status");
    return r.status === 403 || r.status === 200 ? "refused" : "error";
  }
  current = { code: r.data.code, key, title: r.data.title };
  loginColumn = r.data.login_column || null;
  drawSession(r.data.session);
  $("class-login").value = loginColumn || "";
  memory.set(current);
  useSeries(r.data.assignments);
  show();
  showRecovery();
  buildEditor();
  showLoading();
  poll();
  return "open";
}

function useSeries(found) {
  series = found;
  assignment = series.flatMap((a) => a.items);
  drawSeries();
}

const NO_TITLE = "Give the class a title your students will recognise (for example “Mechanics II, Tuesday”; "
  + "200 characters at most): spaces alone are not a title.";

$("create-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  const title = $("create-title").value.trim();
  $("create-status").textContent = "";
  // said at the box, before asking the server (a title of spaces only passes the browser's "required")
  if (!title) {
    $("create-status").textContent = NO_TITLE;
    $("create-title").focus();
    return;
  }
  // the institution login students are asked for, under the header the LMS matches grades by (none: "")
  const r = await api("POST", "/api/classes", { body: { title, login_column: $("create-login").value || null } });
  if (r.status !== 201) {
    const found = refusal(r, "create-status");
    $("create-status").textContent = r.status === 422 && found.at === "assign-status" ? NO_TITLE : found.text;
    return;
  }
  // shown until "I have kept it" (a reload keeps it): the server keeps only its hash, so this is its one showing
  pending.set({ code: r.data.code, recovery: r.data.recovery_code, link: `${window.location.origin}${r.data.teacher_link}` });
  await open(r.data.code, r.data.teacher_key);
});

const pending = stored("lagrange-teach-recovery"); // the recovery code not yet kept: {code, recovery, link}

/** The recovery banner, while the class just made has a recovery code the teacher has not said they kept. */
function showRecovery() {
  const found = pending.get();
  if (!found || !current || found.code !== current.code) return;
  // broken only between its groups on a narrow screen
  secret($("recovery-code"), found.recovery, /(?<=-)/);
  secret($("recovery-link"), found.link, /(?=[#&])|(?<=-)/);
  $("recovery-status").textContent = "";
  $("class-recovery").hidden = false;
}

/** A secret's text in unbreakable parts (split by `at`), so a line may end only between two of them. */
function secret(element, text, at) {
  element.dataset.text = text;
  element.replaceChildren(...text.split(at).flatMap((part) => [el("span", { className: "secret-part", text: part }),
    document.createElement("wbr")]));
}

/** Copy a text to the clipboard (the selection's copy where the Clipboard API is not offered), said beside it. */
async function copy(text, what) {
  try {
    await navigator.clipboard.writeText(text);
  } catch {
    const box = el("textarea", { readonly: "" });
    box.value = text;
    document.body.append(box);
    box.select();
    const done = document.execCommand("copy");
    box.remove();
    if (!done) {
      $("recovery-status").textContent = `Copying is not allowed here: select the ${what} and copy it by hand.`;
      return;
    }
  }
  $("recovery-status").textContent = `The ${what} is copied: paste it where you keep such things.`;
}
$("recovery-code-copy").addEventListener("click", () => copy($("recovery-code").dataset.text, "recovery code"));
$("recovery-link-copy").addEventListener("click", () => copy($("recovery-link").dataset.text, "teacher link"));

$("recovery-done").addEventListener("click", () => {
  pending.set(null);
  $("class-recovery").hidden = true;
  $("recovery-code").textContent = "";
  $("recovery-link").textContent = "";
  $("recovery-status").textContent = "";
  delete $("recovery-code").dataset.text;
  delete $("recovery-link").dataset.text;
});

/** The instructor's key from the class code and its recovery code (POST …/recover), then the class opened. */
async function recover(code, recovery) {
  let r;
  try {
    r = await api("POST", `/api/classes/${encodeURIComponent(code)}/recover`, { body: { recovery_code: recovery } });
  } catch {
    $("start-status").textContent = "The server cannot be reached.";
    return;
  }
  if (r.status !== 200) {
    refuse(r, "start-status");
    return;
  }
  await open(r.data.code, r.data.teacher_key);
}

$("open-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  const recovery = $("open-recovery").value.trim();
  const key = $("open-key").value.trim();
  // nothing to open it with: said here, before asking the server
  if (!recovery && !key) $("start-status").textContent = NO_KEY;
  else if (recovery) await recover($("open-code").value.trim(), recovery);
  else await open($("open-code").value, key);
});

// ---- the live dashboard --------------------------------------------------------------------------

const LOADING = "Loading…";

/** Until the first figures arrive, every table and list of the dashboard says it is loading: an empty "Who is
 * done" on a projector would read as "nobody has done anything". */
function showLoading() {
  const row = (columns) => el("tr", { className: "dash-loading" }, el("td", { colspan: columns, text: LOADING }));
  $("dash-assignments").tBodies[0].replaceChildren(row(4));
  $("dash-students").tBodies[0].replaceChildren(row(7));
  for (const id of ["dash-steps", "dash-mistakes"]) $(id).replaceChildren(el("li", { className: "help dash-loading", text: LOADING }));
  for (const id of ["now-stuck", "now-mistake"]) {
    $(id).querySelector(".now-body").replaceChildren(el("p", { className: "help dash-loading", text: LOADING }));
  }
  $("dash-steps-all").hidden = true;
  $("dash-counts").textContent = LOADING;
}

async function labelOf(entry) {
  const item = entry.scene ? { scene: entry.scene } : assignment.find((i) => i.name === entry.system) || { name: entry.system };
  let practice = null;
  try {
    if (item.scene || item.system) practice = await practiceOf(item);
  } catch {
    /* the label falls back to the step's name */
  }
  const where = entry.scene ? titleOf[entry.scene] || entry.scene : entry.system;
  // the assignment named only when the series has several (one assignment needs no name on a projector)
  const of = series.length > 1 && series.find((a) => a.n === entry.assignment);
  return { tex: stepTex(practice, entry.step, entry.coordinate), where: of ? `${where} · ${of.n}. ${of.title}` : where };
}

/** The steps, the one with the most students stuck first (then the most wrong answers; else in assignment order). */
function byStuck(steps) {
  return steps.map((entry, i) => ({ entry, i }))
    .sort((a, b) => b.entry.stuck - a.entry.stuck || b.entry.incorrect - a.entry.incorrect || a.i - b.i)
    .map(({ entry }) => entry);
}

/** One click to the students concerned: a disclosure listing their names. */
const opened = new Set(); // the lists of names the instructor opened: they stay open when the poll redraws
function whoList(names, what, where, since = []) {
  if (!names.length) return null;
  const id = `${where}|${what}`;
  // a mistake's list marks who has since answered right (it mixed them with those still wrong)
  const said = names.map((n) => (since.includes(n) ? `${n} (right since)` : n));
  const box = el("details", { className: "now-who" },
    el("summary", { text: `${what} (${names.length})` }),
    el("p", { className: "now-names", text: said.join(", ") }));
  box.open = opened.has(id);
  box.addEventListener("toggle", () => (box.open ? opened.add(id) : opened.delete(id)));
  return box;
}

async function drawNow(summary) {
  const [top] = byStuck(summary.steps);
  const stuck = $("now-stuck").querySelector(".now-body");
  if (top && top.stuck) {
    const label = await labelOf(top);
    $("now-stuck").dataset.step = top.step;
    stuck.replaceChildren(
      el("p", { className: "now-what" }, typeset(el("span"), label.tex), el("span", { className: "dash-where", text: ` ${label.where}` })),
      el("p", { className: "now-figure", text: `${top.stuck} of ${summary.students} stuck · ${top.students_done} done` }),
      whoList(top.students_stuck, "Show the students stuck", "now"));
  } else {
    delete $("now-stuck").dataset.step;
    stuck.replaceChildren(el("p", { className: "help", text: "Nobody is stuck yet." }));
  }
  const [mistake] = summary.mistakes;
  const body = $("now-mistake").querySelector(".now-body");
  if (mistake) {
    const where = mistake.steps[0];
    const label = await labelOf(where);
    $("now-mistake").dataset.count = mistake.students.length;
    body.replaceChildren(
      el("p", { className: "now-what" }, mistakeName(mistake)),
      el("p", { className: "now-figure" }, `${madeBy(mistake)} · in `, typeset(el("span"), label.tex),
        el("span", { className: "dash-where", text: ` ${label.where}${mistake.steps.length > 1 ? ` and ${mistake.steps.length - 1} more` : ""}` })),
      whoList(mistake.students, "Show the students who made it", "now", mistake.students_since_right || []));
  } else {
    delete $("now-mistake").dataset.count;
    body.replaceChildren(el("p", { className: "help", text: "No named mistake so far." }));
  }
}

const plural = (n, one, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;
let editing = null; // the assignment loaded into the editor ("Edit…"), saved in its place; null: a new one
let everyStep = false; // "Show every step" pressed: the steps nobody has answered are listed too

/** A step's students: done on their own (as the grade counts them), shown ("Show this step" before a right
 * answer: right, but not counted), stuck, of the class. The bar counts the students who answered: those shown the
 * step without answering it are said apart, so the two sums agree. */
function stepNumbers(entry, students) {
  const blank = entry.students_shown_unanswered;
  const shown = entry.students_shown ? `, ${entry.students_shown} shown`
    + (blank ? ` (${blank === entry.students_shown ? (blank === 1 ? "without" : "all without") : `${blank} of them without`}`
      + " answering: not in the bar)" : "") : "";
  const late = entry.students_late ? `, ${entry.students_late} right only after the due time` : "";
  return `${entry.students_done} of ${plural(students, "student")} done${late}${shown}, ${entry.stuck} stuck`;
}

/** What an equivalent answer to a step is, as an observation (not a mistake): another zero of U, a factor. */
const OTHER_FORM = { potential: "wrote U with another zero", lagrangian: "wrote L plus a constant",
  hamiltonian: "wrote h plus a constant", position: "put the origin elsewhere", equation: "wrote the equation times a factor" };
const otherForm = (entry, students) => (entry.students_equivalent && OTHER_FORM[entry.step]
  ? `${entry.students_equivalent} of ${students} ${OTHER_FORM[entry.step]}` : "");

/** A step's students as a bar, each counted once by their best answer: green those with a right answer, red
 * those with only wrong ones; said in words beside it (with the equivalent answers apart) and in its aria-label.
 * Every step's track is the same width and stands for the whole class, so the bars compare from step to step: a
 * step answered by 3 of 21 fills a seventh of its track, whatever the length of its words. */
function answerBar(entry, students) {
  const right = entry.students_right;
  const wrong = entry.students_wrong;
  // the common scale: the class's size (never less than the students who answered, should one join meanwhile)
  const scale = Math.max(students, right + wrong);
  const other = otherForm(entry, students);
  const words = `${right} right, ${wrong} wrong` + (entry.not_read ? `, ${entry.not_read} ${NOT_READ_WORDS}` : "")
    + (other ? ` · ${other}` : "");
  const bar = el("div", { className: "dash-bar", role: "img",
    "aria-label": `Students who answered this step, of ${plural(students, "student")}: ${words} (green: right, red: wrong)` });
  const good = el("span", { className: "dash-good" });
  const bad = el("span", { className: "dash-bad" });
  good.style.width = scale ? `${(100 * right) / scale}%` : "0";
  bad.style.width = scale ? `${(100 * wrong) / scale}%` : "0";
  bar.append(good, bad);
  return el("div", { className: "dash-bar-row" },
    el("span", { className: "dash-bar-unit", text: "Students" }), bar,
    el("span", { className: "dash-bar-words", text: words }));
}

async function drawSteps(summary) {
  const list = $("dash-steps");
  const rows = [];
  // a step with no answer yet says nothing about the class: listed only on "Show every step"
  const idle = (entry) => !entry.correct && !entry.incorrect && !entry.not_read && !entry.students_done && !entry.stuck;
  const quiet = summary.steps.filter(idle).length;
  const toggle = $("dash-steps-all");
  toggle.hidden = !quiet;
  toggle.textContent = everyStep ? "Show only the steps answered" : `Show every step (${quiet} more not answered yet)`;
  toggle.setAttribute("aria-expanded", String(everyStep));
  for (const entry of byStuck(summary.steps)) {
    if (idle(entry) && !everyStep) continue;
    const label = await labelOf(entry);
    const mistakes = Object.entries(entry.mistakes);
    rows.push(el("li", { className: "dash-step", "data-step": `${entry.scene || entry.system}|${entry.step}` },
      el("div", { className: "dash-label" }, typeset(el("span"), label.tex), el("span", { className: "dash-where", text: ` ${label.where}` })),
      answerBar(entry, summary.students),
      el("p", { className: "dash-numbers",
        text: stepNumbers(entry, summary.students)
          + (mistakes.length ? `; most often: ${entry.mistake_names?.[mistakes[0][0]] || mistakeWords(mistakes[0][0])}` : "") }),
      whoList(entry.students_stuck, "Show the students stuck", `step|${entry.assignment}|${entry.scene || entry.system}|${entry.step}|${entry.coordinate || ""}`)));
  }
  list.replaceChildren(...rows);
  if (!rows.length) list.replaceChildren(el("li", { className: "help", text: quiet ? "No answer yet." : "No steps yet: set an assignment, or wait for the first answer." }));
}

// the Score header sorts by score (lowest first, then highest first), a third click goes back to "who is behind"
$("dash-score-sort").addEventListener("click", () => {
  order = { behind: "score-up", "score-up": "score-down", "score-down": "behind" }[order];
  poll();
});

$("dash-steps-all").addEventListener("click", () => {
  everyStep = !everyStep;
  poll();
});

/** A named mistake's figure: the students who made it (as its "Show the students" counts them), the answers apart
 * when one of them made it more than once: "4 students, 5 answers". */
const madeBy = (mistake) => plural(mistake.students.length, "student")
  + (mistake.count !== mistake.students.length ? `, ${plural(mistake.count, "answer")}` : "");
/** How many students made each of several mistakes: "1 student", "1 or 2 students". */
function spread(mistakes) {
  const counts = mistakes.map((m) => m.students.length);
  const [low, high] = [Math.min(...counts), Math.max(...counts)];
  return low === high ? plural(low, "student") : `${low} to ${high} students`;
}
let moreOpen = false; // "and N more" opened: it stays open when the poll redraws

const FIRST_MISTAKES = 8; // listed at once; the rest behind "and N more", never left out

async function drawMistakes(summary) {
  const rows = [];
  const rest = [];
  for (const [k, mistake] of summary.mistakes.entries()) {
    const pieces = [];
    for (const where of mistake.steps) {
      const label = await labelOf(where);
      pieces.push(el("span", { className: "dash-piece" }, typeset(el("span"), label.tex),
        el("span", { className: "dash-where", text: ` (${label.where}${mistake.steps.length > 1 ? `, ${plural(where.students, "student")}` : ""})` })));
    }
    (k < FIRST_MISTAKES ? rows : rest).push(el("li", { className: "dash-mistake", "data-mistake": mistake.key },
      el("span", { className: "dash-count", text: madeBy(mistake) }),
      mistakeName(mistake),
      el("span", { text: " in " }), ...pieces,
      whoList(mistake.students, "Show the students", `mistake|${mistake.key}`, mistake.students_since_right || [])));
  }
  if (rest.length) {
    // the less common mistakes, said as a count, one click from the list (open through the poll's redraws)
    const more = el("details", { className: "dash-more-mistakes" },
      el("summary", { text: `and ${plural(rest.length, "more mistake")} (${rest.length === 1 ? "made" : "each made"} `
        + `by ${spread(summary.mistakes.slice(FIRST_MISTAKES))})` }),
      el("ol", { className: "dash-mistakes" }, ...rest));
    more.open = moreOpen;
    more.addEventListener("toggle", () => (moreOpen = more.open));
    rows.push(el("li", { className: "dash-more" }, more));
  }
  // beside the mistakes, what is right but not as the set-up asks (another zero of U): an observation, not a mistake
  for (const entry of summary.steps.filter((e) => otherForm(e, summary.students))) {
    const label = await labelOf(entry);
    const name = entry.step === "potential" ? "another zero of U" : `${OTHER_FORM[entry.step].replace(/^wrote /, "")}`;
    rows.push(el("li", { className: "dash-mistake dash-observation", "data-observation": entry.step },
      el("span", { className: "dash-count", text: `${entry.students_equivalent} of ${summary.students}` }),
      el("strong", { text: name }), el("span", { text: " (right, not a mistake) in " }), typeset(el("span"), label.tex),
      el("span", { className: "dash-where", text: ` (${label.where})` })));
  }
  $("dash-mistakes").replaceChildren(...rows);
  if (!rows.length) $("dash-mistakes").replaceChildren(el("li", { className: "help", text: "No named mistake so far." }));
}

const when = (iso) => (iso ? new Date(iso).toLocaleString([], { dateStyle: "medium", timeStyle: "short" }) : "—");

function drawAssignments(summary) {
  const body = $("dash-assignments").tBodies[0];
  body.replaceChildren(...(summary.assignments || []).map((a) => el("tr", { "data-assignment": a.n },
    el("th", { scope: "row", text: `${a.n}. ${a.title}` }),
    el("td", { text: when(a.due) }),
    // the names apart from the counts, so projector mode can show the counts alone
    el("td", { className: "dash-done" }, `${a.students_done.length} of ${summary.students}`,
      a.students_done.length ? el("span", { className: "dash-names", text: `: ${a.students_done.join(", ")}` }) : null,
      // through every step, but with one shown ("Show this step"): not done, as the grade does not count it
      a.students_shown?.length ? el("span", { className: "dash-shown" }, ` · ${a.students_shown.length} with a step shown`,
        el("span", { className: "dash-names", text: `: ${a.students_shown.join(", ")}` })) : null),
    el("td", { className: "dash-stuck", ...(a.students_stuck.length ? { "data-count": plural(a.students_stuck.length, "student") } : {}) },
      a.students_stuck.length ? el("span", { className: "dash-names", text: a.students_stuck.join(", ") }) : "—"))));
}

const codes = new Map(); // a student's new recovery code, given this session: shown beside their name until reload

/** "New code": a new recovery code for a student who lost theirs (the server keeps only hashes, so the old one
 *  cannot be shown again, and it stops working). */
function codeButton(name) {
  const given = codes.get(name);
  if (given) return el("code", { className: "dash-code", text: given });
  const button = el("button", { type: "button", className: "link-button dash-new-code", text: "new code",
    "aria-label": `A new recovery code for ${name} (their old one stops working; asks first)` });
  button.addEventListener("click", async () => {
    if (!window.confirm(`Give ${name} a new recovery code? Their old code stops working.`)) return;
    const r = await api("POST", `/api/classes/${current.code}/students/recovery`, { key: current.key, body: { name } });
    if (r.status !== 200) {
      refuse(r, "data-status");
      return;
    }
    codes.set(name, r.data.recovery_code);
    button.replaceWith(el("code", { className: "dash-code", text: r.data.recovery_code }));
  });
  return button;
}

/** Each student's score as the gradebook computes it (GET …/grades: its one home), per assignment: "66.7 · —". */
const scoreWords = (grades) => (grades || []).map((g) => (g.score === null ? "—" : g.score.toFixed(1))).join(" · ");
/** One number to sort by: the mean of the assignments' scores (no score yet counts 0). */
const scoreKey = (grades) => (grades?.length ? grades.reduce((sum, g) => sum + (g.score ?? 0), 0) / grades.length : 0);
/** A time since, as a lecturer says it: "just now", "4 min ago", "1 h 20 min ago". */
function since(ms) {
  const minutes = Math.floor(Math.max(0, ms) / 60000);
  if (minutes < 1) return "just now";
  if (minutes < 60) return `${minutes} min ago`;
  const hours = Math.floor(minutes / 60);
  return hours < 24 ? `${hours} h ${minutes % 60} min ago` : `${plural(Math.floor(hours / 24), "day")} ago`;
}
let order = "behind"; // the Students table's order: "behind" (fewest steps done on one's own first), or by score

async function drawStudents(found, book) {
  const rows = [];
  const gradesOf = Object.fromEntries((book?.students || []).map((s) => [s.name, s.grades]));
  const students = [...found];
  if (order === "behind") students.sort((a, b) => a.own - b.own || b.shown - a.shown || (a.name < b.name ? -1 : 1));
  else students.sort((a, b) => (order === "score-up" ? 1 : -1) * (scoreKey(gradesOf[a.name]) - scoreKey(gradesOf[b.name]))
    || (a.name < b.name ? -1 : 1));
  $("dash-score-sort").parentElement.setAttribute("aria-sort", order === "score-up" ? "ascending" : order === "score-down" ? "descending" : "none");
  const now = Date.now();
  for (const s of students) {
    const last = [...s.steps].sort((a, b) => (a.last < b.last ? 1 : -1))[0];
    const cell = el("td", { className: "dash-last" });
    if (last) {
      // the step by its name as the page prints it (T, equation of motion for θ), then done or not yet
      const entry = { ...(titleOf[last.item] ? { scene: last.item } : { system: last.item }), step: last.step,
        coordinate: last.coordinate, assignment: last.assignment };
      const label = await labelOf(entry);
      cell.append(typeset(el("span"), label.tex), el("span", { className: "dash-where", text: ` ${label.where}` }),
        el("span", { text: last.shown ? " · shown" : last.late ? " · right, late" : last.done ? " ✓ done" : " · not yet right" }));
    } else cell.textContent = "—";
    // the institution login, on a line of its own under the pseudonym, when the class asks for it
    const login = loginColumn ? el("span", { className: "dash-login", text: `${loginColumn}: ${s.login || "none given"}` }) : "";
    rows.push(el("tr", { "data-student": s.name },
      el("th", { scope: "row" }, s.name, " ", codeButton(s.name), login),
      // done on one's own, as the grade counts them; the steps shown apart
      // by the due time; the steps right only after it said apart (recorded, never counted)
      el("td", { className: "dash-own", text: (s.assigned ? `${s.own} of ${s.assigned}` : String(s.own)) + (s.late ? ` (${s.late} late)` : "") }),
      el("td", { className: "dash-shown-count", text: String(s.shown) }),
      el("td", { className: "dash-score", text: scoreWords(gradesOf[s.name]) }),
      // every answer sent, those the checker could not read said apart (they are never counted wrong)
      el("td", { text: s.not_read ? `${s.attempts} (${s.not_read} ${NOT_READ_WORDS})` : String(s.attempts) }),
      // the time since their last answer: who stopped half way, told from who is still working
      el("td", { className: "dash-active", text: last ? since(now - new Date(last.last).getTime()) : "no answer yet" }),
      cell));
  }
  $("dash-students").tBodies[0].replaceChildren(...rows);
}

async function poll() {
  clearTimeout(timer);
  if (!current) return;
  try {
    const [summary, students] = await Promise.all([
      api("GET", `/api/classes/${current.code}/summary`, { key: current.key }),
      api("GET", `/api/classes/${current.code}/students`, { key: current.key }),
    ]);
    // the scores after them, not beside them: a page holds at most two requests at a time (a classroom's network
    // shares the server's connections)
    const book = summary.status === 200 ? await api("GET", `/api/classes/${current.code}/grades`, { key: current.key }) : null;
    if (summary.status === 403) {
      $("dash-counts").textContent = "This class no longer exists (deleted, or past its retention).";
      return;
    }
    if (summary.status === 200 && students.status === 200) {
      const s = summary.data;
      $("dash-counts").textContent = `${s.students} student${s.students === 1 ? "" : "s"} · ${s.attempts} answer${s.attempts === 1 ? "" : "s"} · updated ${new Date().toLocaleTimeString()}`;
      await drawNow(s);
      drawAssignments(s);
      await drawSteps(s);
      await drawMistakes(s);
      await drawStudents(students.data.students, book?.status === 200 ? book.data : null);
    }
  } catch {
    $("dash-counts").textContent = "The server cannot be reached; retrying…";
  }
  timer = setTimeout(poll, POLL_MS);
}

// ---- the assignment editor -----------------------------------------------------------------------

function buildEditor() {
  const list = $("assign-scenes");
  list.replaceChildren(...scenes.map((scene) => {
    // a new assignment starts with nothing ticked
    const box = el("input", { type: "checkbox", id: `assign-${scene.id}`, "data-scene": scene.id });
    const steps = el("ul", { className: "assign-steps" });
    const item = el("li", { className: "assign-scene" }, box, el("label", { for: `assign-${scene.id}`, text: scene.title }), steps);
    const fill = async () => {
      if (!box.checked) {
        steps.replaceChildren();
        return;
      }
      const practice = await practiceOf({ scene: scene.id });
      steps.replaceChildren(...practice.exercises.map((e, k) => {
        const id = `assign-${scene.id}-${k}`;
        const tick = el("input", { type: "checkbox", id, "data-step": e.step, "data-coordinate": e.coordinate || "" });
        // the step in words, as the student reads it ("Energy function h", "ω² of small oscillations")
        return el("li", {}, tick, el("label", { for: id, text: e.title }));
      }));
    };
    box.fill = fill; // awaited when an assignment is loaded to edit, before its steps are ticked
    box.addEventListener("change", fill);
    fill();
    return item;
  }));
}

/** An item of an assignment as the list shows it: its scene or system, then its steps as the page prints them. */
function itemLine(item) {
  const where = item.scene ? titleOf[item.scene] || item.scene : item.name;
  const steps = el("span", { className: "assign-item-steps", text: item.steps.length ? "…" : "every step" });
  if (item.steps.length) {
    practiceOf(item.scene ? { scene: item.scene } : item).catch(() => null).then((practice) => {
      steps.replaceChildren(...item.steps.flatMap((s, k) => [k ? ", " : "",
        typeset(el("span"), stepTex(practice, s.step, s.coordinate))]));
    });
  }
  return el("li", {}, el("span", { text: `${where}: ` }), steps);
}

/** The series: one entry per assignment (its title, due time if any, items with their steps), each deletable. */
function drawSeries() {
  $("assign-series").replaceChildren(...series.map((a) => {
    // "Delete…": the ellipsis says a question comes before anything is deleted
    const remove = el("button", { type: "button", className: "danger", text: "Delete…", "data-delete": a.n,
      "aria-label": `Delete assignment ${a.n}, ${a.title} (asks first)` });
    remove.addEventListener("click", async () => {
      if (!window.confirm(`Delete assignment ${a.n}, "${a.title}", and every answer recorded for it?`)) return;
      const r = await api("DELETE", `/api/classes/${current.code}/assignments/${a.n}`, { key: current.key });
      if (r.status === 204) $("assign-status").textContent = `Deleted: ${a.title}.`;
      else refuse(r, "assign-status");
      await reloadSeries();
    });
    // "Edit…": the assignment loaded into the editor; saving replaces it in its place, its answers kept
    const edit = el("button", { type: "button", text: "Edit…", "data-edit": a.n,
      "aria-label": `Edit assignment ${a.n}, ${a.title} (its answers are kept)` });
    edit.addEventListener("click", () => editAssignment(a));
    return el("li", { className: "assign-entry", "data-assignment": a.n },
      el("strong", { text: a.title }), a.due ? ` · due ${when(a.due)} ` : " · no due date ", edit, " ", remove,
      el("ul", { className: "assign-items" }, ...a.items.map(itemLine)));
  }));
  // the empty state is a sentence beside the list, not its first item
  $("assign-none").hidden = series.length > 0;
}

async function reloadSeries() {
  const r = await api("GET", `/api/classes/${current.code}/assignments`, { key: current.key });
  if (r.status === 200) useSeries(r.data.assignments);
  poll();
}

/** The typed system of the editor, its steps shown to tick (from POST /api/practice, as a student's page loads them). */
function typedSystem() {
  const text = $("assign-system").value.trim();
  if (!text) return null;
  return { name: $("assign-system-name").value.trim(), system: JSON.parse(text), setup: $("assign-system-setup").value.trim() };
}

/** Where a text stops being JSON: the first place no continuation can make valid (a prefix up to it is JSON
 * cut short), as {line, column, near} counted from 1. */
function whereNotJson(text) {
  let good = 0;
  for (let k = 1; k <= text.length; k++) {
    try {
      JSON.parse(text.slice(0, k));
      good = k;
    } catch (error) {
      // only cut short so far: "Unexpected end of JSON input", "end of data" (Firefox), or a complaint about the
      // very end ("Expected ',' or '}' … at position k" for a prefix of k characters)
      const at = error.message.match(/at position (\d+)/);
      if (/end of (JSON )?(input|data)/i.test(error.message) || (at && Number(at[1]) === k)) good = k;
      else break;
    }
  }
  const before = text.slice(0, good).split("\n");
  const near = text.slice(good, good + 12).split("\n")[0];
  return { line: before.length, column: before[before.length - 1].length + 1, near };
}

/** The typed system read from its box, or null with the reason said at the box (not JSON, or empty). */
function readSystem() {
  try {
    return typedSystem();
  } catch {
    const text = $("assign-system").value;
    const { line, column, near } = whereNotJson(text);
    $("assign-system-status").textContent = `The system is not written in the expected form: at line ${line}, `
      + `column ${column}${near ? ` (at “${near}”)` : ""}. Write it as in the example above the box: braces around `
      + "named parts, each name and each formula in double quotes, lists in square brackets.";
    return null;
  }
}

/** The typed system's steps (POST /api/practice), or null with the refusal said at the system's box. */
async function systemPractice(item) {
  try {
    return await practiceOf(item);
  } catch (error) {
    if (error.response) refuse(error.response, "assign-system-status");
    else $("assign-system-status").textContent = "The server cannot be reached.";
    return null;
  }
}

async function loadSystemSteps() {
  // a fresh try: the last refusal and steps go (they were for the system as it was)
  $("assign-system-steps").replaceChildren();
  $("assign-system-status").textContent = "";
  const item = readSystem();
  if (!item) {
    if (!$("assign-system").value.trim()) $("assign-system-status").textContent = "Type the system first.";
    return;
  }
  $("assign-system-status").textContent = "Finding its steps…";
  const practice = await systemPractice(item);
  if (!practice) return;
  $("assign-system-status").textContent = "";
  $("assign-system-steps").replaceChildren(...practice.exercises.map((e, k) => {
    const id = `assign-system-${k}`;
    const tick = el("input", { type: "checkbox", id, "data-step": e.step, "data-coordinate": e.coordinate || "" });
    return el("li", {}, tick, el("label", { for: id, text: e.title })); // the step in words, as the student reads it
  }));
  return practice;
}

$("assign-system-load").addEventListener("click", loadSystemSteps);

const ticked = (list) => [...list.querySelectorAll("input:checked")].map((t) => ({
  step: t.dataset.step, ...(t.dataset.coordinate ? { coordinate: t.dataset.coordinate } : {}) }));

$("assign-save").addEventListener("click", async () => {
  const items = [];
  for (const box of document.querySelectorAll("#assign-scenes > li > input[data-scene]")) {
    if (box.checked) items.push({ scene: box.dataset.scene, steps: ticked(box.parentElement.querySelector(".assign-steps")) });
  }
  $("assign-status").textContent = "";
  $("assign-system-status").textContent = "";
  const typed = readSystem();
  if (!typed && $("assign-system").value.trim()) return; // not JSON: said at the system's box
  if (typed) {
    // none ticked: every step, as for a scene (its steps loaded if "Show its steps" was not pressed)
    let steps = ticked($("assign-system-steps"));
    if (!steps.length) {
      const practice = await systemPractice(typed);
      if (!practice) return;
      steps = practice.exercises.map((e) => ({ step: e.step, ...(e.coordinate ? { coordinate: e.coordinate } : {}) }));
    }
    if (!typed.setup) {
      // the set-up is what the students cannot do without: said at the system's box before anything is sent
      $("assign-system-status").textContent = NO_SETUP;
      $("assign-system-setup").focus();
      return;
    }
    items.push({ ...typed, steps });
  }
  if (!items.length) {
    $("assign-status").textContent = NOTHING_SET;
    return;
  }
  const typedDue = $("assign-due").value;
  // an edited assignment whose due time was left as it was keeps it exactly (a time already past stays allowed)
  const due = editing && typedDue === localInput(editing.due) ? editing.due
    : typedDue ? new Date(typedDue).toISOString() : null;
  // a new due time already past: said at the form, in its own local time, before anything is sent
  if (due && due !== editing?.due && new Date(due) <= new Date()) {
    $("assign-status").textContent = PAST_DUE(typedDue);
    $("assign-due").focus();
    return;
  }
  if (editing) {
    // a scene's parameters (set through the API) stay with the scene
    for (const item of items) item.parameters = editing.items.find((i) => i.scene && i.scene === item.scene)?.parameters;
    const title = $("assign-title-input").value.trim() || editing.title;
    const r = await api("PUT", `/api/classes/${current.code}/assignments/${editing.n}`,
      { key: current.key, body: { title, due, items } });
    if (r.status !== 200) {
      refuse(r, "assign-status");
      return;
    }
    resetEditor();
    await reloadSeries();
    $("assign-status").textContent = `Saved: ${r.data.n}. ${r.data.title} (its answers are kept).`;
    return;
  }
  const title = $("assign-title-input").value.trim() || `Assignment ${series.length + 1}`;
  const r = await api("POST", `/api/classes/${current.code}/assignments`, { key: current.key, body: { title, due, items } });
  if (r.status !== 201) {
    refuse(r, "assign-status");
    return;
  }
  resetEditor();
  await reloadSeries();
  $("assign-status").textContent = `Added: ${r.data.n}. ${r.data.title}.`;
});

/** The editor emptied, back to "A new assignment". */
function resetEditor() {
  editing = null;
  $("assign-title-input").value = "";
  $("assign-due").value = "";
  $("assign-system").value = "";
  $("assign-system-name").value = "";
  $("assign-system-setup").value = "";
  $("assign-system-steps").replaceChildren();
  $("assign-system-status").textContent = "";
  $("assign-editor-title").textContent = "A new assignment";
  $("assign-save").textContent = "Add this assignment";
  $("assign-cancel").hidden = true;
  buildEditor();
}

$("assign-cancel").addEventListener("click", () => {
  resetEditor();
  $("assign-status").textContent = "";
});

/** An ISO time as a datetime-local input's value, in the browser's local time ("2026-12-04T17:00"). */
function localInput(iso) {
  if (!iso) return "";
  const t = new Date(iso);
  const pad = (n) => String(n).padStart(2, "0");
  return `${t.getFullYear()}-${pad(t.getMonth() + 1)}-${pad(t.getDate())}T${pad(t.getHours())}:${pad(t.getMinutes())}`;
}

const tickSteps = (list, steps) => {
  for (const s of steps) {
    const box = list.querySelector(`input[data-step="${s.step}"][data-coordinate="${s.coordinate || ""}"]`);
    if (box) box.checked = true;
  }
};

/** A stored system as a teacher types it: pretty-printed, without the fields left at their defaults (null, "",
 * empty lists), and a parameter with nothing but its name (and the default value 1) as its bare name. */
function asTyped(system) {
  const clean = (value) => {
    if (Array.isArray(value)) return value.map(clean);
    if (!value || typeof value !== "object") return value;
    const kept = Object.entries(value).map(([k, v]) => [k, clean(v)])
      .filter(([, v]) => v !== null && v !== "" && !(Array.isArray(v) && !v.length)
        && !(typeof v === "object" && v && !Array.isArray(v) && !Object.keys(v).length));
    return Object.fromEntries(kept);
  };
  const found = clean(system);
  if (Array.isArray(found.parameters)) {
    found.parameters = found.parameters.map((p) => (p && typeof p === "object" && Object.keys(p).every((k) => k === "name"
      || (k === "value" && p.value === 1)) ? p.name : p));
  }
  return JSON.stringify(found, null, 2);
}

/** An assignment loaded into the editor: its title, due time, scenes and steps ticked, its typed system. */
async function editAssignment(a) {
  resetEditor();
  editing = a;
  $("assign-editor-title").textContent = `Editing assignment ${a.n}`;
  $("assign-save").textContent = `Save the changes to assignment ${a.n}`;
  $("assign-cancel").hidden = false;
  $("assign-title-input").value = a.title;
  $("assign-due").value = localInput(a.due);
  $("assign-status").textContent = `Editing ${a.n}. ${a.title}: its answers are kept when you save.`;
  for (const item of a.items.filter((i) => i.scene)) {
    const box = $(`assign-${item.scene}`);
    if (!box) continue;
    box.checked = true;
    await box.fill();
    tickSteps(box.parentElement.querySelector(".assign-steps"), item.steps);
  }
  const typed = a.items.find((i) => i.system);
  if (typed) {
    $("assign-system-box").open = true;
    $("assign-system-name").value = typed.name;
    $("assign-system").value = asTyped(typed.system);
    $("assign-system-setup").value = typed.setup || ""; // what the students read above the boxes, kept
    if (await loadSystemSteps()) tickSteps($("assign-system-steps"), typed.steps);
  }
  $("assign-editor-title").scrollIntoView({ block: "start" });
}

// ---- the record ----------------------------------------------------------------------------------

async function download(path, name) {
  const res = await fetch(path, { headers: { Authorization: `Bearer ${current.key}` } });
  if (!res.ok) {
    $("data-status").textContent = `The export failed (${res.status}).`;
    return;
  }
  const link = el("a", { href: URL.createObjectURL(await res.blob()), download: name });
  document.body.append(link);
  link.click();
  link.remove();
}

$("export-csv").addEventListener("click", () => download(`/api/classes/${current.code}/export?format=csv`, `class-${current.code}.csv`));
$("grades-csv").addEventListener("click", () => download(`/api/classes/${current.code}/grades?format=csv`, `grades-${current.code}.csv`));
$("grades-details-csv").addEventListener("click", () => download(`/api/classes/${current.code}/grades?format=details-csv`,
  `grades-${current.code}-details.csv`));

function forget(message = "") {
  clearTimeout(timer);
  current = null;
  memory.set(null);
  pending.set(null);
  $("class-recovery").hidden = true;
  show();
  $("start-status").textContent = message;
}

// closing forgets the class on this device only: asked first, with the way back (the key itself) in the question
$("forget-class").addEventListener("click", () => {
  const { code, key } = current;
  if (!window.confirm(`Close the class ${code} on this device? It is not deleted, but this browser forgets it: to open `
    + "it again you need its recovery code or teacher link (shown once when you created it), or this instructor key: "
    + `${key}`)) return;
  forget(`The class ${code} is closed on this device, not deleted: open it again with its recovery code, its teacher `
    + "link or its instructor key.");
});
/** The delete dialog's answer: "download", "delete" or "keep" (Escape keeps the class). */
function askDelete(code) {
  const dialog = $("delete-dialog");
  $("delete-dialog-code").textContent = code;
  dialog.returnValue = "keep";
  return new Promise((resolve) => {
    dialog.addEventListener("close", () => resolve(dialog.returnValue || "keep"), { once: true });
    dialog.showModal();
  });
}

$("delete-class").addEventListener("click", async () => {
  const { code } = current;
  // the record offered first, in three plain buttons: once deleted, nothing of it can be downloaded
  const chosen = await askDelete(code);
  if (chosen === "keep") return;
  if (chosen === "download") {
    await download(`/api/classes/${code}/export?format=csv`, `class-${code}.csv`);
    await download(`/api/classes/${code}/grades?format=details-csv`, `grades-${code}-details.csv`);
  }
  if (!window.confirm(`Delete the class ${code} and every answer recorded for it? This cannot be undone.`)) return;
  const r = await api("DELETE", `/api/classes/${code}`, { key: current.key });
  if (r.status === 204) forget(`The class ${code} is deleted, with every answer recorded for it. Its students are told `
    + "it was closed when they next open it.");
  else refuse(r, "data-status");
});

// ---- projector mode: large type, only what the class should see -----------------------------------

const projector = stored("lagrange-teach-projector");
// the names' choice is never remembered: a reload opens with them hidden (a laptop mirrored to a projector); the
// choice an earlier version kept in this browser is forgotten
stored("lagrange-teach-names").set(null);
function project(on) {
  document.body.classList.toggle("projector", on);
  $("projector").setAttribute("aria-pressed", String(on));
  $("projector").textContent = on ? "Leave projector mode" : "Projector mode";
  projector.set(on || null);
}
/** The students' names on the dashboard: hidden (counts only) until the teacher presses "Show the students' names". */
function showNames(on) {
  document.body.classList.toggle("names-shown", on);
  $("names-shown").setAttribute("aria-pressed", String(on));
  $("names-shown").textContent = on ? "Hide the students' names" : "Show the students' names";
}
$("names-shown").addEventListener("click", () => showNames(!document.body.classList.contains("names-shown")));
$("projector").addEventListener("click", () => {
  const on = !document.body.classList.contains("projector");
  project(on);
  if (on) showNames(false); // going onto the projector: the names go first
});
project(Boolean(projector.get()));
// projected: once the banner has scrolled away, the class code and its QR code stay in a corner (CSS shows the badge
// only in projector mode), so a latecomer can still join while the lecturer shows "Stuck on" lower down
new IntersectionObserver(([entry]) => document.body.classList.toggle("banner-away", !entry.isIntersecting))
  .observe(document.querySelector(".class-banner"));
showNames(false);

show();
// a teacher link (#class=…&recover=…): the fragment is read here and wiped from the address at once
const fragment = new URLSearchParams(window.location.hash.slice(1));
if (fragment.get("class") && fragment.get("recover")) {
  window.history.replaceState(null, "", window.location.pathname + window.location.search);
  recover(fragment.get("class"), fragment.get("recover"));
} else if (fragment.get("class") && !current) {
  // a teacher link cut before its recovery code
  window.history.replaceState(null, "", window.location.pathname + window.location.search);
  $("open-code").value = fragment.get("class");
  $("open-code").closest("details").open = true;
  $("start-status").textContent = `This teacher link is incomplete: it has no recovery code. ${NO_KEY}`;
} else if (current) {
  // a class this browser kept: reopened, and forgotten only when the server says the key no longer opens it
  open(current.code, current.key).then((how) => how === "refused" && forget());
}
// a teacher link pasted into this tab changes only the fragment, and the browser does not load the page again:
// read it as a fresh load would (after a cut link, the whole one pasted here did nothing)
window.addEventListener("hashchange", () => {
  if (new URLSearchParams(window.location.hash.slice(1)).get("class")) window.location.reload();
});

// ---- the session's ends: close joining, stop answers (kept in the class's record; reopened as easily) --------

let session = null; // {joining_open, joining_closed_at, answers_open, answers_stopped_at}: as the server said
const clock = (iso) => new Date(iso).toLocaleTimeString([], { timeStyle: "short" });

/** The two buttons say what a press does; the line beside them says the state, in a teacher's words. */
function drawSession(state) {
  session = state || null;
  $("session-joining").hidden = $("session-answers").hidden = !session;
  if (!session) return;
  $("session-joining").textContent = session.joining_open ? "Close joining" : "Reopen joining";
  $("session-joining").setAttribute("aria-pressed", String(!session.joining_open));
  $("session-answers").textContent = session.answers_open ? "Stop answers" : "Take answers again";
  $("session-answers").setAttribute("aria-pressed", String(!session.answers_open));
  const said = [];
  if (!session.joining_open) {
    said.push(`Joining closed at ${clock(session.joining_closed_at)}: new students are refused; those who joined keep working.`);
  }
  if (!session.answers_open) {
    said.push(`Answers stopped at ${clock(session.answers_stopped_at)}: students are told their answers are not `
      + "recorded; what they answered before is kept.");
  }
  $("session-status").textContent = said.length ? said.join(" ") : "Open: students may join and answer.";
  document.body.classList.toggle("session-ended", !session.joining_open || !session.answers_open);
}

async function setSession(change) {
  const r = await api("PUT", `/api/classes/${current.code}/session`, { key: current.key, body: change });
  if (r.status !== 200) {
    refuse(r, "session-status");
    return;
  }
  drawSession(r.data);
}
$("session-joining").addEventListener("click", () => setSession({ joining_open: !session.joining_open }));
$("session-answers").addEventListener("click", () => setSession({ answers_open: !session.answers_open }));

// the institution login asked at joining, changed for the open class (PUT …/login); the grades file follows
$("class-login").addEventListener("change", async () => {
  const column = $("class-login").value || null;
  const r = await api("PUT", `/api/classes/${current.code}/login`, { key: current.key, body: { login_column: column } });
  if (r.status !== 200) {
    $("class-login").value = loginColumn || "";
    $("data-status").textContent = r.data?.detail || `Not changed (${r.status}).`;
    return;
  }
  loginColumn = r.data.login_column;
  $("data-status").textContent = loginColumn
    ? `Students joining from now on are asked for their institution login (“${loginColumn}” in the grades file).`
    : "Students are no longer asked for an institution login.";
  poll();
});
