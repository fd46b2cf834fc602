"""Integrators: ``base`` holds the rules, each other module one family of methods."""

from __future__ import annotations

from app.numerics.methods.base import Method, Problem, Trajectory
from app.numerics.methods.explicit import CompiledDOP853, CompiledVern8
from app.numerics.methods.scipy_ivp import ScipyMethod
from app.numerics.methods.symplectic import GaussLegendre, StormerVerlet, Yoshida4

METHODS: dict[str, Method] = {
    m.name: m
    for m in (
        CompiledDOP853(),
        CompiledVern8(),
        StormerVerlet(),
        Yoshida4(),
        GaussLegendre(),
        *(ScipyMethod(name) for name in ("DOP853", "RK45", "Radau", "BDF", "LSODA")),
    )
}

__all__ = ["METHODS", "Method", "Problem", "Trajectory"]
