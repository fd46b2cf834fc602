/**
 * action-focus.js — what the action panel says about the kinetic focus and the kind of S at ε = 0
 * (static/js/action.js prints it; tests/web/test_focus_words.py runs it in node on the server's answers).
 *
 *   focusSentences(s)   {verdict, focus, marks}: the kind of the true path for the variations on screen,
 *                       the focus of those variations and of all coordinates varied together, and the
 *                       marks for the time axis
 *
 * Every sentence names its family of variations.  The panel varies one coordinate c alone (the others kept on
 * the true path); its focus t_c comes at the first focus t* of all coordinates varied together or later, or
 * never (the tabletop's θ: L does not depend on θ).  Before t* the true path is a minimum of S among every
 * variation with the same ends; between t* and t_c it is a minimum among the variations of c alone but not of S;
 * past t_c some variation of c alone lowers S.
 */
import { fmt } from "./summaries.js";

const known = (x) => x !== null && x !== undefined;

/** "θ₁ and θ₂", "x, y and z". */
function together(labels) {
  return labels.length <= 2 ? labels.join(" and ") : `${labels.slice(0, -1).join(", ")} and ${labels[labels.length - 1]}`;
}

/**
 * s: {labels: every coordinate's label, c: the varied one's index, T: τ, tEnd: the run's end, tAll: the first
 * focus of all coordinates together (null: none before tEnd), tAlone: the varied coordinate's own (null: none
 * before tEnd), kind: "minimum" | "saddle" | "maximum" on the sine shapes of c, never: no focus at any τ,
 * lowering: the sentence naming the shape that lowers S (for a saddle)}.
 */
export function focusSentences(s) {
  const { labels, c, T, tEnd, kind, never } = s;
  const n = labels.length, label = labels[c];
  const tAll = known(s.tAll) ? s.tAll : null;
  // with one coordinate its variations are all the variations: one focus
  const tAlone = n === 1 ? tAll : known(s.tAlone) ? s.tAlone : null;
  const others = together(labels.filter((_, i) => i !== c));
  const all = together(labels);
  const alone = n === 1 ? `the variations of ${label}` : `the variations of ${label} alone (${others} kept on the true path)`;
  const tau = `With τ = ${fmt(T)} s`;
  const marked = (t) => (t <= T ? ", marked on the time axis" : "");
  const marks = [];
  if (never) {
    return {
      verdict: kind === "minimum" ? `${tau} the true path is a minimum of S: every variation with the same ends raises it.`
        : `${tau} every variation of ${label} tried lowers S: the true path is a maximum among them.`,
      focus: "No true path of this system reaches a kinetic focus, at any τ, whatever coordinates are varied: L is at most linear in the coordinates and its mass matrix is constant.",
      marks,
    };
  }
  // the focus of the family on screen, then (with several coordinates) the one of all of them together
  let focus;
  if (n === 1) {
    focus = tAll === null
      ? `For ${alone} no kinetic focus comes before ${fmt(tEnd)} s, the end of the run.`
      : `For ${alone} the first kinetic focus (conjugate point) of this start is at t* = ${fmt(tAll)} s${marked(tAll)}.`;
  } else {
    focus = tAlone === null
      ? `For ${alone} no kinetic focus comes before ${fmt(tEnd)} s, the end of the run.`
      : `For ${alone} the first kinetic focus (conjugate point) of this start is at ${fmt(tAlone)} s${marked(tAlone)}.`;
    if (tAll === null) focus += ` For ${all} varied together none comes before then either.`;
    else if (tAlone !== null && Math.abs(tAlone - tAll) <= 1e-6 * tAll) focus += ` For ${all} varied together it comes at the same time.`;
    else {
      const later = tAlone === null || tAlone > tAll;
      focus += ` For ${all} varied together the first comes ${later ? "earlier, " : ""}at t* = ${fmt(tAll)} s${marked(tAll)}.`;
    }
  }
  if (tAll !== null && tAll <= T) marks.push({ t: tAll, text: n === 1 ? "kinetic focus t*" : `focus: ${all} together` });
  if (n > 1 && tAlone !== null && tAlone <= T && !(tAll !== null && Math.abs(tAlone - tAll) <= 1e-6 * tAll)) {
    marks.push({ t: tAlone, text: `focus: ${label} alone` });
  }
  const pastAll = tAll !== null && tAll < T, pastAlone = tAlone !== null && tAlone < T;
  const family = n === 1 ? "" : ` of ${label} alone`;
  let verdict;
  if (kind === "minimum" && !pastAll) {
    verdict = `${tau}, before any kinetic focus, the true path is a minimum of S: every variation with the same ends raises it.`;
  } else if (kind === "minimum" && !pastAlone) {
    // between t* and the varied coordinate's own focus: a minimum among the variations on screen only
    verdict = `${tau} the true path is a minimum among the variations of ${label} alone, as S(ε) shows, but not a minimum `
      + `of S: τ is past t* = ${fmt(tAll)} s, the first kinetic focus of ${all} varied together, and a variation that moves ${others} too lowers S.`;
  } else if (kind === "minimum") {
    // past the family's own focus, yet every sine shape tried raises S: the lowering variation is not among them
    verdict = `${tau}, past the kinetic focus${family}, the true path is no longer a minimum of S, though the sine shapes tried `
      + `all raise it. Jacobi's theorem gives a variation${family} with the same ends that lowers S (the Jacobi field that vanishes at 0 `
      + "and at the focus, bent a little), and it is not among these shapes. “Find the path” and then Relax count the directions "
      + "of change that lower the discrete action. S is still stationary: its tangent at ε = 0 stays flat.";
  } else if (kind === "saddle") {
    verdict = `${tau}, past the kinetic focus${family}, the true path is no longer a minimum of S: it is a saddle. ${s.lowering} `
      + "S is still stationary: its tangent at ε = 0 stays flat.";
  } else {
    verdict = `${tau} every variation${family} tried lowers S: the true path is a maximum among them.`;
  }
  return { verdict, focus, marks };
}
