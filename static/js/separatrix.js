/**
 * separatrix.js — the marks on the slider of an initial rate q̇(0) where the motion changes kind, kept for
 * the current start q(0) and parameters.
 *
 *   followSeparatrix(form, spec)   returns update(request): the marks and their note for request.initial
 *                                  and request.parameters (spec: the page data's "separatrix", or null)
 *   separatrixMarks(spec, parameters, q0)   [{value, label}], ± each rate
 *
 * The rule and the words are the server's (app/viz/control_ranges.py, separatrix_spec and separatrix_marks):
 * the conserved quantity is the energy function h (E where no constraint moves); at rest it is U_eff, so
 * h = ½ M(q) q̇² + U_eff(q), and from q₀ the rate that just reaches an unstable equilibrium q_top solves
 * ½ M(q₀) q̇₀² = U_eff(q_top) − U_eff(q₀).  Which equilibria are unstable (ω² < 0), and where they sit,
 * are worked out again at the current parameters; with none above the start the note goes.
 */
import { compile } from "./expr.js";
import { placeTicks } from "./controls.js";

const START = "{start}"; // the place in a label where the start's value goes (control_ranges.START)

/** A number as the server's f"{x:.4g}" prints it for the sizes a slider holds. */
const g4 = (x) => String(Number(x.toPrecision(4)));

export function separatrixMarks(spec, parameters, q0) {
  const q = spec.coordinate, rate = `${q}_dot`;
  const h = compile(spec.h), mass = compile(spec.mass);
  const env = (x, v = 0) => ({ ...parameters, t: 0, [q]: x, [rate]: v });
  const value = (f, e) => { try { return f(e); } catch { return NaN; } };
  const h0 = value(h, env(q0)), m0 = value(mass, env(q0));
  const marks = [];
  for (const top of spec.tops) {
    const where = value(compile(top.position), env(0)), w2 = value(compile(top.omega_squared), env(0));
    const level = value(h, env(where));
    // arccos(g/(R w²)) where R w² < g is NaN: no such equilibrium at these parameters
    if (![where, w2, level, h0, m0].every(Number.isFinite) || w2 >= 0 || m0 <= 0 || level <= h0) continue;
    // h(q₀, q̇₀) = ½ M(q₀) q̇₀² + U_eff(q₀) = U_eff(q_top)
    const v = Math.sqrt((2 * (level - h0)) / m0);
    // h is that quadratic in q̇ only where M does not depend on q̇: checked, as the server does
    if (Math.abs(value(h, env(q0, v)) - level) > 1e-9 * Math.max(Math.abs(level), 1e-3)) continue;
    const label = top.label.replace(START, g4(q0));
    marks.push({ value: v, label }, { value: -v, label });
  }
  return marks;
}

export function followSeparatrix(form, spec) {
  if (!spec) return () => {};
  const ctl = form.querySelector(`.control[data-name="${CSS.escape(`${spec.coordinate}_dot`)}"]`);
  if (!ctl) return () => {};
  const range = ctl.querySelector('input[type="range"]');
  let list = ctl.querySelector("datalist");
  let note = ctl.querySelector("p.ticks");
  if (!list) {
    list = Object.assign(document.createElement("datalist"), { id: `${range.id}-ticks` });
    note = Object.assign(document.createElement("p"), { className: "ticks", hidden: true });
    ctl.querySelector(".control-inputs").after(list, note);
  }
  return (request) => {
    const q0 = request.initial[spec.coordinate];
    if (!Number.isFinite(q0)) return;
    const marks = separatrixMarks(spec, request.parameters, q0);
    list.replaceChildren(...marks.map((m) => {
      const option = document.createElement("option");
      option.dataset.value = String(m.value);
      option.label = m.label;
      return option;
    }));
    placeTicks(ctl);
    if (marks.length) range.setAttribute("list", list.id);
    else range.removeAttribute("list");
    // a pair ±v with the same words is said once (page_model._marks)
    const said = marks.filter((m) => m.value > 0).map((m) => `±${g4(m.value)} ${spec.unit} (${m.label})`);
    note.hidden = said.length === 0;
    note.textContent = said.length ? `The slider marks ${said.join("; ")}.` : "";
  };
}
