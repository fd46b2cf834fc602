/**
 * prose.js — a symbol's subscript in a sentence the browser composes, set as the server sets it
 * (app/web/rendering/prose.py, the rule's home): U_eff -> U<sub>eff</sub>, p_θ -> p<sub>θ</sub>, U_eff'' -> U<sub>eff</sub>″.
 *
 *   import { proseHTML, setProse } from "/static/js/prose.js";
 *   setProse(element, "p_θ stays at 1 kg·m²/s.");   // escapes, then sets the subscripts
 *   proseHTML("U_eff (J)")                           // for Plotly's legend and axis titles, which read <sub>
 */

const SUBSCRIPTED = /(?<![A-Za-z0-9_Α-Ωα-ω]{2})([A-Za-zΑ-Ωα-ω][\u0300-\u036f]?)_([A-Za-z0-9Α-Ωα-ω₀-₉\u0300-\u036f]+)(''|'|″|′)?/g;
const PRIMES = { "''": "″", "'": "′", "″": "″", "′": "′" };

const escapeHTML = (s) => String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);

/** HTML of ``text``: escaped, each subscript as <sub>; a prime is read before escaping turns ' into &#39;. */
export function proseHTML(text) {
  const s = String(text ?? "");
  let out = "";
  let at = 0;
  for (const m of s.matchAll(SUBSCRIPTED)) {
    const [whole, stem, sub, prime] = m;
    out += `${escapeHTML(s.slice(at, m.index))}${escapeHTML(stem)}<sub>${escapeHTML(sub)}</sub>${PRIMES[prime] ?? ""}`;
    at = m.index + whole.length;
  }
  return out + escapeHTML(s.slice(at));
}

/** Put ``text`` into ``element`` as a sentence with its subscripts set. */
export function setProse(element, text) {
  element.innerHTML = proseHTML(text);
}

/**
 * A panel's readout whose sentences set their subscripts: after ``proseReadout(el)``, ``el.textContent = s``
 * shows ``s`` as ``setProse`` would, and reading ``el.textContent`` gives the text as shown (p<sub>θ</sub> reads "pθ").
 */
export function proseReadout(element) {
  if (!element) return element;
  const text = Object.getOwnPropertyDescriptor(Node.prototype, "textContent");
  Object.defineProperty(element, "textContent", {
    configurable: true,
    get() { return text.get.call(this); },
    set(value) { this.innerHTML = proseHTML(value); },
  });
  return element;
}

// a formula quoted in words stands alone: not a letter of a longer word, nor the T of "T's"
const EDGE_BEFORE = "(?<![\\p{L}\\p{N}\\p{M}_'])";
const EDGE_AFTER = "(?![\\p{L}\\p{N}\\p{M}_'′″⁰¹²³⁴⁵⁶⁷⁸⁹₀-₉])";
const escapeRegExp = (s) => s.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");

/**
 * A verdict's sentence cut into its words and the formulas it quotes (``formulas``: the verdict's own list, each
 * {text, latex}, longest first, app/engine/tutor/spoken_tex.py): [{text}, {latex, text}, {text}, …] in order.
 */
export function proseParts(text, formulas = []) {
  let parts = [{ text: String(text ?? "") }];
  for (const f of formulas || []) {
    if (!f?.text || !f.latex) continue;
    const at = new RegExp(`${EDGE_BEFORE}${escapeRegExp(f.text)}${EDGE_AFTER}`, "gu");
    parts = parts.flatMap((part) => {
      if (part.latex !== undefined) return [part];
      const out = [];
      let from = 0;
      for (const m of part.text.matchAll(at)) {
        out.push({ text: part.text.slice(from, m.index) }, { latex: f.latex, text: f.text });
        from = m.index + m[0].length;
      }
      out.push({ text: part.text.slice(from) });
      return out.filter((p) => p.latex !== undefined || p.text);
    });
  }
  // a parenthesis the words open against a formula is set with it, so that a line never ends on "("
  parts.forEach((part, k) => {
    const before = parts[k - 1];
    if (part.latex !== undefined && before?.latex === undefined && before?.text.endsWith("(")) {
      before.text = before.text.slice(0, -1);
      part.latex = `(${part.latex}`;
      part.text = `(${part.text}`;
    }
  });
  return parts.filter((p) => p.latex !== undefined || p.text);
}

/** Put a verdict's sentence into ``element``: its formulas typeset (KaTeX, math italic, as the answer's own
 * formulas are; the text as printed where KaTeX is not loaded), its words with their subscripts set. */
export function setMathProse(element, text, formulas = []) {
  element.replaceChildren();
  for (const part of proseParts(text, formulas)) {
    const span = document.createElement("span");
    if (part.latex !== undefined && window.katex) {
      span.className = "prose-math";
      span.dataset.text = part.text; // the words as printed, for a copy or a test that reads them
      window.katex.render(part.latex, span, { throwOnError: false });
    } else {
      span.innerHTML = proseHTML(part.text);
    }
    element.append(span);
  }
  return element;
}
