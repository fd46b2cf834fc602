"""The chapter's scenes: a registry mapping an id to its declaration."""

from app.scenes.pendulums import SIMPLE_PENDULUM, SPHERICAL_PENDULUM
from app.scenes.types import Parameter, Particle, Scene, System

SCENES: dict[str, Scene] = {scene.id: scene for scene in (SIMPLE_PENDULUM, SPHERICAL_PENDULUM)}

__all__ = ["SCENES", "Parameter", "Particle", "Scene", "System"]
