"""Forces of constraint: the engine against a second, Cartesian route, and its refusals.

The second route never uses the engine's accelerations: it differentiates each
constraint twice along a Cartesian motion, puts Newton's law
r_i'' = (-grad_i U + sum_b lambda_b grad_i g_b) / m_i into g'' = 0, and solves
the linear system for the multipliers in Cartesian positions and velocities;
only then are the positions r(q, t) of the declaration substituted.
"""

import pytest
import sympy as sp

from app.engine.derivation.derive import Derivation, derive
from app.engine.equations.constraints import constraint_forces
from app.engine.errors import DerivationError
from app.scenes import SCENES
from app.scenes.types import Constraint, Parameter, Particle, System
from tests.reference import numerically_equal
from tests.scenes.common import forces

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

CONSTRAINED = sorted(sid for sid, s in SCENES.items() if s.system.constraints)


def forces_of(d: Derivation):
    """The constraint forces of a derivation, computed afresh (not the derivation's remembered member)."""
    return constraint_forces(d.system, d.mechanics, d.equations)


def cartesian_route(system: System) -> list[sp.Expr]:
    """The reported force of each constraint, from g'' = 0 in Cartesian coordinates."""
    n = len(system.particles)
    suffix = [""] if n == 1 else [str(i + 1) for i in range(n)]
    real = {}

    def sym(name):
        return real.setdefault(name, sp.Symbol(name, real=True))

    r = [[sym(a + s) for a in "xyz"] for s in suffix]
    v = [[sym("v" + a + s) for a in "xyz"] for s in suffix]
    t = sym("t")
    local = {p.name: sym(p.name) for p in system.parameters} | {"t": t}
    local |= {c.name: c for row in r for c in row}
    masses = [sp.sympify(p.mass, locals=local) for p in system.particles]
    U = sp.sympify(system.cartesian_potential, locals=local)
    gs = [sp.sympify(c.expression, locals=local) for c in system.constraints]
    flat_r = [c for row in r for c in row]
    flat_v = [c for row in v for c in row]
    inv_m = [1 / masses[i // 3] for i in range(3 * n)]

    def grad(f):
        return [sp.diff(f, c) for c in flat_r]

    # g'' = grad g . r'' + v^T (Hess g) v + 2 d/dt(grad g) . v + d^2 g/dt^2
    A = sp.zeros(len(gs))
    rhs = sp.zeros(len(gs), 1)
    for a, ga in enumerate(gs):
        Ga = grad(ga)
        hess = sum(
            sp.diff(ga, ci, cj) * vi * vj
            for ci, vi in zip(flat_r, flat_v, strict=True)
            for cj, vj in zip(flat_r, flat_v, strict=True)
        )
        w = hess + 2 * sum(sp.diff(e, t) * vi for e, vi in zip(Ga, flat_v, strict=True)) + sp.diff(ga, t, 2)
        rhs[a] = sum(im * e * f for im, e, f in zip(inv_m, Ga, grad(U), strict=True)) - w
        for c, gc in enumerate(gs):
            A[a, c] = sum(im * e * f for im, e, f in zip(inv_m, Ga, grad(gc), strict=True))
    lam = A.LUsolve(rhs)

    # now the motion: r = r(q, t), v = dr/dt along q(t)
    q = [sym(n) for n in system.coordinates]
    qd = [sym(n + "_dot") for n in system.coordinates]
    local_q = {p.name: sym(p.name) for p in system.parameters} | {"t": t} | {c.name: c for c in q}
    positions = [[sp.sympify(c, locals=local_q) for c in p.position] for p in system.particles]
    at = {}
    for row_r, row_v, pos in zip(r, v, positions, strict=True):
        for c, vc, e in zip(row_r, row_v, pos, strict=True):
            at[c] = e
            at[vc] = sp.diff(e, t) + sum(sp.diff(e, qi) * qdi for qi, qdi in zip(q, qd, strict=True))
    out = []
    for a, c in enumerate(system.constraints):
        g_on = grad(gs[a])[3 * (c.on - 1) : 3 * c.on]
        out.append((lam[a] * sp.sqrt(sum(e**2 for e in g_on))).xreplace(at))
    return out


@pytest.mark.parametrize("scene_id", CONSTRAINED)
def test_multipliers_agree_with_the_cartesian_route(scene_id):
    ours = [f.force for f in forces(scene_id)]
    theirs = cartesian_route(SCENES[scene_id].system)
    for a, b in zip(ours, theirs, strict=True):
        symbols = sorted(a.free_symbols | b.free_symbols, key=str)
        assert numerically_equal(a, b, symbols), (scene_id, a, b)


@pytest.mark.parametrize("scene_id", CONSTRAINED)
def test_forces_depend_on_state_and_parameters_only(scene_id):
    d = SCENES[scene_id].system
    allowed = {f"{q}{s}" for q in d.coordinates for s in ("", "_dot")} | {p.name for p in d.parameters} | {"t"}
    for f in forces(scene_id):
        assert {s.name for s in f.force.free_symbols} <= allowed


def test_the_scaling_of_g_does_not_change_the_force():
    base = SCENES["simple-pendulum"].system
    scaled = Constraint("tension", "-3*(x**2 + y**2 + (z - R)**2 - R**2)", "toward the pivot")
    other = derive(System(**{**base.__dict__, "constraints": (scaled,)}))
    (f,) = constraint_forces(other.system, other.mechanics, other.equations)
    assert sp.simplify(f.force - forces("simple-pendulum")[0].force) == 0


PENDULUM = dict(
    coordinates=("theta",),
    parameters=(Parameter("m", 1.0, min=0.1), Parameter("g", 9.8, min=0.1), Parameter("R", 1.0, min=0.1)),
    particles=(Particle("m", ("R*sin(theta)", "0", "-R*cos(theta)")),),
    potential="-m*g*R*cos(theta)",
    cartesian_potential="m*g*z",
)
STRING = Constraint("tension", "R**2 - x**2 - y**2 - z**2", "toward the pivot", slack_when_negative=True)


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"constraints": (Constraint("wrong", "R - x", "?"),)}, "does not hold"),
        ({"constraints": (Constraint("side", "y", "sideways"),)}, "do not account for the motion"),
        ({"constraints": (STRING,), "cartesian_potential": "2*m*g*z"}, "differs from U"),
        ({"constraints": (STRING,), "cartesian_potential": None}, "cartesian_potential"),
        ({"constraints": (Constraint("t", "R**2 - x**2 - z**2", "?", on=2),)}, "'on'"),
        ({"constraints": (Constraint("t", "R**2 - x**2 - w**2", "?"),)}, "unknown name"),
    ],
)
def test_bad_declarations_are_refused(changes, message):
    system = System(**{**PENDULUM, **changes})
    with pytest.raises(DerivationError, match=message):
        forces_of(derive(system))


def test_a_parameter_named_like_a_cartesian_coordinate_is_refused():
    system = System(
        coordinates=("theta",),
        parameters=(Parameter("z", 1.0),),
        particles=(Particle("1", ("sin(theta)", "0", "-cos(theta)")),),
        potential="0",
        cartesian_potential="0",
        constraints=(Constraint("t", "1 - x**2 - y**2", "?"),),
    )
    with pytest.raises(DerivationError, match="clashes"):
        forces_of(derive(system))


def test_constraint_forces_need_particles():
    system = System(
        coordinates=("x",),
        kinetic="x_dot**2/2",
        potential="0",
        cartesian_potential="0",
        constraints=(Constraint("c", "y", "?"),),
    )
    with pytest.raises(DerivationError, match="particles"):
        forces_of(derive(system))


def test_no_constraints_no_forces():
    assert forces_of(derive(SCENES["tabletop-spring"].system)) == ()
