/**
 * answer-box.js — the one box an answer is typed in: a practice step's, its follow-up question's and a class
 * page's step.  A one-line input scrolls a long answer sideways on a phone and hides its start;
 * this box is a textarea of one line that grows to as many lines as the answer needs, so all of it shows.
 * Enter checks, as it did in the one-line input (``onEnter``, by default the box's form is submitted); a line
 * break pasted in becomes a space, as the parser reads one, so nothing typed is lost.
 */

/** Grow (or shrink) the box to its text's lines. */
export function fit(box) {
  box.style.height = "auto";
  const border = box.offsetHeight - box.clientHeight;
  box.style.height = `${box.scrollHeight + border}px`;
}

/** A new answer box with ``attributes`` (id, name, aria-describedby, …). */
export function answerBox(attributes = {}, onEnter = null) {
  const box = document.createElement("textarea");
  box.rows = 1;
  box.className = "answer-box";
  for (const [k, v] of Object.entries({ autocomplete: "off", spellcheck: "false", autocapitalize: "off", enterkeyhint: "done", ...attributes })) {
    box.setAttribute(k, v);
  }
  box.addEventListener("keydown", (event) => {
    if (event.key !== "Enter" || event.isComposing) return;
    event.preventDefault();
    if (onEnter) onEnter();
    else box.form?.requestSubmit();
  });
  box.addEventListener("input", () => {
    if (/[\r\n]/.test(box.value)) {
      const at = box.selectionStart;
      box.value = box.value.replace(/\r\n|[\r\n]/g, " ");
      box.setSelectionRange(at, at);
    }
    fit(box);
  });
  // the width it is laid out at (a phone turned, the page's first layout) changes its lines; its own height,
  // which fit sets, does not (so no loop of observations)
  let width = -1;
  if (typeof ResizeObserver !== "undefined") {
    new ResizeObserver(([entry]) => {
      if (entry.contentRect.width === width) return;
      width = entry.contentRect.width;
      fit(box);
    }).observe(box);
  }
  return box;
}
