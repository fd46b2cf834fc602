/**
 * controls.js — the parameter and initial-condition controls of a simulation.
 *
 * Markup (rendered by templates/_controls.html):
 *   <div class="control" data-group="parameters|initial|run" data-name="m"
 *        data-min="0.01" data-max="100" data-log="true" data-default="1">
 *     <label id="ctl-m-label" for="ctl-m-range">…</label>
 *     <input type="range" id="ctl-m-range" …> <input type="number" id="ctl-m" …>
 *     <p class="hint" id="ctl-m-hint">allowed: 0.01 to 100 kg</p>
 *   </div>
 * plus <select name="method"> and <select name="rtol">.
 *
 *   bindControls(form, handlers)     keep each slider and number field in step, check
 *                                    ranges (aria-invalid + message); onInput(request) on
 *                                    every change, onSettle(request) 150 ms after the last
 *   readRequest(form)                the simulate request body {parameters, initial, t_end, method, rtol}
 *   resetControls(form)              back to the defaults
 *
 * The slider covers a useful range inside the allowed one (data-slider-min/-max; the number
 * field takes any allowed value), on a log scale when that range spans decades; on a log
 * slider whose allowed range starts at 0 the first position is 0 itself.  Its aria-valuetext
 * always reads the real value with its unit.  Marks (a <datalist>, e.g. critical damping) sit
 * at their values.  Arrow keys move a slider by 1/200 of its range (Shift with them: 1/20), Page Up/Down by 1/10.
 */

// A slider's positions run from 0 to its max, which the server sets (app/viz/page_model.py SLIDER_STEPS).
const stepsOf = (ctl) => Number(ctl.querySelector('input[type="range"]').max);

function sliderRange(ctl) {
  const lo = Number(ctl.dataset.sliderMin ?? ctl.dataset.min), hi = Number(ctl.dataset.sliderMax ?? ctl.dataset.max);
  return [lo, hi, ctl.dataset.log === "true" && lo > 0, Number(ctl.dataset.min) === 0];
}

function fromSlider(ctl, position) {
  const [lo, hi, log, zero] = sliderRange(ctl);
  const u = Number(position) / stepsOf(ctl);
  if (log) return zero && Number(position) === 0 ? 0 : lo * Math.pow(hi / lo, u);
  return lo + (hi - lo) * u;
}

function toSlider(ctl, value) {
  const [lo, hi, log, zero] = sliderRange(ctl);
  if (log && zero && value < lo) return 0;
  const v = Math.min(hi, Math.max(lo, value));
  const u = log ? Math.log(v / lo) / Math.log(hi / lo) : (v - lo) / (hi - lo);
  return Math.round(u * stepsOf(ctl));
}

/** Arrow keys step a slider by a sensible share of its range, not by one of its many positions: a fine
 * step (1/200 of the range), Shift with it a coarse one (1/20), Page Up/Down 1/10. */
function stepKeys(ctl, range) {
  range.addEventListener("keydown", (event) => {
    const steps = stepsOf(ctl), arrow = event.shiftKey ? steps / 20 : steps / 200, page = steps / 10;
    const by = { ArrowRight: arrow, ArrowUp: arrow, ArrowLeft: -arrow, ArrowDown: -arrow, PageUp: page, PageDown: -page }[event.key];
    if (by === undefined) return;
    event.preventDefault();
    range.value = String(Math.min(steps, Math.max(0, Number(range.value) + by)));
    range.dispatchEvent(new Event("input", { bubbles: true }));
  });
}

/** Put the marks of a control's datalist at their values on its slider (again when separatrix.js changes them). */
export function placeTicks(ctl) {
  const list = ctl.querySelector("datalist");
  if (!list) return;
  for (const option of list.querySelectorAll("option")) option.value = String(toSlider(ctl, Number(option.dataset.value)));
}

/** A value rounded for display: 4 significant digits, no trailing zeros. */
export function tidy(x) {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return "0";
  return String(Number(x.toPrecision(4)));
}

function parts(ctl) {
  return {
    range: ctl.querySelector('input[type="range"]'),
    number: ctl.querySelector('input[type="number"]'),
    hint: ctl.querySelector(".hint"),
  };
}

/**
 * A number read from a control's box: one that prints as a bound (3.142 for π) is that bound, since the box holds
 * values rounded to 4 figures (tidy): the slider's own end, put in the box as 3.142, was refused as beyond π.
 */
export function snapToBounds(value, lo, hi) {
  for (const bound of [lo, hi]) if (Number.isFinite(value) && Number.isFinite(bound) && tidy(value) === tidy(bound)) return bound;
  return value;
}

function readValue(ctl) {
  return snapToBounds(Number(parts(ctl).number.value), Number(ctl.dataset.min), Number(ctl.dataset.max));
}

function check(ctl) {
  const { number, hint } = parts(ctl);
  const value = readValue(ctl);
  const lo = Number(ctl.dataset.min), hi = Number(ctl.dataset.max);
  const unit = ctl.dataset.unit ? ` ${ctl.dataset.unit}` : "";
  const ok = number.value.trim() !== "" && Number.isFinite(value) && value >= lo && value <= hi;
  number.setAttribute("aria-invalid", ok ? "false" : "true");
  ctl.classList.toggle("invalid", !ok);
  // the server's words for the range ("more than 0, up to 10 kg") where it gave them
  const range = ctl.dataset.allowed || `${tidy(lo)} to ${tidy(hi)}${unit}`;
  // a slider narrower than what may be typed says both ("slider: 1 to 1,000 N/m; type any value from …")
  hint.textContent = ok
    ? ctl.dataset.hint || `allowed: ${range}`
    : `${ctl.dataset.label || ctl.dataset.name} must be a number ${
        ctl.dataset.allowed && lo > 0 && lo <= 1e-6 ? range : `from ${tidy(lo)} to ${tidy(hi)}${unit}`}`;
  return ok;
}

function setValueText(ctl, value) {
  const { range } = parts(ctl);
  range.setAttribute("aria-valuetext", `${tidy(value)}${ctl.dataset.unit ? " " + ctl.dataset.unit : ""}`);
}

function setValue(ctl, value) {
  const { range, number } = parts(ctl);
  number.value = tidy(value);
  range.value = String(toSlider(ctl, value));
  setValueText(ctl, value);
  check(ctl);
}

export function readRequest(form) {
  const request = { parameters: {}, initial: {} };
  for (const ctl of form.querySelectorAll(".control")) {
    const value = readValue(ctl);
    const group = ctl.dataset.group;
    if (group === "parameters") request.parameters[ctl.dataset.name] = value;
    else if (group === "initial") request.initial[ctl.dataset.name] = value;
    else request[ctl.dataset.name] = value;
  }
  const method = form.querySelector('select[name="method"]');
  if (method) request.method = method.value;
  const rtol = form.querySelector('select[name="rtol"]');
  if (rtol) request.rtol = Number(rtol.value);
  return request;
}

export function resetControls(form) {
  for (const ctl of form.querySelectorAll(".control")) setValue(ctl, Number(ctl.dataset.default));
  for (const sel of form.querySelectorAll("select[data-default]")) sel.value = sel.dataset.default;
}

/** Set one control by name (e.g. "theta" for an initial angle); returns false if absent. */
export function setControl(form, name, value) {
  const ctl = form.querySelector(`.control[data-name="${CSS.escape(name)}"]`);
  if (!ctl) return false;
  setValue(ctl, value);
  return true;
}

/**
 * Bind the controls.  handlers: {onInput(request), onSettle(request), onInvalid(message)}
 * (a bare function is onSettle).  Every change of a value calls onInput at once (the live
 * preview) and onSettle `delay` ms after the last change (the server's run); a method,
 * tolerance, submit or reset settles at once.  An invalid value calls onInvalid with what
 * is wrong instead.  Returns {fire(now), set(values)}: set({name: value, ...}) moves
 * controls as if the user had (dragging a body in the animation does this).
 */
/** How long an input rests (ms) before it counts as settled: the server's run is asked for then, and the panels
 *  that follow only a resting input (the action panel) follow then too. */
export const SETTLE_MS = 150;

export function bindControls(form, handlers, delay = SETTLE_MS) {
  const { onInput = null, onSettle = () => {}, onInvalid = () => {} } =
    typeof handlers === "function" ? { onSettle: handlers } : handlers;
  let timer = null;
  const fire = (now, preview = true) => {
    clearTimeout(timer);
    const bad = [...form.querySelectorAll(".control")].filter((ctl) => !check(ctl));
    if (bad.length) {
      onInvalid(bad.map((ctl) => parts(ctl).hint.textContent).join("; "));
      return;
    }
    const request = readRequest(form);
    if (preview && onInput) onInput(request);
    timer = setTimeout(() => onSettle(readRequest(form)), now ? 0 : delay);
  };
  for (const ctl of form.querySelectorAll(".control")) {
    const { range, number } = parts(ctl);
    range.value = String(toSlider(ctl, Number(number.value)));
    setValueText(ctl, Number(number.value));
    check(ctl);
    placeTicks(ctl);
    stepKeys(ctl, range);
    range.addEventListener("input", () => {
      const value = fromSlider(ctl, range.value);
      number.value = tidy(value);
      setValueText(ctl, value);
      check(ctl);
      fire(false);
    });
    number.addEventListener("input", () => {
      if (check(ctl)) {
        range.value = String(toSlider(ctl, Number(number.value)));
        setValueText(ctl, Number(number.value));
      }
      fire(false);
    });
    number.addEventListener("change", () => fire(true, false));
  }
  // a setting's select has a name (method, rtol); a select without one (the course-page frame's plot) is not a run's
  for (const sel of form.querySelectorAll("select[name]")) sel.addEventListener("change", () => fire(true, false));
  form.addEventListener("submit", (event) => { event.preventDefault(); fire(true, false); });
  const reset = form.querySelector('[data-action="reset"]');
  if (reset) reset.addEventListener("click", () => { resetControls(form); fire(true); });
  const set = (values) => {
    for (const [name, value] of Object.entries(values)) {
      const ctl = form.querySelector(`.control[data-name="${CSS.escape(name)}"]`);
      if (ctl) setValue(ctl, value);
    }
    fire(false);
  };
  return { fire, set };
}

/** The value and range of a control by name ({value, min, max}), or null. */
export function controlRange(form, name) {
  const ctl = form.querySelector(`.control[data-name="${CSS.escape(name)}"]`);
  if (!ctl) return null;
  return { value: Number(parts(ctl).number.value), min: Number(ctl.dataset.min), max: Number(ctl.dataset.max) };
}
