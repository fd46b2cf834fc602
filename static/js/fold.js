/**
 * fold.js — on a phone the plot panels sit right under the animation, each folded to its title and one line.
 *
 *   foldPanels(root)     on a narrow screen (PHONE), every panel of root's .panels gets a button in its
 *                        heading (aria-expanded) and starts folded: its title and the first line of its
 *                        explanation show, the plot does not; a tap unfolds it.  On a wider screen the
 *                        buttons go and every panel shows in full (a phone turned sideways, a resized window).
 *   isFolded(section)    whether a panel is folded now (a folded panel is not drawn: it has no size)
 *
 * Unfolding dispatches "lagrange:unfold" on the section (it bubbles): the drawing code (simulation.js,
 * plotkit.js drawWhenVisible) draws a panel that is near the viewport once it is no longer folded.
 * site.css holds the folded look (phone only).
 */
export const PHONE = "(max-width: 40rem)";

// (outside a browser, as when node imports a module for its tests, nothing is a phone)
const phone = globalThis.window?.matchMedia ? window.matchMedia(PHONE) : { matches: false, addEventListener() {} };

export function isFolded(section) {
  return phone.matches && section.classList.contains("folded");
}

function unfold(section) {
  section.dispatchEvent(new CustomEvent("lagrange:unfold", { bubbles: true }));
}

function addButton(section) {
  const heading = section.querySelector(":scope > h3");
  if (!heading || heading.querySelector("button.fold")) return;
  const button = document.createElement("button");
  button.type = "button";
  button.className = "fold";
  button.setAttribute("aria-expanded", "false");
  button.append(...heading.childNodes);
  heading.append(button);
  section.classList.add("folded");
  button.addEventListener("click", () => {
    const open = section.classList.toggle("folded") === false;
    button.setAttribute("aria-expanded", String(open));
    if (open) unfold(section);
  });
}

function removeButton(section) {
  const button = section.querySelector(":scope > h3 > button.fold");
  if (button) button.replaceWith(...button.childNodes);
  if (section.classList.contains("folded")) { section.classList.remove("folded"); unfold(section); }
}

export function foldPanels(root = document) {
  const sections = () => root.querySelectorAll(".panels > section.panel");
  const apply = () => {
    for (const section of sections()) (phone.matches ? addButton : removeButton)(section);
  };
  apply();
  phone.addEventListener("change", apply);
}
