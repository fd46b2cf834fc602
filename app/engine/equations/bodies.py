"""Rigid bodies: the kinetic energy of a body that turns as well as moves.

A rigid body's kinetic energy splits into two pieces (König's theorem, Taylor § 10.1): the whole mass moving
with the centre of mass, and the turning about the centre,

    T = ½ M v_cm² + ½ I_cm θ̇²,

where I_cm is the moment of inertia about the axis through the centre normal to the plane of motion and θ̇ the
rate at which the body's angle θ turns (printed as that rate, never as ω, which the pages keep for frequencies).
Each uniform body's I_cm is a number times M size² (INERTIA, the one table of them); a declared body
(app/scenes/types.py ``Body``) gives its kind, mass, size, centre and angle.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from app.engine.algebra.simplify import pythagoras
from app.engine.algebra.trig import merged
from app.engine.errors import DerivationError
from app.engine.parser.symbols import SymbolTable
from app.scenes.types import Body

# I_cm / (M size²) for each uniform body, about the axis through its centre normal to the plane:
# a rod of length ℓ turning end over end, ML²/12; a disc of radius R about its axis, MR²/2; a ring, MR²
# (all its mass at distance R); a solid sphere, 2MR²/5
INERTIA: dict[str, sp.Rational] = {
    "rod": sp.Rational(1, 12),
    "disc": sp.Rational(1, 2),
    "ring": sp.Integer(1),
    "sphere": sp.Rational(2, 5),
}

# what the size of each kind is, in words (the step's explanation, an error message)
SIZE_WORDS = {"rod": "length", "disc": "radius", "ring": "radius", "sphere": "radius"}


@dataclass(frozen=True)
class BodyMotion:
    """One body's kinematics and its two pieces of kinetic energy."""

    body: Body
    mass: sp.Expr
    size: sp.Expr
    centre: tuple[sp.Expr, ...]
    velocity: tuple[sp.Expr, ...]
    speed_squared: sp.Expr
    turning_rate: sp.Expr
    inertia: sp.Expr
    translation: sp.Expr
    rotation: sp.Expr
    angle: sp.Expr = sp.Integer(0)  # the turning angle as declared, whose rate is turning_rate

    @property
    def kinetic(self) -> sp.Expr:
        return self.translation + self.rotation


def body_motion(index: int, body: Body, table: SymbolTable, read: Callable[[str, str], sp.Expr]) -> BodyMotion:
    """The body's v_cm², turning rate θ̇, I_cm and its translational and rotational energies.

    ``read(text, where)`` parses a text of positions (no velocities) in the system's names."""
    where = f"body {index}" + (f" ({body.label})" if body.label else "")
    if body.kind not in INERTIA:
        raise DerivationError(f"{where}: a body is one of {', '.join(INERTIA)}, not {body.kind!r}")
    if len(body.centre) != 3:
        raise DerivationError(f"{where}: a centre has three components (x, y, z)")
    mass = read(body.mass, f"{where} mass")
    size = read(body.size, f"{where} {SIZE_WORDS[body.kind]}")
    centre = tuple(read(c, f"{where} centre") for c in body.centre)
    angle = read(body.angle, f"{where} angle")
    # v_cm = dr_cm/dt along the motion (chain rule through every coordinate)
    velocity = tuple(table.dt(c) for c in centre)
    # v_cm² = v_cm · v_cm, with sin² + cos² = 1 (app/engine/algebra/trig.py)
    speed_squared = merged(pythagoras(sum(c**2 for c in velocity)))
    # θ̇ = d(angle)/dt: the angle turns about the axis normal to the plane
    turning_rate = table.dt(angle)
    # I_cm = (number) M size², from the one table
    inertia = INERTIA[body.kind] * mass * size**2
    # T = ½ M v_cm² (the centre's motion) + ½ I_cm θ̇² (the turning about the centre)
    translation = merged(sp.expand(sp.Rational(1, 2) * mass * speed_squared))
    rotation = sp.expand(sp.Rational(1, 2) * inertia * turning_rate**2)
    return BodyMotion(
        body, mass, size, centre, velocity, speed_squared, turning_rate, inertia, translation, rotation, angle
    )
