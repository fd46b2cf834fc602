/**
 * classroom.js — what the instructor's page (teach.js) and the students' page (join.js) share:
 * calls to /api/classes with a key, KaTeX typesetting, a step's label and a mistake's name.
 */
import { fetchRetrying } from "./api.js";

/** Call the API; answers {status, data, retryAfter}. A key goes as "Authorization: Bearer <key>". With `tries`,
 * a 429 or 503 is retried (api.js), as long as the server asks for at most `patience` seconds. */
export async function api(method, path, { key, body, tries = 1, patience } = {}) {
  const headers = { Accept: "application/json" };
  if (key) headers.Authorization = `Bearer ${key}`;
  if (body !== undefined) headers["Content-Type"] = "application/json";
  const init = { method, headers, body: body === undefined ? undefined : JSON.stringify(body) };
  const res = await fetchRetrying(path, init, { tries, patience });
  let data = null;
  const type = res.headers.get("Content-Type") || "";
  if (type.includes("json")) data = await res.json();
  else if (res.status !== 204) data = await res.text();
  return { status: res.status, data, retryAfter: Number(res.headers.get("Retry-After") || 0) };
}

/** Typeset LaTeX into an element (plain text until KaTeX is there). */
export function typeset(element, tex, display = false) {
  if (window.katex) {
    window.katex.render(tex, element, { throwOnError: false, displayMode: display });
  } else {
    element.textContent = tex;
  }
  return element;
}

export function el(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (name === "text") node.textContent = value;
    else if (name === "className") node.className = value;
    else node.setAttribute(name, value);
  }
  for (const child of children) if (child) node.append(child);
  return node;
}

/** The practice document of a scene (GET) or of an assigned system (POST /api/practice), cached per page. */
const practices = new Map();
export async function practiceOf(item) {
  // a typed system is known by what it says, not its name: a corrected system is derived afresh
  const id = item.scene ? `scene:${item.scene}` : `system:${JSON.stringify(item.system)}`;
  if (!practices.has(id)) {
    const load = item.scene
      ? api("GET", `/api/scenes/${encodeURIComponent(item.scene)}/practice`)
      : api("POST", "/api/practice", { body: item.system });
    practices.set(id, load.then((r) => {
      if (r.status !== 200) {
        practices.delete(id);
        // the refusal kept whole, for a page that says it at the field it concerns
        throw Object.assign(new Error((r.data && r.data.detail) || `the steps could not be loaded (${r.status})`), { response: r });
      }
      return r.data;
    }));
  }
  return practices.get(id);
}

/** The exercise of a practice document for a step (and coordinate). */
export function exerciseOf(practice, step, coordinate) {
  return practice.exercises.find((e) => e.step === step && (e.coordinate || null) === (coordinate || null))
    || practice.exercises.find((e) => e.step === step);
}

/** LaTeX naming a step: its symbol (T, U, L, p_θ, θ̈, h, ω²), or the equation of motion of a coordinate. */
export function stepTex(practice, step, coordinate) {
  const e = practice && exerciseOf(practice, step, coordinate);
  if (step === "equation") {
    const q = coordinate && practice ? practice.symbols[coordinate] || coordinate : "";
    return q ? `\\text{equation of motion for }${q}` : "\\text{equation of motion}";
  }
  if (step === "omega_squared") return "\\omega^2";
  return e ? e.lhs : `\\text{${step}}`;
}

/** A mistake's name as words: "missing_cross_term" → "missing cross term". */
export function mistakeWords(name) {
  return name.replace(/_/g, " ").replace(/^\w/, (c) => c.toUpperCase());
}

/** A class page's two panes: `start` while no class is open (no `fields`), else `live`, each element named in
 * `fields` given its text. */
export function showPanes(start, live, fields) {
  document.getElementById(start).hidden = Boolean(fields);
  document.getElementById(live).hidden = !fields;
  for (const [id, text] of Object.entries(fields || {})) document.getElementById(id).textContent = text;
}

/** Read and write one JSON record in localStorage (nothing kept when storage is off). */
export function stored(key) {
  return {
    get() {
      try {
        return JSON.parse(window.localStorage.getItem(key) || "null");
      } catch {
        return null;
      }
    },
    set(value) {
      try {
        if (value === null) window.localStorage.removeItem(key);
        else window.localStorage.setItem(key, JSON.stringify(value));
      } catch {
        /* storage off: the page still works until it is closed */
      }
    },
  };
}
