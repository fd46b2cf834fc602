/**
 * teach.js — the instructor's page (templates/teach.html): create or open a class, project its code,
 * set the assignment, and watch the class live: the summary and the students are polled every
 * two seconds. The first screen answers "which step is the class stuck on, and which mistake": the
 * step with the most students stuck (answered, not yet right) and the most common named mistake,
 * totalled over every scene, each one click from the students concerned; then the steps, most stuck
 * first (bars of right and wrong answers), every mistake, each assignment of the series (who is done,
 * who is stuck), one row per student. Projector mode enlarges the type and hides the editing. The
 * instructor key stays in localStorage. A class holds a series of assignments (title, optional due
 * time, scenes and typed systems with their steps), added and deleted here. The recovery code is
 * shown once at creation; the teacher link carries it in its fragment (#class=…&recover=…), which a
 * browser never sends to a server: opened on another machine, it restores the key there.
 */
import { api, el, mistakeWords, practiceOf, showPanes, stepTex, stored, typeset } from "./classroom.js";

const POLL_MS = 2000;
const memory = stored("lagrange-teach");
const scenes = JSON.parse(document.getElementById("class-scenes").textContent);
const titleOf = Object.fromEntries(scenes.map((s) => [s.id, s.title]));
const $ = (id) => document.getElementById(id);
let current = memory.get(); // {code, key, title}
let timer = null;
let assignment = []; // every item of the series (for the labels of typed systems)
let series = [];

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
  }
}

async function open(code, key) {
  let r;
  try {
    r = await api("GET", `/api/classes/${encodeURIComponent(code)}/me`, { key });
  } catch {
    $("start-status").textContent = "The server cannot be reached.";
    return "unreachable";
  }
  if (r.status !== 200 || r.data.role !== "instructor") {
    $("start-status").textContent = r.status === 200 ? "That is a student's key, not the instructor's." : (r.data?.detail || `Not opened (${r.status}).`);
    return r.status === 403 || r.status === 200 ? "refused" : "error";
  }
  current = { code: r.data.code, key, title: r.data.title };
  memory.set(current);
  useSeries(r.data.assignments);
  show();
  buildEditor();
  poll();
  return "open";
}

function useSeries(found) {
  series = found;
  assignment = series.flatMap((a) => a.items);
  drawSeries();
}

$("create-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  const title = $("create-title").value.trim();
  const r = await api("POST", "/api/classes", { body: { title } });
  if (r.status !== 201) {
    $("start-status").textContent = r.data?.detail || `The class was not created (${r.status}).`;
    return;
  }
  await open(r.data.code, r.data.teacher_key);
  // shown once: the server keeps only its hash
  $("recovery-code").textContent = r.data.recovery_code;
  $("recovery-link").textContent = `${window.location.origin}${r.data.teacher_link}`;
  $("class-recovery").hidden = false;
});

$("recovery-done").addEventListener("click", () => {
  $("class-recovery").hidden = true;
  $("recovery-code").textContent = "";
  $("recovery-link").textContent = "";
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
    $("start-status").textContent = r.data?.detail || `Not opened (${r.status}).`;
    return;
  }
  await open(r.data.code, r.data.teacher_key);
}

$("open-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  const recovery = $("open-recovery").value.trim();
  if (recovery) await recover($("open-code").value.trim(), recovery);
  else await open($("open-code").value, $("open-key").value.trim());
});

// ---- the live dashboard --------------------------------------------------------------------------

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
function whoList(names, what, where) {
  if (!names.length) return null;
  const id = `${where}|${what}`;
  const box = el("details", { className: "now-who" },
    el("summary", { text: `${what} (${names.length})` }),
    el("p", { className: "now-names", text: names.join(", ") }));
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
    $("now-mistake").dataset.count = mistake.count;
    body.replaceChildren(
      el("p", { className: "now-what" }, el("strong", { text: mistake.name || mistakeWords(mistake.key) })),
      el("p", { className: "now-figure" }, `${mistake.count}× · in `, typeset(el("span"), label.tex),
        el("span", { className: "dash-where", text: ` ${label.where}${mistake.steps.length > 1 ? ` and ${mistake.steps.length - 1} more` : ""}` })),
      whoList(mistake.students, "Show the students who made it", "now"));
  } else {
    delete $("now-mistake").dataset.count;
    body.replaceChildren(el("p", { className: "help", text: "No named mistake so far." }));
  }
}

async function drawSteps(summary) {
  const list = $("dash-steps");
  const rows = [];
  for (const entry of byStuck(summary.steps)) {
    const label = await labelOf(entry);
    const total = entry.correct + entry.incorrect;
    const bar = el("div", { className: "dash-bar", role: "img",
      "aria-label": `${entry.correct} right, ${entry.incorrect} wrong` });
    const good = el("span", { className: "dash-good" });
    const bad = el("span", { className: "dash-bad" });
    good.style.width = total ? `${(100 * entry.correct) / total}%` : "0";
    bad.style.width = total ? `${(100 * entry.incorrect) / total}%` : "0";
    bar.append(good, bad);
    const mistakes = Object.entries(entry.mistakes);
    rows.push(el("li", { className: "dash-step" },
      el("div", { className: "dash-label" }, typeset(el("span"), label.tex), el("span", { className: "dash-where", text: ` ${label.where}` })),
      bar,
      el("p", { className: "dash-numbers",
        text: `${entry.stuck} stuck · ${entry.students_done} of ${summary.students} done · ${entry.correct} right · ${entry.incorrect} wrong`
          + (mistakes.length ? ` · most often: ${entry.mistake_names?.[mistakes[0][0]] || mistakeWords(mistakes[0][0])}` : "") }),
      whoList(entry.students_stuck, "Show the students stuck", `step|${entry.assignment}|${entry.scene || entry.system}|${entry.step}|${entry.coordinate || ""}`)));
  }
  list.replaceChildren(...rows);
  if (!rows.length) list.replaceChildren(el("li", { className: "help", text: "No steps yet: set an assignment, or wait for the first answer." }));
}

async function drawMistakes(summary) {
  const rows = [];
  for (const mistake of summary.mistakes.slice(0, 8)) {
    const pieces = [];
    for (const where of mistake.steps) {
      const label = await labelOf(where);
      pieces.push(el("span", { className: "dash-piece" }, typeset(el("span"), label.tex),
        el("span", { className: "dash-where", text: ` (${label.where}${mistake.steps.length > 1 ? `, ${where.count}×` : ""})` })));
    }
    rows.push(el("li", { className: "dash-mistake", "data-mistake": mistake.key },
      el("span", { className: "dash-count", text: `${mistake.count}×` }),
      el("strong", { text: mistake.name || mistakeWords(mistake.key) }),
      el("span", { text: " in " }), ...pieces,
      whoList(mistake.students, "Show the students", `mistake|${mistake.key}`)));
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
    el("td", { className: "dash-done", text: `${a.students_done.length} of ${summary.students}${a.students_done.length ? `: ${a.students_done.join(", ")}` : ""}` }),
    el("td", { className: "dash-stuck", text: a.students_stuck.length ? a.students_stuck.join(", ") : "—" }))));
}

function drawStudents(students) {
  const body = $("dash-students").tBodies[0];
  body.replaceChildren(...students.map((s) => {
    const last = [...s.steps].sort((a, b) => (a.last < b.last ? 1 : -1))[0];
    return el("tr", {},
      el("th", { scope: "row", text: s.name }),
      el("td", { text: s.assigned ? `${s.done} of ${s.assigned}` : String(s.done) }),
      el("td", { text: String(s.attempts) }),
      el("td", { text: last ? `${last.step}${last.coordinate ? ` (${last.coordinate})` : ""} ${last.done ? "✓" : "…"}` : "—" }));
  }));
}

async function poll() {
  clearTimeout(timer);
  if (!current) return;
  try {
    const [summary, students] = await Promise.all([
      api("GET", `/api/classes/${current.code}/summary`, { key: current.key }),
      api("GET", `/api/classes/${current.code}/students`, { key: current.key }),
    ]);
    if (summary.status === 403) {
      $("dash-counts").textContent = "This class no longer exists (deleted, or past its retention).";
      return;
    }
    if (summary.status === 200 && students.status === 200) {
      const s = summary.data;
      $("dash-counts").textContent = `${s.students} student${s.students === 1 ? "" : "s"} · ${s.attempts} answer${s.attempts === 1 ? "" : "s"} · updated ${new Date().toLocaleTimeString()}`;
      await drawNow(s);
      await drawSteps(s);
      await drawMistakes(s);
      drawAssignments(s);
      drawStudents(students.data.students);
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
        return el("li", {}, tick, typeset(el("label", { for: id }), stepTex(practice, e.step, e.coordinate)));
      }));
    };
    box.addEventListener("change", fill);
    fill();
    return item;
  }));
}

/** The series: one line per assignment (its number, title, due time, items), each with a Delete button. */
function drawSeries() {
  $("assign-series").replaceChildren(...series.map((a) => {
    const remove = el("button", { type: "button", className: "danger", text: "Delete", "data-delete": a.n });
    remove.addEventListener("click", async () => {
      if (!window.confirm(`Delete assignment ${a.n}, "${a.title}", and every answer recorded for it?`)) return;
      const r = await api("DELETE", `/api/classes/${current.code}/assignments/${a.n}`, { key: current.key });
      $("assign-status").textContent = r.status === 204 ? `Deleted: ${a.title}.` : r.data?.detail || `Not deleted (${r.status}).`;
      await reloadSeries();
    });
    const items = a.items.map((i) => (i.scene ? titleOf[i.scene] || i.scene : i.name)).join(", ");
    return el("li", { className: "assign-entry", "data-assignment": a.n },
      el("strong", { text: a.title }), ` · due ${when(a.due)} · ${items} `, remove);
  }));
  if (!series.length) $("assign-series").replaceChildren(el("li", { className: "help", text: "No assignment yet: students may practise any scene." }));
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
  return { name: $("assign-system-name").value.trim(), system: JSON.parse(text) };
}

$("assign-system-load").addEventListener("click", async () => {
  let item;
  try {
    item = typedSystem();
  } catch (error) {
    $("assign-status").textContent = `The system is not JSON: ${error.message}`;
    return;
  }
  if (!item) return;
  try {
    const practice = await practiceOf(item);
    $("assign-system-steps").replaceChildren(...practice.exercises.map((e, k) => {
      const id = `assign-system-${k}`;
      const tick = el("input", { type: "checkbox", id, "data-step": e.step, "data-coordinate": e.coordinate || "" });
      return el("li", {}, tick, typeset(el("label", { for: id }), stepTex(practice, e.step, e.coordinate)));
    }));
  } catch (error) {
    $("assign-status").textContent = error.message;
  }
});

const ticked = (list) => [...list.querySelectorAll("input:checked")].map((t) => ({
  step: t.dataset.step, ...(t.dataset.coordinate ? { coordinate: t.dataset.coordinate } : {}) }));

$("assign-save").addEventListener("click", async () => {
  const items = [];
  for (const box of document.querySelectorAll("#assign-scenes > li > input[data-scene]")) {
    if (box.checked) items.push({ scene: box.dataset.scene, steps: ticked(box.parentElement.querySelector(".assign-steps")) });
  }
  let typed = null;
  try {
    typed = typedSystem();
  } catch (error) {
    $("assign-status").textContent = `The system is not JSON: ${error.message}`;
    return;
  }
  if (typed) items.push({ ...typed, steps: ticked($("assign-system-steps")) });
  const due = $("assign-due").value ? new Date($("assign-due").value).toISOString() : null;
  const title = $("assign-title-input").value.trim() || `Assignment ${series.length + 1}`;
  const r = await api("POST", `/api/classes/${current.code}/assignments`, { key: current.key, body: { title, due, items } });
  if (r.status !== 201) {
    $("assign-status").textContent = r.data?.detail || `Not added (${r.status}).`;
    return;
  }
  $("assign-title-input").value = "";
  $("assign-due").value = "";
  $("assign-system").value = "";
  $("assign-system-name").value = "";
  $("assign-system-steps").replaceChildren();
  buildEditor();
  await reloadSeries();
  $("assign-status").textContent = `Added: ${r.data.n}. ${r.data.title}.`;
});

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

function forget() {
  clearTimeout(timer);
  current = null;
  memory.set(null);
  show();
}

$("forget-class").addEventListener("click", forget);
$("delete-class").addEventListener("click", async () => {
  if (!window.confirm(`Delete the class ${current.code} and every answer recorded for it? This cannot be undone.`)) return;
  const r = await api("DELETE", `/api/classes/${current.code}`, { key: current.key });
  if (r.status === 204) forget();
  else $("data-status").textContent = r.data?.detail || `Not deleted (${r.status}).`;
});

// ---- projector mode: large type, only what the class should see -----------------------------------

const projector = stored("lagrange-teach-projector");
function project(on) {
  document.body.classList.toggle("projector", on);
  $("projector").setAttribute("aria-pressed", String(on));
  $("projector").textContent = on ? "Leave projector mode" : "Projector mode";
  projector.set(on || null);
}
$("projector").addEventListener("click", () => project(!document.body.classList.contains("projector")));
project(Boolean(projector.get()));

show();
// a teacher link (#class=…&recover=…): the fragment is read here and wiped from the address at once
const fragment = new URLSearchParams(window.location.hash.slice(1));
if (fragment.get("class") && fragment.get("recover")) {
  window.history.replaceState(null, "", window.location.pathname + window.location.search);
  recover(fragment.get("class"), fragment.get("recover"));
} else if (current) {
  // a class this browser kept: reopened, and forgotten only when the server says the key no longer opens it
  open(current.code, current.key).then((how) => how === "refused" && forget());
}
