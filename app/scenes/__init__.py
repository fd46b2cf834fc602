"""The scenes: a registry mapping an id to its declaration, in the chapter's order, then those beyond it."""

from app.scenes.beads import HELIX_BEAD, ROTATING_PARABOLA
from app.scenes.beyond import COUPLED_OSCILLATORS, DOUBLE_PENDULUM, MASSIVE_PULLEY, PHYSICAL_PENDULUM
from app.scenes.inclines import INCLINE_BLOCK, MOVABLE_INCLINE, ROLLING_CYLINDER_WEDGE
from app.scenes.pendulums import DAMPED_PENDULUM, SIMPLE_PENDULUM, SPHERICAL_PENDULUM
from app.scenes.two_body import PULLEY, RAIL_TWO_BODY, TABLETOP_SPRING
from app.scenes.types import Body, Constraint, CoordinateChange, Erratum, Event, Parameter, Particle, Scene, System

SCENES: dict[str, Scene] = {
    scene.id: scene
    for scene in (
        DAMPED_PENDULUM,
        SIMPLE_PENDULUM,
        HELIX_BEAD,
        INCLINE_BLOCK,
        TABLETOP_SPRING,
        SPHERICAL_PENDULUM,
        RAIL_TWO_BODY,
        PULLEY,
        MOVABLE_INCLINE,
        ROLLING_CYLINDER_WEDGE,
        ROTATING_PARABOLA,
        COUPLED_OSCILLATORS,
        DOUBLE_PENDULUM,
        PHYSICAL_PENDULUM,
        MASSIVE_PULLEY,
    )
}

__all__ = ["SCENES", "Body", "Constraint", "CoordinateChange", "Erratum", "Event", "Parameter", "Particle", "Scene", "System"]
