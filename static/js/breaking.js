/**
 * breaking.js — a display formula too wide for its box is broken across lines, as a textbook does on a narrow page.
 *
 *   alignedRows(tex)          the rows of a formula: an aligned block (\begin{aligned} … \end{aligned}) gives
 *                             one row per line, its alignment marks (&) dropped; any other formula is one row
 *   joinedRows(tex)           the formula with each line the engine broke off (a row "&\\quad …" of an aligned
 *                             block, broken by a count of characters before the page knew its width) joined
 *                             back onto the line before it
 *   breakable(row)            the row with a break allowed after each \\quad at its top level
 *   fractionRow(row)          a row's widest fraction at its top level (θ̈₁ = \frac{…}{…}, H = \frac{…}{…} − mgs sin α):
 *                             what comes before it, its numerator, its denominator and what comes after it; else null
 *   numeratorTerms(num)       a numerator's terms, split before each + and − at its top level
 *   stackedFraction(f, n)     the row again with its numerator's terms on n lines, each under the first
 *   vectorRow(row)            a row that ends in a vector written across, \vec r = \left(a, b, c\right): what comes
 *                             before it and its components; else null
 *   columnVector(v)           the row again with the vector set as a column, its components one under the other
 *   breakDisplay(el, katex)   typeset el's formula (data-tex) as a display, on one line where the engine broke
 *                             it if that fits el (a textbook never breaks a formula where there is room); else
 *                             as the engine broke it; if that is wider than el too, typeset it again row by row
 *                             (the engine's lines joined: KaTeX breaks them where the box needs), each row in text mode at display size (\displaystyle), so
 *                             that KaTeX's own line breaking applies: a row goes on to the next line after a
 *                             relation (=) or a binary operator (+, −) at its top level, continuation lines
 *                             indented (site.css, .math-line).  A fraction, one piece for KaTeX, wider than the
 *                             box even so has its numerator broken over more lines, as a textbook does on a
 *                             narrow page; a vector wider than the box is set as a column.  Returns whether
 *                             it broke the formula.
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

/** The rows of an aligned block's body at its top level: each [as written (with its &), without its alignment
 *  marks, the space its separator carries (\\[4pt] gives "[4pt]", else "")]. A control symbol (\{, \&, \,) is
 *  kept whole; a separator inside braces or an inner environment belongs to them. */
function blockRows(body) {
  const rows = [];
  let row = "";
  let bare = "";
  let braces = 0;
  let envs = 0;
  for (let i = 0; i < body.length; i++) {
    const c = body[i];
    if (c === "\\") {
      if (body.startsWith("\\begin{", i)) envs += 1;
      else if (body.startsWith("\\end{", i)) envs -= 1;
      else if (body[i + 1] === "\\" && braces === 0 && envs === 0) {
        const close = body[i + 2] === "[" ? body.indexOf("]", i + 2) : -1;
        rows.push([row, bare, close > 0 ? body.slice(i + 2, close + 1) : ""]);
        row = ""; bare = "";
        i = close > 0 ? close : i + 1;
        continue;
      }
      row += c + (body[i + 1] ?? ""); bare += c + (body[i + 1] ?? "");
      i += 1;
      continue;
    }
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    row += c;
    if (!(c === "&" && braces === 0 && envs === 0)) bare += c;
  }
  rows.push([row, bare, ""]);
  return rows;
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
  // a row that is itself an aligned block, or ends in one, gives its own lines
  return blockRows(t.slice(OPEN.length, t.length - CLOSE.length)).map(([, bare]) => bare.trim()).filter(Boolean)
    .flatMap((r) => (r.includes(OPEN) ? alignedRows(r) : [r]));
}

// the space between the rows of a stacked display that holds a fraction (the double pendulum's θ̈₁ and θ̈₂,
// each a tall fraction, touched: θ̈₁'s denominator on θ̈₂'s numerator); a textbook leaves a clear gap there
export const ROW_GAP = "0.6em";

/** A display's TeX with room between the rows of its aligned block when a row holds a fraction at display size;
 *  any other formula as it is.  KaTeX, like LaTeX's arrays, reads \\[0.6em] as a least depth, which a deep
 *  fraction already passes (nothing changed); so each row but the last ends in an invisible copy of itself lowered
 *  by the gap (\raisebox{-0.6em}{$\displaystyle\vphantom{…}$}): the row is then exactly that much deeper, however
 *  deep it was.  Only the typeset form: the page's data-tex, which the tests and the reader's copy read, is left
 *  alone. */
export function spacedRows(tex) {
  const t = tex.trim();
  if (!t.startsWith(OPEN) || !t.endsWith(CLOSE) || !/\\d?frac(?![a-zA-Z])/.test(t)) return tex;
  // the outer block's rows: each as written (with its &) and without its alignment marks (for the copy)
  const rows = blockRows(t.slice(OPEN.length, t.length - CLOSE.length));
  if (rows.length < 2) return tex;
  const last = rows.length - 1;
  return OPEN + rows.map(([r, b, gap], k) => (k < last
    ? `${r}\\raisebox{-${ROW_GAP}}{$\\displaystyle\\vphantom{${b}}$} \\\\${gap} `
    : r)).join("") + CLOSE;
}

// a line the engine broke off a row: the separator of an aligned block, then the quad that indents the line
const CONTINUATION = /\s*\\\\(?:\[[^\]]*\])?\s*&\\quad(?![a-zA-Z])\s*/y;

/** The formula with each continuation line of its aligned block (``\\ &\quad - m g z``) back on the line before
 *  it (``… + λ₂(…) - m g z``): the rows as written, the engine's breaks undone.  Only the display's own rows, at
 *  the top level: a numerator the engine stacked inside a fraction (the double pendulum's θ̈₁) keeps its lines. */
export function joinedRows(tex) {
  let braces = 0;
  let last = 0;
  let out = "";
  for (let i = 0; i < tex.length; i++) {
    const c = tex[i];
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    else if (c === "\\" || /\s/.test(c)) {
      CONTINUATION.lastIndex = i;
      const m = braces === 0 ? CONTINUATION.exec(tex) : null;
      if (m && m.index === i) {
        out += `${tex.slice(last, i)} `;
        last = i + m[0].length;
        i = last - 1;
      } else if (c === "\\") {
        i += 1; // a control symbol (\{, \}) is no brace
      }
    }
  }
  return out + tex.slice(last);
}

/** The relation written at ``i`` of a row (=, \\approx, \\equiv, \\le, \\ge …), or "". */
function relationAt(row, i) {
  if (row[i] === "=" || row[i] === "<" || row[i] === ">") return row[i];
  const word = /^\\(approx|equiv|leq|geq|le|ge|neq|ne|sim)(?![a-zA-Z])/.exec(row.slice(i));
  return word ? word[0] : "";
}

/** A row with a line break allowed after each wide space at its top level (\quad before "(string tension)",
 *  between two equations of one row), where KaTeX by itself breaks only after relations and operators, and before
 *  a joining word of prose (\text{ with }: "for every δq" / "with δq(t₀) = δq(t₁) = 0").  A line never ends in a
 *  relation (no "=" at a line's end, its "0" alone on the next): each relation holds on to what
 *  follows it, and a second relation of the same equation may begin the next line instead, as a textbook
 *  continues a display ("= …" under the first).  So a value beside what it evaluates goes on to the next line
 *  with its ≈ before it ("≈ 5.747 s⁻²", never a bare number beginning a line).  What must stay whole (a
 *  condition δq(t₀) = δq(t₁) = 0) is one group in braces: nothing inside braces breaks.  ``loose``: for a row
 *  wider than its box however it breaks so, a break after a relation as well (not after a wide space's first),
 *  rather than a box that scrolls sideways. */
/** Whether a + or − written after ``out`` joins two terms (binary), not a sign of the term after a relation, an
 *  opening bracket, a comma, another sign, or at the start. */
function binaryAt(out) {
  const before = out.trimEnd();
  if (!before || /\\nobreak$/.test(before) || /\\allowbreak$/.test(before)) return false;
  return !/[=(\[{,+\-&<>]$|\\(left[.(\[|]?|quad|qquad|,|;|:|!|le|ge|leq|geq|approx|equiv|to|cdot|times)$/.test(before);
}

export function breakable(row, loose = false) {
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
      // never a break after a relation; before one that continues an equation (a = b ⏎ = c, ≈ 5.7), allowed.
      // Loose (a row wider than its box even so: "½ period = ∫ …" with a fraction nearly a phone wide): a break
      // after the row's first relation too (not after a wide space's first). Never after a
      // relation that begins its row (an aligned block's "= ∫ …" under "t = …"): it would stand alone on its line
      //; nor after one that continues an equation ("H = Σ p q̇ − L =" at a line's end, its fraction
      // below): that one begins the next line with what follows it.  ``loose`` "after", the last try for a
      // row still too wide: a continuing relation may end a line as well (the break after it), but a value's ≈ not
      const first = out.trim() === "";
      const approx = relation === "\\approx" && related;
      const after = loose === "after";
      const held = !loose || first || (after ? approx || (!related && spaced) : related || spaced);
      out += `${related && (!after || approx) ? "\\allowbreak " : ""}${relation}${held ? "\\nobreak " : ""}`;
      i += relation.length - 1;
      related = true;
      continue;
    }
    // a joining word of prose at the top level (\text{ with }, its leading space says it joins): a break before it
    if (top && /^\\text\{\s/.test(row.slice(i)) && out.trim() !== "") {
      out += "\\allowbreak ";
    }
    // a + or − between two terms at the top level: the break goes before it, never after, so that a line's end
    // never holds a sign the next line needs, and the next line begins with it, as a textbook sets it (the
    // wedge's H cut after a "−" that sat past a phone's edge)
    if ((c === "+" || c === "-") && top && binaryAt(out)) {
      out += `\\allowbreak ${c}\\nobreak `;
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

const FRAC = /\\d?frac(?![a-zA-Z])/y;

/** The end of the group in braces opening at ``i`` (row[i] === "{"): the index of its closing brace, or -1. */
function groupEnd(row, i) {
  let depth = 0;
  for (let j = i; j < row.length; j++) {
    if (row[j] === "\\") j += 1;
    else if (row[j] === "{") depth += 1;
    else if (row[j] === "}" && --depth === 0) return j;
  }
  return -1;
}

export function fractionRow(row) {
  const t = row.trim();
  let braces = 0;
  let brackets = 0; // \left … \right: a fraction inside brackets is not the row's
  let best = null;
  for (let i = 0; i < t.length; i++) {
    const c = t[i];
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    else if (c === "\\") {
      if (/^\\left(?![a-zA-Z])/.test(t.slice(i))) brackets += 1;
      else if (/^\\right(?![a-zA-Z])/.test(t.slice(i))) brackets -= 1;
      FRAC.lastIndex = i;
      if (braces === 0 && brackets === 0 && FRAC.test(t) && t[FRAC.lastIndex] === "{") {
        const numEnd = groupEnd(t, FRAC.lastIndex);
        const denEnd = numEnd > 0 && t[numEnd + 1] === "{" ? groupEnd(t, numEnd + 1) : -1;
        if (denEnd > 0) {
          // the widest: the one with the longest numerator (its numerator is what breaks over lines)
          const f = {
            before: t.slice(0, i), num: t.slice(FRAC.lastIndex + 1, numEnd), den: t.slice(numEnd + 2, denEnd),
            after: t.slice(denEnd + 1),
          };
          if (!best || f.num.length > best.num.length) best = f;
          i = denEnd;
          continue;
        }
      }
      i += 1;
    }
  }
  return best;
}

export function numeratorTerms(num) {
  // a numerator already set on lines (an aligned block, continuations after \quad) is one sum again
  const whole = alignedRows(num.trim()).map((r) => r.replace(/^\\q?quad(?![a-zA-Z])/, "").trim()).join(" ");
  const terms = [];
  let term = "";
  let braces = 0;
  let brackets = 0; // \left … \right: never split inside
  for (let i = 0; i < whole.length; i++) {
    const c = whole[i];
    if (c === "\\") {
      const word = /^\\([a-zA-Z]+|.)/.exec(whole.slice(i))?.[0] ?? c;
      if (word === "\\left") brackets += 1;
      else if (word === "\\right") brackets -= 1;
      term += word;
      i += word.length - 1;
      continue;
    }
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    // a sign between two terms (not the first term's own sign, nor one after a relation or an opening bracket)
    if ((c === "+" || c === "-") && braces === 0 && brackets === 0 && /[^\s=(\[{,]\s*$/.test(term)) {
      terms.push(term.trim());
      term = "";
    }
    term += c;
  }
  if (term.trim()) terms.push(term.trim());
  return terms;
}

/** The terms in ``lines`` groups, in order, each about an equal share of the widths given (one per term). */
function groupsOf(terms, widths, lines) {
  const total = widths.reduce((a, b) => a + b, 0);
  const groups = [];
  let group = [];
  let done = 0;
  terms.forEach((term, k) => {
    // a new line once this one has its share and enough terms are left for the lines still to come
    const share = (total * (groups.length + 1)) / lines;
    const left = terms.length - k;
    if (group.length && (done + widths[k] / 2 > share || left === lines - groups.length - 1)) {
      groups.push(group);
      group = [];
    }
    group.push(term);
    done += widths[k];
  });
  groups.push(group);
  return groups;
}

export function stackedFraction(f, lines, widths = null) {
  const terms = numeratorTerms(f.num);
  const groups = groupsOf(terms, widths ?? terms.map((t) => t.length), Math.min(lines, terms.length));
  // as Morin sets a numerator on a narrow page: each line under the first, beginning with its sign (no indent, which
  // the engine's desktop form gives its second line: a phone has no room for it)
  const rows = groups.map((g) => `&${g.join(" ")}`);
  return `${f.before}\\frac{\\begin{aligned}${rows.join(" \\\\ ")}\\end{aligned}}{${f.den}}${f.after ?? ""}`;
}

/** The components of a bracket's inside, split at its commas at the top level (not inside braces or inner
 *  brackets). */
function components(inside) {
  const parts = [];
  let part = "";
  let braces = 0;
  let brackets = 0;
  for (let i = 0; i < inside.length; i++) {
    const c = inside[i];
    if (c === "\\") {
      const word = /^\\([a-zA-Z]+|.)/.exec(inside.slice(i))?.[0] ?? c;
      if (word === "\\left") brackets += 1;
      else if (word === "\\right") brackets -= 1;
      part += word;
      i += word.length - 1;
      continue;
    }
    if (c === "{") braces += 1;
    else if (c === "}") braces -= 1;
    if (c === "," && braces === 0 && brackets === 0) {
      parts.push(part.trim());
      part = "";
      continue;
    }
    part += c;
  }
  parts.push(part.trim());
  return parts;
}

export function vectorRow(row) {
  const t = row.trim();
  const close = "\\right)";
  if (!t.endsWith(close)) return null;
  // the \left( that the row's last \right) closes
  let depth = 0;
  for (let i = t.length - close.length; i >= 0; i--) {
    if (t.startsWith("\\right", i) && !/[a-zA-Z]/.test(t[i + 6] ?? "")) depth += 1;
    else if (t.startsWith("\\left", i) && !/[a-zA-Z]/.test(t[i + 5] ?? "")) {
      depth -= 1;
      if (depth === 0) {
        const before = t.slice(0, i);
        // a vector given by its components after a relation (\vec r = (…)), not a product's bracket (m (a + b))
        if (t[i + 5] !== "(" || !/=\s*$/.test(before)) return null;
        const parts = components(t.slice(i + 6, t.length - close.length));
        return parts.length > 1 && parts.every(Boolean) ? { before, parts } : null;
      }
    }
  }
  return null;
}

export function columnVector(v) {
  // as a textbook sets a vector on a narrow page: a column, its components one under the other
  return `${v.before}\\begin{pmatrix}${v.parts.join(" \\\\ ")}\\end{pmatrix}`;
}

/** A line still wider than its box, ending in a fraction: its numerator on as few lines as make it fit (each
 *  term's width measured as KaTeX sets it), on one term a line at most. */
function stackFraction(line, row, katex, loose = true) {
  const f = fractionRow(row);
  if (!f) return;
  const terms = numeratorTerms(f.num);
  const had = alignedRows(f.num.trim()).length;
  if (terms.length <= had) return;
  const probe = document.createElement("span");
  probe.style.cssText = "position:absolute;visibility:hidden;white-space:nowrap";
  line.append(probe);
  const widths = terms.map((t) => {
    katex.render(`\\displaystyle ${t}`, probe, { displayMode: false, throwOnError: false });
    return probe.getBoundingClientRect().width;
  });
  probe.remove();
  for (let n = had + 1; n <= terms.length; n++) {
    katex.render(`\\displaystyle ${breakable(stackedFraction(f, n, widths), loose)}`, line, {
      displayMode: false,
      throwOnError: false,
    });
    if (line.scrollWidth <= line.clientWidth + 1) return;
  }
}

export function breakDisplay(el, katex) {
  const tex = el.dataset.tex;
  if (!tex || !katex) return false;
  // a formula broken for a narrower box is typeset whole again first: it may fit now
  const whole = (t) => katex.render(spacedRows(t), el, { displayMode: true, throwOnError: false });
  const fits = () => el.scrollWidth <= el.clientWidth + 1;
  // the engine broke long sums by a count of characters, before the page knew its width: joined again where the
  // one line fits (F3: the rotating parabola's L′ with "− m g z" alone on a second line of a wide page)
  const joined = joinedRows(tex);
  if (joined !== tex) {
    whole(joined);
    if (fits() && !el.querySelector(".katex-error")) {
      delete el.dataset.broken;
      return false;
    }
    whole(tex);
  } else if (el.dataset.broken) {
    // a formula broken for a narrower box is typeset whole again first: it may fit now
    whole(tex);
  }
  delete el.dataset.broken;
  if (fits() || el.querySelector(".katex-error")) return false;
  el.textContent = "";
  // too wide as the engine broke it too: each row whole (its continuation lines joined), broken by KaTeX where
  // this box needs, rather than a line the engine broke for another width ("− m g z" alone after a gap)
  for (const row of alignedRows(joined)) {
    const line = document.createElement("div");
    line.className = "math-line";
    // a row holding a fraction keeps a clear gap from its neighbours (site.css), as spacedRows gives a
    // display typeset whole
    if (/\\d?frac(?![a-zA-Z])/.test(row)) line.classList.add("has-fraction");
    katex.render(`\\displaystyle ${breakable(row)}`, line, { displayMode: false, throwOnError: false });
    el.append(line);
    // a row wider than the box however it breaks before its relations: then after them as well, rather than
    // a box that scrolls sideways
    if (line.scrollWidth > line.clientWidth + 1) {
      katex.render(`\\displaystyle ${breakable(row, true)}`, line, { displayMode: false, throwOnError: false });
    }
    // still wider, a row ending in a tall fraction (the double pendulum's θ̈₁ on a phone): its numerator over
    // more lines
    if (line.scrollWidth > line.clientWidth + 1) stackFraction(line, row, katex);
    // still wider, a vector written across (the rolling cylinder's r⃗_cm on a phone): set as a column
    const vector = line.scrollWidth > line.clientWidth + 1 ? vectorRow(row) : null;
    if (vector) {
      // beside its name (v⃗ = ⎛…⎞) where that fits, else the column under it (a phone too narrow for both)
      katex.render(`\\displaystyle ${breakable(columnVector(vector))}`, line, { displayMode: false, throwOnError: false });
      const wide = line.scrollWidth > line.clientWidth + 1;
      if (wide) katex.render(`\\displaystyle ${columnVector(vector)}`, line, { displayMode: false, throwOnError: false });
    }
    // still wider: a relation that continues the equation may end a line too (the break after it), kept only where
    // that is narrower (a line's "=" at its end is better than a box that scrolls further)
    else if (line.scrollWidth > line.clientWidth + 1) {
      const kept = line.innerHTML, width = line.scrollWidth;
      katex.render(`\\displaystyle ${breakable(row, "after")}`, line, { displayMode: false, throwOnError: false });
      if (line.scrollWidth > line.clientWidth + 1) stackFraction(line, row, katex, "after");
      if (line.scrollWidth >= width) line.innerHTML = kept;
    }
  }
  if (el.querySelector(".katex-error")) {
    katex.render(spacedRows(tex), el, { displayMode: true, throwOnError: false });
    return false;
  }
  el.dataset.broken = "true";
  return true;
}
