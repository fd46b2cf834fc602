/**
 * breaking.js — a display formula too wide for its box is broken across lines, as a textbook does on a narrow page.
 *
 *   alignedRows(tex)          the rows of a formula: an aligned block (\begin{aligned} … \end{aligned}) gives
 *                             one row per line, its alignment marks (&) dropped; any other formula is one row
 *   breakable(row)            the row with a break allowed after each \\quad at its top level
 *   breakDisplay(el, katex)   typeset el's formula (data-tex) as a display; if it is wider than el, typeset
 *                             it again row by row, each row in text mode at display size (\displaystyle), so
 *                             that KaTeX's own line breaking applies: a row goes on to the next line after a
 *                             relation (=) or a binary operator (+, −) at its top level, continuation lines
 *                             indented (site.css, .math-line).  Returns whether it broke the formula.
 *
 * What cannot break (a matrix, one bracket \left( … \right) wider than a phone) still overflows: the box then
 * scrolls and shows so (scrollboxes.js).
 */
const OPEN = "\\begin{aligned}";
const CLOSE = "\\end{aligned}";

/** Where a row ends in an aligned block at its top level (E = \begin{aligned} … \end{aligned}): the block's
 *  start, or -1. */
function trailingBlock(row) {
  let braces = 0;
  let envs = 0;
  for (let i = 0; i < row.length; i++) {
    const c = row[i];
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    else if (c === "\\") {
      if (braces === 0 && envs === 0 && row.startsWith(OPEN, i)) {
        // its own \end{aligned} must close the row
        let depth = 0;
        for (let j = i; j < row.length; j++) {
          if (row.startsWith("\\begin{", j)) depth += 1;
          else if (row.startsWith("\\end{", j)) {
            depth -= 1;
            if (depth === 0) return row.startsWith(CLOSE, j) && j + CLOSE.length === row.length ? i : -1;
          }
        }
        return -1;
      }
      if (row.startsWith("\\begin{", i)) envs += 1;
      else if (row.startsWith("\\end{", i)) envs -= 1;
      i += 1;
    }
  }
  return -1;
}

export function alignedRows(tex) {
  const t = tex.trim();
  if (!t.startsWith(OPEN) || !t.endsWith(CLOSE)) {
    // a row that goes on in an aligned block of its own (the engine's long sums): its first line, then the rest
    const at = trailingBlock(t);
    if (at <= 0) return [t];
    const inner = alignedRows(t.slice(at));
    return [`${t.slice(0, at)}${inner[0] ?? ""}`, ...inner.slice(1)];
  }
  const body = t.slice(OPEN.length, t.length - CLOSE.length);
  const rows = [];
  let row = "";
  let braces = 0;
  let envs = 0;
  for (let i = 0; i < body.length; i++) {
    const c = body[i];
    if (c === "\\") {
      if (body.startsWith("\\begin{", i)) envs += 1;
      else if (body.startsWith("\\end{", i)) envs -= 1;
      else if (body[i + 1] === "\\" && braces === 0 && envs === 0) {
        rows.push(row);
        row = "";
        i += 1;
        // a row separator may carry a space: \\[4pt]
        if (body[i + 1] === "[") i = body.indexOf("]", i + 1);
        continue;
      }
      row += c + (body[i + 1] ?? ""); // a control symbol (\{, \&, \,) is kept whole
      i += 1;
      continue;
    }
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    if (c === "&" && braces === 0 && envs === 0) continue;
    row += c;
  }
  rows.push(row);
  // a row that is itself an aligned block, or ends in one, gives its own lines
  return rows.map((r) => r.trim()).filter(Boolean).flatMap((r) => (r.includes(OPEN) ? alignedRows(r) : [r]));
}

/** The relation written at ``i`` of a row (=, \\approx, \\equiv, \\le, \\ge …), or "". */
function relationAt(row, i) {
  if (row[i] === "=" || row[i] === "<" || row[i] === ">") return row[i];
  const word = /^\\(approx|equiv|leq|geq|le|ge|neq|ne|sim)(?![a-zA-Z])/.exec(row.slice(i));
  return word ? word[0] : "";
}

/** A row with a line break allowed after each wide space at its top level (\quad before "(string tension)",
 *  between two equations of one row), where KaTeX by itself breaks only after relations and operators.
 *  A relation just after a wide space holds on to what follows it (no "K =" left at a line's end, its matrix on
 *  the next line), and so does the row's first relation when ``glue`` is set (the row is wider than its box
 *  however it breaks: "ω₁² =" then stays with the fraction too wide for a phone, in the box that scrolls); a value
 *  beside what it evaluates goes on to the next line with its ≈ before it ("≈ 5.747 s⁻²", never a bare number
 *  beginning a line). */
export function breakable(row, glue = false) {
  let out = "";
  let braces = 0;
  let brackets = 0; // \left … \right: one piece for KaTeX, never broken inside
  let related = false; // a relation met since the last wide space
  let spaced = false; // a wide space met
  for (let i = 0; i < row.length; i++) {
    const c = row[i];
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    const top = braces === 0 && brackets === 0;
    if (c === "\\" && /^\\left(?![a-zA-Z])/.test(row.slice(i))) brackets += 1;
    else if (c === "\\" && /^\\right(?![a-zA-Z])/.test(row.slice(i))) brackets -= 1;
    const quad = row.startsWith("\\quad", i) || row.startsWith("\\qquad", i);
    if (c === "\\" && quad && top) {
      const word = row.startsWith("\\qquad", i) ? "\\qquad" : "\\quad";
      out += `${word}\\allowbreak `;
      i += word.length - 1;
      related = false;
      spaced = true;
      continue;
    }
    const relation = top ? relationAt(row, i) : "";
    if (relation) {
      const approx = relation === "\\approx" && related;
      const held = approx || (!related && (spaced || glue));
      out += `${approx ? "\\allowbreak " : ""}${relation}${held ? "\\nobreak " : ""}`;
      i += relation.length - 1;
      related = true;
      continue;
    }
    if (c === "\\" && i + 1 < row.length) {
      // a control word or symbol kept whole (\left<, \{ are not relations)
      const word = /^\\([a-zA-Z]+|.)/.exec(row.slice(i))[0];
      out += word;
      i += word.length - 1;
      continue;
    }
    out += c;
  }
  return out;
}

export function breakDisplay(el, katex) {
  const tex = el.dataset.tex;
  if (!tex || !katex) return false;
  // a formula broken for a narrower box is typeset whole again first: it may fit now
  if (el.dataset.broken) {
    katex.render(tex, el, { displayMode: true, throwOnError: false });
    delete el.dataset.broken;
  }
  if (el.scrollWidth <= el.clientWidth + 1 || el.querySelector(".katex-error")) return false;
  el.textContent = "";
  for (const row of alignedRows(tex)) {
    const line = document.createElement("div");
    line.className = "math-line";
    katex.render(`\\displaystyle ${breakable(row)}`, line, { displayMode: false, throwOnError: false });
    el.append(line);
    // a row wider than the box however it breaks: its first relation kept with what it relates
    if (line.scrollWidth > line.clientWidth + 1) {
      katex.render(`\\displaystyle ${breakable(row, true)}`, line, { displayMode: false, throwOnError: false });
    }
  }
  if (el.querySelector(".katex-error")) {
    katex.render(tex, el, { displayMode: true, throwOnError: false });
    return false;
  }
  el.dataset.broken = "true";
  return true;
}
