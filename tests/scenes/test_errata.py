"""Each erratum's correct formula is what the engine derives (parsed from the text itself)."""

import pytest
import sympy as sp

from app.engine.derive import substitute_cyclic
from app.scenes import SCENES
from app.service.derivations import derivation
from tests.reference import numerically_equal, random_point
from tests.scenes.common import S, read, transformed

ERRATA = [(sid, i) for sid, s in sorted(SCENES.items()) for i in range(len(s.errata))]


def engine_result(scene_id: str, check: str):
    """The engine's value that an erratum's check names."""
    d = derivation(scene_id)
    table, eqs, red = d.table, d.equations, d.reduction
    kind, *args = check.split(":")
    index = table.names.index(args[0]) if args and args[0] in table.names else None
    if kind == "acceleration":
        return eqs.accelerations[index]
    if kind == "reduced-acceleration":
        return substitute_cyclic(eqs.accelerations[index], red)
    if kind == "reduced-force":
        return red.effective_mass * substitute_cyclic(eqs.accelerations[index], red)
    if kind == "dL/dq":
        return eqs.dL_dq[index]
    if kind == "potential-force":
        return -sp.diff(d.mechanics.U, table.q[index])
    if kind == "equation":
        return eqs.residuals[index]
    if kind == "speed-squared":
        return d.mechanics.speeds_squared[int(args[0]) - 1]
    if kind == "position":
        r = d.mechanics.positions[int(args[0]) - 1]
        return r if len(args) == 1 else r["xyz".index(args[1])]
    if kind == "point-acceleration":
        c = d.mechanics.positions[int(args[0]) - 1]["xyz".index(args[1])]
        acc = dict(zip(table.qdd, eqs.accelerations, strict=True))
        return table.dt(table.dt(c)).xreplace(acc)
    if kind == "lagrangian":
        return d.mechanics.L
    if kind == "potential":
        return d.mechanics.U
    if kind == "energy-minus-h":
        return d.energetics.energy_minus_h
    if kind == "radial-speed":
        # E_r = m_eff r_dot^2 / 2 + U_eff, solved for r_dot (the outgoing branch)
        return sp.sqrt(2 * (S("E_r") - red.effective_potential) / red.effective_mass)
    if kind == "time-integrand":
        return red.time_integral.function
    if kind == "omega-squared":
        return red.equilibria[int(args[0])].omega_squared
    if kind == "taylor-coefficient":
        # the (q - q0)^2 coefficient of U_eff's Taylor series about the equilibrium
        e = red.equilibria[int(args[0])]
        r = table.q[table.names.index(red.coordinate)]
        return sp.diff(red.effective_potential, r, 2).xreplace({r: e.position}) / 2
    if kind == "transformed-momentum":
        tr = transformed(scene_id)
        new = tr.derivation
        return tr.to_original(new.equations.momenta[new.table.names.index(args[0])])
    raise AssertionError(f"unknown check {check!r}")


def free(*exprs):
    return sorted(set().union(*(sp.sympify(e).free_symbols for e in exprs)), key=str)


@pytest.mark.parametrize(("scene_id", "index"), ERRATA)
def test_erratum_correct_formula_is_the_engines(scene_id, index):
    e = SCENES[scene_id].errata[index]
    assert e.chapter and e.reason and " = " in e.correct
    # the formula after the last '=' is the one compared
    correct = read(e.correct.rsplit("=", 1)[1])
    ours = engine_result(scene_id, e.check)
    kind = e.check.split(":")[0]
    if kind == "position" and isinstance(ours, tuple):
        assert len(correct) == 3
        for a, c in zip(ours, correct, strict=True):
            assert numerically_equal(a, c, free(a, c)), (a, c)
    elif kind == "potential":
        # a potential is fixed up to a constant
        for q in derivation(scene_id).table.q:
            assert numerically_equal(sp.diff(ours, q), sp.diff(correct, q), free(ours, correct))
    elif kind == "equation":
        # an equation = 0 is fixed up to a constant factor
        points = free(ours, correct)
        ratios = {round(complex(sp.N((ours / correct).xreplace(random_point(points, s)))).real, 9) for s in range(3)}
        assert len(ratios) == 1 and ratios != {0.0}, ratios
    elif kind == "radial-speed":
        assert numerically_equal(ours**2, correct**2, free(ours, correct))
    else:
        assert numerically_equal(ours, correct, free(ours, correct)), (ours, correct)


def test_every_scene_with_chapter_formulas_has_errata():
    # the chapter states formulas for these examples, and each has mistakes
    with_errata = {sid for sid, s in SCENES.items() if s.errata}
    assert with_errata == {
        "simple-pendulum",
        "incline-block",
        "tabletop-spring",
        "spherical-pendulum",
        "rail-two-body",
        "pulley",
        "movable-incline",
        "rotating-parabola",
    }


@pytest.mark.parametrize(
    ("scene_id", "check", "chapter"),
    [
        # the chapter's formulas, re-typed: each must differ from the engine's result
        ("spherical-pendulum", "acceleration:theta", "sin(theta)*cos(theta)*phi_dot**2 - g*sin(theta)/R"),
        ("pulley", "acceleration:y1", "-g - 4*m2*g/(m1 + m2 + 4*m1*m2/M)"),
        ("movable-incline", "point-acceleration:2:z", "-(M + m)*g*sin(alpha)*cos(alpha)/(M + m*sin(alpha)**2)"),
        ("tabletop-spring", "omega-squared:0", "4*k"),
        ("tabletop-spring", "time-integrand", "sqrt(2*E_r/m - p_theta**2/(2*m*r**2) - k*r**2/2)"),
    ],
)
def test_the_chapters_versions_are_rejected(scene_id, check, chapter):
    ours = engine_result(scene_id, check)
    wrong = read(chapter)
    assert not numerically_equal(ours, wrong, free(ours, wrong))
