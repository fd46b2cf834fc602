/**
 * verdict-words.js — the words of a checked step, in one home for a scene page's practice mode (practice.js)
 * and a class page (join.js): the same answer gets the same verdict, named mistake, reason and refusal, worded
 * and punctuated the same, on both pages; and each answer box says what it takes in the same words.
 */

// the verdict's own word, where a message does not open with it
const LABELS = { correct: "Correct", equivalent: "Equivalent", incorrect: "Not yet" };

// what each box takes (app/engine/tutor/answer_sides.py): an equation as a textbook writes it, else the right-hand side
const HOW = {
  equation: "Type the equation as lhs = rhs, or as one expression equal to zero.",
  acceleration: "Type {a} = … ({a} is typed {q}_ddot), or only the right-hand side.",
  other: "Type only the right-hand side.",
};

/** What a box takes, said above its names: "Type only the right-hand side."; its note (how to write a position)
 * first, unless ``withNote`` is false (the page then folds the note, said in full on an earlier box). */
export function howTo(exercise, withNote = true) {
  // the acceleration as the page prints it (θ̈), its typed spelling once
  const how = (HOW[exercise.step] || HOW.other).replaceAll("{a}", exercise.acceleration || "q̈").replace("{q}", exercise.coordinate || "q");
  return `${exercise.note && withNote ? `${exercise.note} ` : ""}${how}`;
}

/** The names a box's answer may use, as the page prints them with how each is typed once: "θ̇ (type theta_dot)". */
export function namesSaid(exercise) {
  return (exercise.names_said || exercise.names).join(", ");
}

/** The rule the reader applies to numbered names, said as the checker applies it: m_1 is read as m1. */
export function numbered(names) {
  const example = names.find((name) => /^[A-Za-z]+\d+$/.test(name));
  if (!example) return "";
  const [, stem, digits] = example.match(/^([A-Za-z]+)(\d+)$/);
  return ` A number may follow a name with or without _ (${example} or ${stem}_${digits}).`;
}

/** A message ended with a full stop (its first word left as the message has it). */
export function endOf(text) {
  return /[.!?]$/.test(text) ? text : `${text}.`;
}

/** A sentence: its first letter a capital when it opens with a word ("a velocity…", "the sign…"), never when
 * it opens with a symbol (α, z, ω², d/dt: capitals would be other symbols), ended with a full stop. */
export function sentenceOf(text) {
  const t = (text || "").trim();
  const word = /^(a|[a-z]{2,})(\s|,|'|’)/.test(t); // a word, or a word's possessive (gravity's)
  return t ? `${word ? t[0].toUpperCase() : t[0]}${t.slice(1)}${/[.!?]$/.test(t) ? "" : "."}` : "";
}

/** A refusal's message without the field it is located at ("answer: …", "text: …"), the box being the field,
 * nor the columns of the parts at fault ("at column 7", "at columns 7 and 13"), nor the part itself quoted in
 * code's quotes at the end (": 'theta'"): both are marked in what was typed, shown under the message. */
export function wordsOf(detail) {
  // (a declared system's refusal is located by a path, system.particles.0.position: the path is not for a student)
  const located = / at columns? \d+(?:(?:, | and )\d+)*/.test(detail || "");
  const words = (detail || "").replace(/^(answer|text|follow_up|coordinate|step|system(\.[\w]+)*): /, "").replace(/ at columns? \d+(?:(?:, | and )\d+)*/g, "");
  return located ? words.replace(/: (?:'[^']*'|"[^"]*")$/, "") : words;
}

/** A verdict's words: its head [the verdict's word with its colon, the rest], the named mistake [label, name]
 * (or null), the reason ("Why: …" after a named mistake, else "Hint: …"; "" if none) and the part-by-part line. */
export function verdictWords(result) {
  const [first, ...rest] = (result.message || "").split(":");
  const head = rest.length ? [`${first}:`, rest.join(":")] : [LABELS[result.verdict] || result.verdict, ` ${first}`];
  const mistake = result.mistake ? [result.mistake.approximation ? "An approximation: " : "The mistake: ", result.mistake.name] : null;
  // after a named mistake, where it comes from (the hint would repeat its name); else the hint
  const why = result.mistake ? sentenceOf(result.mistake.where) : sentenceOf(result.hint);
  const reason = why ? `${result.mistake ? "Why: " : "Hint: "}${why}` : "";
  return { head, mistake, reason, partial: result.partial?.message || "" };
}

/** The correct part a named mistake points at (a denominator, a stretch, a rod's I about its end), kept closed
 * until the student asks for it: the words of its disclosure, {summary: "Show the correct denominator", note:
 * "(up to a constant factor)" or "", latex, text}; null where the verdict has none. The verdict names the place and
 * the kind of slip; "Show this step" stays for giving up. */
export function correctPartWords(result) {
  const part = result.correct_part;
  if (!part || result.verdict !== "incorrect") return null;
  return { summary: `Show the correct ${part.what}`, note: part.note ? `(${part.note})` : "", latex: part.latex, text: part.text || "" };
}

/** A refusal's words, [label, sentence]: "Not checked: " and what was wrong, in the checker's own case after the colon and
 * ended with a full stop; "Busy: " and `busy` (or the server's words) when the server asked to wait. */
export function refusalWords(status, detail, busy = "") {
  if (status === 503 || status === 429) return ["Busy: ", busy || endOf(wordsOf(detail) || "the server is busy")];
  return ["Not checked: ", endOf(wordsOf(detail) || "the answer could not be read")];
}
