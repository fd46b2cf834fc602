"""The common mistakes a student makes at each step, as data, and what each one produces.

A mistake is a rule: the steps it concerns, how to build the expression a
student who made it would write (from the engine's own derivation), and the hint
to give when an answer matches it. ``RULES`` is checked in order; the first
match wins. ``POINTERS`` is the general reminder of each step's rule, given
when no known mistake matches.

The mistaken expressions are built from the same objects the engine derives:

* missing ½ in T: 2T (and 2T − U for L);
* speed instead of squared speed: Σ ½ m_i |v_i| (or q̇ in place of q̇²);
* the sign of U: −U (and T + U for L is its own rule);
* a missing cross term: T without its terms of degree 1 in the velocities and
  its products of two different velocities, which a forgotten chain rule drops;
* a force counted twice: the force of U entered again as Q, E_k + ∂U/∂q_k;
* d/dt of ∂L/∂q̇ without its chain-rule terms: Σ_j M_kj q̈_j − ∂L/∂q_k − Q_k;
* a forgotten generalized force: E_k + Q_k; the sign of ∂L/∂q: d/dt ∂L/∂q̇ + ∂L/∂q − Q;
* ω for ω²: √ω²;
* h written as L, or as E = T + U where h ≠ E;

and the accelerations each wrong set of equations would give, M q̈ = f'.
The momentum rule (a missing coordinate-dependent factor such as sin²θ) is not
an expression but a ratio: see ``app.engine.tutor.check``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.derivation.dimensions import STIFFNESS_PLAIN, STIFFNESS_WORDS
from app.engine.document.notation import MASS_INERTIA, Inertia
from app.scenes.types import System


@dataclass(frozen=True)
class Rule:
    mistake: str
    steps: tuple[str, ...]
    hint: str
    build: Callable[[Derivation, str, int | None], sp.Expr | None]
    name: str = ""  # what went wrong, in a few words (the hint says why)


STIFFNESS_UNITS = ("N/m", "kg/s²", "kg/s^2", "kg s⁻²")


def has_springs(d: Derivation) -> bool:
    """Whether the system may hold a spring (springs_possible of its declaration).  The one answer to "does this
    problem have springs" for every message family."""
    return springs_possible(d.system)


def springs_possible(system: System) -> bool:
    """Whether a declared system may hold a spring: a parameter with a stiffness's unit, or no parameter with a unit."""
    units = [p.unit for p in system.parameters if p.unit]
    return not units or any(u.replace(" ", "") in STIFFNESS_UNITS for u in units)


# the clauses of the hints about springs, left out of a system without one (has_springs)
SPRING_CLAUSES = (
    ", plus ½ k times the square of each spring's stretch",
    " (and +½ k × stretch² for a spring)",
    " and ½ k × stretch² for every spring",
)


# the step's rule for U names gravity first; where the system has no g (masses on a horizontal line)
# it names the springs alone
GRAVITY_CLAUSE = (
    "m g times the height of each mass above a level of your choice (height measured upward, against gravity), "
    "plus ½ k times",
    "½ k times",
)


def has_gravity(d: Derivation) -> bool:
    """Whether the system has gravity: a parameter g.  The one answer to "is there gravity in this problem" for every
    message family."""
    return any(p.name == "g" for p in d.system.parameters)


def why_no_gravity(d: Derivation) -> str:
    """Why a system without g has no gravity term, where its bodies show it: every height stays the same, so the
    weights do no work (the coupled oscillators' masses on a horizontal line); "" where they do not."""
    moving = {*d.table.q, d.table.t}
    positions = d.mechanics.positions
    if has_gravity(d) or not positions or any(r[2].free_symbols & moving for r in positions):
        return ""
    # a horizontal line where the bodies move along x alone, else a level plane
    line = not any(r[1].free_symbols & moving for r in positions)
    where = "a horizontal line" if line else "a level plane"
    if len(positions) > 1:
        return f"the masses move on {where}, so their heights never change and gravity does no work on them"
    return f"the mass moves on {where}, so its height never changes and gravity does no work on it"


def absent_names(d: Derivation) -> dict[str, str]:
    """Names a student may expect that this problem has not, each with why (read_answer says it): g where no
    body's height changes."""
    why = why_no_gravity(d)
    return {"g": why} if why else {}


def without_gravity(text: str | None) -> str | None:
    """A hint without its clause about gravity, for a system with no g."""
    return text.replace(*GRAVITY_CLAUSE) if text else text


def without_springs(text: str | None) -> str | None:
    """A hint with its clauses about springs left out, for a system that has none."""
    if not text:
        return text
    for clause in SPRING_CLAUSES:
        text = text.replace(clause, "")
    # a quantity in kg/s² is no spring constant where there is no spring
    return text.replace(STIFFNESS_WORDS, STIFFNESS_PLAIN)


POINTERS = {
    "position": "Place the body with x across and z up: follow the lengths from the origin the statement names to "
    "the body, adding each one's part along this axis (a length times the cosine of its angle to the axis, or the sine "
    "of its angle to the line across it), and the position of whatever carries the body.",
    "kinetic": "T adds ½ m v² over the masses, with v² the squared speed: differentiate each position along the "
    "motion (the chain rule through every coordinate, and through t if a constraint moves), then add the squares "
    "of the velocity's components.",
    "potential": "U depends on positions only: m g times the height of each mass above a level of your choice "
    "(height measured upward, against gravity), plus ½ k times the square of each spring's stretch.",
    "lagrangian": "L = T − U, with T and U written in the generalized coordinates and their velocities.",
    "momentum": "p = ∂L/∂q̇: differentiate L with respect to this coordinate's velocity, keeping every other "
    "coordinate and velocity fixed, and keep every factor that multiplies that velocity.",
    "equation": "d/dt(∂L/∂q̇) − ∂L/∂q = Q, written as one expression equal to zero (or as lhs = rhs) in q, q̇ and q̈; d/dt is a total "
    "derivative, so it acts on every coordinate and velocity inside ∂L/∂q̇.",
    "acceleration": "Write the Euler–Lagrange equations and solve them for q̈; when coordinates are coupled (a "
    "mass matrix with off-diagonal terms), solve the equations together.",
    "hamiltonian": "h = Σ p_k q̇_k − L, written in the coordinates and velocities.",
    # {w}: the document's letter for the frequency (ω, or Ω where ω is a parameter), formatted where read
    "omega_squared": "About a stable equilibrium, where the effective potential has zero slope, {w}² is the effective "
    "potential's second derivative there divided by the {inertia} (the coefficient of ½ q̇² in T).",
}


def _T(d: Derivation) -> sp.Expr | None:
    return d.mechanics.T


def _U(d: Derivation) -> sp.Expr | None:
    return d.mechanics.U


def _times_two(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
    T, U = _T(d), _U(d)
    if T is None:
        return None
    return 2 * T if step == "kinetic" else 2 * T - U


def _speed(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
    m = d.mechanics
    if m.T is None:
        return None
    if m.speeds_squared:
        # |v| = sqrt(v²), taken with positive symbols so that sqrt(R² θ̇²) reads R θ̇ as a student writes it
        symbols = sorted(set().union(*(v2.free_symbols for v2 in m.speeds_squared)), key=lambda s: s.name)
        positive = {s: sp.Dummy(s.name, positive=True) for s in symbols}
        back = {v: s for s, v in positive.items()}
        speeds = [sp.sqrt(sp.factor(v2.xreplace(positive))).xreplace(back) for v2 in m.speeds_squared]
        T = sum(sp.Rational(1, 2) * mass * v for mass, v in zip(m.masses, speeds, strict=True))
    else:
        # q̇² written as q̇
        T = m.T.xreplace({qd**2: qd for qd in d.table.qd})
    return T if step == "kinetic" else T - m.U


def cross_terms(T: sp.Expr, velocities: tuple[sp.Symbol, ...]) -> sp.Expr:
    """The terms of T that are not a single squared velocity: products of two velocities, and degree 1."""
    cross = sp.Integer(0)
    for term in sp.Add.make_args(sp.expand(T)):
        powers = [sp.degree(term, v) for v in velocities if term.has(v)]
        if powers and powers != [2]:
            cross += term
    return cross


def _no_cross(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
    T = _T(d)
    if T is None:
        return None
    cross = cross_terms(T, d.table.qd)
    if cross == 0:
        return None
    return T - cross if step == "kinetic" else d.mechanics.L - cross


def _negative_u(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
    U = _U(d)
    if U is None:
        return None
    return -U


def _t_plus_u(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
    return None if _T(d) is None else _T(d) + _U(d)  # type: ignore[operator]


# ---- equations and the accelerations they would give ---------------------------------------------


def _residuals(d: Derivation, mistake: str) -> list[sp.Expr] | None:
    """Every coordinate's Euler–Lagrange expression as written with ``mistake``."""
    eqs, m, table = d.equations, d.mechanics, d.table
    out = []
    for j in range(len(table.names)):
        if mistake == "double_force":
            if m.U is None:
                return None
            # the force of U, -∂U/∂q, entered again as a generalized force
            out.append(eqs.residuals[j] + sp.diff(m.U, table.q[j]))
        elif mistake == "chain_rule":
            # d/dt p_j taken as Σ_k (∂p_j/∂q̇_k) q̈_k alone
            partial = sum(eqs.mass_matrix[j, i] * table.qdd[i] for i in range(len(table.names)))
            out.append(partial - eqs.dL_dq[j] - m.Q[j])
        elif mistake == "forgot_force":
            out.append(eqs.residuals[j] + m.Q[j])
        elif mistake == "sign_of_dl_dq":
            out.append(eqs.ddt_momenta[j] + eqs.dL_dq[j] - m.Q[j])
    return out


def _equation(mistake: str) -> Callable[[Derivation, str, int | None], sp.Expr | None]:
    def build(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
        wrong = _residuals(d, mistake)
        if wrong is None or k is None:
            return None
        # a cyclic coordinate (∂L/∂q = 0) has no ∂L/∂q whose sign could be off: naming it would send the
        # student looking for a term the step does not have
        if mistake == "sign_of_dl_dq" and sp.expand(d.equations.dL_dq[k]) == 0:
            return None
        if step == "equation":
            return wrong[k]
        # the same mass matrix: M q̈ = f' with f' = −E'(q̈ = 0)
        zero = dict.fromkeys(d.table.qdd, sp.Integer(0))
        forcing = sp.Matrix([-sp.expand(r).xreplace(zero) for r in wrong])
        M = d.equations.mass_matrix
        # left unsimplified: only its values are compared, and what is shown is the difference
        return M.LUsolve(forcing)[k]

    return build


def _h_as_l(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
    return d.mechanics.L


def _h_as_e(d: Derivation, step: str, k: int | None) -> sp.Expr | None:
    en = d.energetics
    return None if d.mechanics.T is None or en.h_equals_e else en.energy


RULES: tuple[Rule, ...] = (
    Rule(
        "missing_half",
        ("kinetic", "lagrangian"),
        "Your T is twice the correct T: the kinetic energy of each mass is ½ m v², and the factor ½ seems to be missing.",
        _times_two,
        "the ½ of ½ m v² left out",
    ),
    Rule(
        "speed_not_squared",
        ("kinetic", "lagrangian"),
        "It looks as if you used the speed v where T needs the squared speed v² = v·v (the sum of the squared "
        "velocity components).",
        _speed,
        "the speed where T needs its square",
    ),
    Rule(
        "t_plus_u",
        ("lagrangian",),
        "Your L is T + U, and the Lagrangian is L = T − U: either U was added to T, or U's sign is reversed (U is "
        "+m g × height with the height measured upward, so check which way each coordinate moves a mass up or down).",
        _t_plus_u,
        "L written as T + U",
    ),
    Rule(
        "sign_of_u",
        ("potential",),
        "The sign of U is reversed: U is +m g × height with height measured upward, against gravity (and "
        "+½ k × stretch² for a spring). Check which way your height axis points.",
        _negative_u,
        "the sign of U",
    ),
    Rule(
        "missing_cross_term",
        ("kinetic", "lagrangian"),
        "A cross term is missing: when a position depends on several coordinates (or on t), squaring its velocity "
        "gives mixed products, twice the product of two of its parts. Forgetting the chain rule through one of them "
        "drops those terms.",
        _no_cross,
        "the cross terms of T left out",
    ),
    Rule(
        "force_counted_twice",
        ("equation", "acceleration"),
        "A force is counted twice: a force that comes from U, such as gravity, is already in ∂L/∂q, so it is not "
        "written again beside it.",
        _equation("double_force"),
        "a force of U, such as gravity, counted twice",
    ),
    Rule(
        "chain_rule_in_ddt",
        ("equation", "acceleration"),
        "The d/dt of ∂L/∂q̇ is missing its chain-rule terms: ∂L/∂q̇ depends on the coordinates too, so its time "
        "derivative has terms (∂/∂q of ∂L/∂q̇)·q̇ besides the q̈ ones.",
        _equation("chain_rule"),
        "the chain-rule terms of d/dt(∂L/∂q̇) left out",
    ),
    Rule(
        "forgot_force",
        ("equation", "acceleration"),
        "The generalized force is missing: the equation is d/dt(∂L/∂q̇) − ∂L/∂q = Q, and this system has a Q that "
        "no potential describes.",
        _equation("forgot_force"),
        "the generalized force left out",
    ),
    Rule(
        "sign_of_dl_dq",
        ("equation", "acceleration"),
        "A sign is off between the two terms: the equation is d/dt(∂L/∂q̇) − ∂L/∂q = Q, with a minus before ∂L/∂q.",
        _equation("sign_of_dl_dq"),
        "the sign of ∂L/∂q",
    ),
    # h written as E is tried first: where h ≠ E and U = 0, L and E are one expression, and the h-is-L
    # hint ("it comes to T + U") would teach the very slip the student made
    Rule(
        "h_is_e",
        ("hamiltonian",),
        "That is the energy E = T + U. Here h ≠ E because a constraint moves with time: h = Σ p q̇ − L = T₂ − T₀ + U.",
        _h_as_e,
        "h written as the energy E = T + U",
    ),
    Rule(
        "h_is_l",
        ("hamiltonian",),
        "That is L. The energy function h = Σ p q̇ − L comes to T + U for T quadratic in the velocities, not T − U.",
        _h_as_l,
        "h written as L",
    ),
)

# {w}: the document's letter for the frequency, as in POINTERS["omega_squared"]; {i}: its inertia's (I_eff, m_eff)
OMEGA_HINT = "This is {w}, not {w}²: square it ({w}² = U_eff″/{i} at the equilibrium)."


def pointer(step: str, frequency: str = "ω", inertia: Inertia = MASS_INERTIA) -> str:
    """A step's rule, the frequency named by the document's letter and the inertia by its coordinate's words."""
    return POINTERS[step].format(w=frequency, inertia=inertia.words) if step == "omega_squared" else POINTERS[step]


# a momentum short of a factor: the factor is named, never the corrected momentum
MISSING_FACTOR_HINT = (
    "A factor {factor} is missing from your momentum. p = ∂L/∂q̇ keeps every factor that multiplies the velocity "
    "in L, including ones that depend on the coordinates."
)
CONSTANT_FACTOR_HINT = (
    "A factor {factor} is missing from your momentum. p = ∂L/∂q̇ keeps every factor that multiplies the velocity in L."
)
HALF_MOMENTUM_HINT = (
    "Your momentum is half the correct one: the ½ of ½ a q̇² is gone once it is differentiated, since "
    "∂(½ a q̇²)/∂q̇ = a q̇."
)
