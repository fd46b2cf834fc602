"""Slips of T and U carried on into L and into the equation of motion (app/engine/tutor/mistake_carried.py): what a
student who goes on from their own wrong T and U is told."""

from __future__ import annotations

import dataclasses
from functools import cache

import pytest
import sympy as sp

from app.engine.derivation.derive import Derivation, derive
from app.engine.tutor.check import judge, problem
from app.engine.tutor.mistake_carried import MAX_SLIPS, lagrangian_changes
from app.engine.tutor.mistake_pieces import swap_sin_cos
from app.scenes import SCENES

# each test derives a scene, and a system declared with a student's T and U
pytestmark = pytest.mark.slow


@cache
def derivation(name: str) -> Derivation:
    return derive(SCENES[name].system)


def own_equation(name: str, T: sp.Expr, U: sp.Expr, coordinate: str) -> str:
    """The equation of motion a student derives, correctly, from their own T and U (the engine's derivation of
    a system declared with that T and U), as they would type it."""
    system = dataclasses.replace(SCENES[name].system, particles=(), kinetic=sp.sstr(T), potential=sp.sstr(U),
                                 constraints=(), cartesian_potential=None, coordinate_change=None)  # fmt: skip
    d = derive(system)
    k = d.table.names.index(coordinate)
    return sp.sstr(d.equations.residuals[k])


def test_an_equation_from_an_l_with_sin_and_cos_swapped_throughout_names_that_l():
    # review student-f, 9: the spherical pendulum's L with sin and cos swapped, differentiated correctly
    d = derivation("spherical-pendulum")
    T, U = swap_sin_cos(d.mechanics.T), swap_sin_cos(d.mechanics.U)
    result = judge(problem(d, "equation", "theta"), own_equation("spherical-pendulum", T, U, "theta"))
    assert result["verdict"] == "incorrect"
    assert result["mistake"]["key"] == "equation.carried.throughout", result
    assert result["hint"].startswith(
        "Your equation for θ follows from an L with sin and cos swapped throughout"
    ), result["hint"]
    assert "it is the right equation for that L" in result["hint"] and "total derivative" not in result["hint"]


def test_the_student_f_equation_as_typed_is_named_as_carried():
    d = derivation("spherical-pendulum")
    typed = "m*R**2*theta_ddot - (-m*R**2*sin(theta)*cos(theta)*phi_dot**2 - m*g*R*cos(theta))"
    assert judge(problem(d, "equation", "theta"), typed)["mistake"]["key"] == "equation.carried.throughout"


def test_an_l_from_a_t_and_a_u_each_with_a_slip_names_both():
    # review student-f, 11: T with sin and cos swapped, U with sin and cos swapped and its sign reversed
    d = derivation("spherical-pendulum")
    typed = "(1/2)*m*R**2*(theta_dot**2 + cos(theta)**2*phi_dot**2) + m*g*R*sin(theta)"
    result = judge(problem(d, "lagrangian"), typed)
    assert result["mistake"]["key"].startswith("lagrangian.carried.kinetic.piece.sin_cos"), result
    name = result["mistake"]["name"]
    assert name.endswith("of U") and " of T, and " in name and name.count("sin and cos swapped") == 2, name
    assert result["hint"].startswith("Your L has two mistakes: ") and "Hint: L = T − U" not in result["hint"]
    # and the equation derived from that L names the same two slips
    T = swap_sin_cos(d.mechanics.T)
    U = -swap_sin_cos(d.mechanics.U)
    eq = judge(problem(d, "equation", "theta"), own_equation("spherical-pendulum", T, U, "theta"))
    assert eq["mistake"]["key"].startswith("equation.carried.kinetic."), eq
    assert eq["hint"].startswith(f"Your equation for θ follows from an L with {name.replace('your', 'the')}")


def test_an_equation_from_a_u_with_its_sign_reversed_is_not_a_slip_of_differentiating():
    d = derivation("simple-pendulum")
    # a U with sin and cos swapped carried on: the page names it, never the generic rule
    result = judge(problem(d, "equation", "theta"), own_equation("simple-pendulum", d.mechanics.T,
                                                                 swap_sin_cos(d.mechanics.U), "theta"))  # fmt: skip
    assert result["mistake"] is not None and "sin and cos swapped" in result["hint"], result


@pytest.mark.parametrize("name", sorted(SCENES))
def test_the_carried_changes_are_bounded_by_count(name):
    changes = lagrangian_changes(derivation(name))
    assert len(changes) <= MAX_SLIPS**2 + 2 * MAX_SLIPS + 1
    # computed once per derivation: the second call is the same object
    assert lagrangian_changes(derivation(name)) is changes
