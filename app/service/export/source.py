"""What an export is made from: a derivation, its JSON document and the problem's data."""

from __future__ import annotations

from dataclasses import dataclass, field

from app.engine.derivation.derive import Derivation
from app.engine.document.model import Document, Erratum
from app.scenes.types import Event, Parameter, Scene
from app.viz.names import label

FORMATS = {
    "ipynb": ("application/x-ipynb+json", "a Jupyter notebook"),
    "py": ("text/x-python; charset=utf-8", "a standalone Python script"),
    "tex": ("application/x-tex; charset=utf-8", "a LaTeX document"),
}


@dataclass(frozen=True)
class Source:
    """One derivation with the problem around it; ``initial`` is q then q_dot, in coordinate order."""

    derivation: Derivation
    document: Document
    stem: str  # the file name without its extension
    title: str
    statement: str
    initial: tuple[float, ...]
    t_end: float
    section: str = ""
    figure: str = ""
    errata: tuple[Erratum, ...] = field(default=())
    events: tuple[Event, ...] = ()  # where the set-up ends (the exported run stops there, as the app's does)

    @property
    def parameters(self) -> tuple[Parameter, ...]:
        return self.derivation.system.parameters


def scene_source(scene: Scene, d: Derivation, document: Document, initial: tuple[float, ...]) -> Source:
    return Source(
        derivation=d,
        document=document,
        stem=scene.id,
        title=scene.title,
        statement=scene.statement,
        initial=initial,
        t_end=scene.t_end,
        section=scene.section,
        figure=scene.figure,
        errata=tuple(document.errata),
        events=scene.events,
    )


def system_source(d: Derivation, document: Document, initial: tuple[float, ...], t_end: float) -> Source:
    """A user's system: the statement is written here from its names and form, never from typed prose."""
    system = d.system
    coordinates = ", ".join(label(n) for n in system.coordinates)
    parameters = ", ".join(label(p.name) for p in system.parameters)
    if system.lagrangian is not None:
        form = "by its Lagrangian L"
    elif system.particles:
        count = len(system.particles)
        form = f"by {count} particle{'s' if count > 1 else ''} placed in terms of the coordinates, and a potential U"
    else:
        form = "by its kinetic energy T and potential energy U"
    forced = " Generalized forces that no potential describes act on it." if system.forces else ""
    statement = (
        f"A system declared in the playground, with generalized coordinates {coordinates}"
        + (f" and parameters {parameters}" if parameters else "")
        + f", given {form}.{forced} Derive its equations of motion and simulate it."
    )
    return Source(
        derivation=d,
        document=document,
        stem="system",
        title="A system of your own",
        statement=statement,
        initial=initial,
        t_end=t_end,
    )
