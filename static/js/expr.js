/**
 * expr.js — evaluate the expression trees the server sends (app/viz/exprtree.py).
 *
 * A tree is a number, a symbol name (string), or [op, ...args] with op one of
 * "+", "*", "neg", "/", "pow" or a function name (the parser's FUNCTIONS
 * plus sign; atan2 takes two arguments, the others one).  No code is
 * generated or evaluated: a tree compiles to nested closures.
 *
 *   import { compile, evaluate } from "/static/js/expr.js";
 *   const f = compile(tree);          // f(env) -> number, env maps names to numbers
 *   f({ theta: 0.3, R: 1, g: 9.81 });
 *   evaluate(tree, env);              // one-off
 *   seriesOf(tree, envAt, n);         // Float64Array of f(envAt(i)) for i < n
 */

// How the browser computes each function a tree may hold: the parser's allowlist (app/engine/parser/parse.py,
// its one home) plus sign. tests/viz/test_expr_js.py fails if a name there has no implementation here.
const FUNCS = {
  sin: Math.sin, cos: Math.cos, tan: Math.tan, asin: Math.asin, acos: Math.acos, atan: Math.atan,
  sinh: Math.sinh, cosh: Math.cosh, tanh: Math.tanh, exp: Math.exp, log: Math.log, sqrt: Math.sqrt,
  Abs: Math.abs, sign: Math.sign,
  cot: (x) => 1 / Math.tan(x), sec: (x) => 1 / Math.cos(x), csc: (x) => 1 / Math.sin(x), atan2: Math.atan2,
};

export function compile(tree) {
  if (tree === null || tree === undefined) return null;
  if (typeof tree === "number") return () => tree;
  if (typeof tree === "string") {
    const name = tree;
    return (env) => {
      const v = env[name];
      if (v === undefined) throw new Error(`no value for ${name}`);
      return v;
    };
  }
  const [op, ...rest] = tree;
  const args = rest.map(compile);
  switch (op) {
    case "+":
      return (env) => { let s = 0; for (const a of args) s += a(env); return s; };
    case "*":
      return (env) => { let s = 1; for (const a of args) s *= a(env); return s; };
    case "neg":
      return (env) => -args[0](env);
    case "/":
      return (env) => args[0](env) / args[1](env);
    case "pow":
      return (env) => Math.pow(args[0](env), args[1](env));
    default: {
      const f = FUNCS[op];
      if (!f) throw new Error(`unknown function ${op}`);
      if (args.length === 2) return (env) => f(args[0](env), args[1](env));
      return (env) => f(args[0](env));
    }
  }
}

export function evaluate(tree, env) {
  return compile(tree)(env);
}

export function seriesOf(tree, envAt, n) {
  const f = compile(tree);
  const out = new Float64Array(n);
  for (let i = 0; i < n; i++) out[i] = f(envAt(i));
  return out;
}

/** Names a tree refers to (to tell whether it depends on a coordinate). */
export function symbolsOf(tree, into = new Set()) {
  if (typeof tree === "string") into.add(tree);
  else if (Array.isArray(tree)) for (const a of tree.slice(1)) symbolsOf(a, into);
  return into;
}
