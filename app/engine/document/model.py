"""The printed derivation: one typed model of the document the engine prints from a ``Derivation``.

``app.engine.document.contract`` builds a ``Document`` once; the caches hold it, the API sends its JSON
(``Document.as_json``, the same bytes as the dict it replaced), and viz, the pages and the exports read
its attributes.  Every model forbids keys it does not name, so a document that changes shape without
the model fails its tests.  An expression is a ``Pair``: the text of its textbook form, its LaTeX, and
a tree the browser evaluates.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.engine.display.names import MASS_MATRIX
from app.engine.document.notation import ANGLE_INERTIA, MASS_INERTIA, RIGHT_SIDE
from app.engine.document.trees import FUNCTIONS as TREE_FUNCTIONS

# a key the model does not name is an error: the model is the document's one description
SHAPE = ConfigDict(extra="forbid", populate_by_name=True)

TREE = (
    "The same expression as a JSON tree, to evaluate without a parser (the pages do): a number, a "
    "symbol's name, or [op, ...arguments] with op one of '+', '*', 'neg', '/', 'pow' or a function "
    f"({', '.join(sorted(TREE_FUNCTIONS))}; atan2 takes y then x). null when it has none (another "
    "function, or too large)."
)


class Pair(BaseModel):
    """An expression: its textbook form as text and as LaTeX, and its tree."""

    model_config = SHAPE
    sympy: str = Field(description="In the symbol convention: q, q_dot, q_ddot, t, parameters by name.")
    latex: str
    tree: Any = Field(default=None, description=TREE)


class Root(BaseModel):
    """An expression with its running-text form too (a root r₀ = (p²/(m k))^{1/4}, an ω² on a slider's mark)."""

    model_config = SHAPE
    sympy: str
    latex: str
    tree: Any = Field(default=None, description=TREE)
    unicode: str


class Factor(BaseModel):
    model_config = SHAPE
    sympy: str
    latex: str


class Equation(BaseModel):
    """One Euler–Lagrange equation, as its row in the results box prints it (residual = 0)."""

    model_config = SHAPE
    coordinate: str
    sympy: str
    latex: str
    tree: Any = Field(default=None, description=TREE)
    divided_by: Factor | None = Field(
        default=None,
        description=(
            "The factor common to the equation's terms that it is shown divided by (null: shown as derived); row k "
            "of mass_matrix and forcing is equation k times its factor."
        ),
    )


class Symbol(BaseModel):
    """How a name is written: LaTeX, Unicode and plain text."""

    model_config = SHAPE
    latex: str
    unicode: str
    plain: str


class Letter(BaseModel):
    model_config = SHAPE
    latex: str
    unicode: str


class NotationEntry(BaseModel):
    """One letter of a document's "Symbols" table: each letter means one quantity on its page."""

    model_config = SHAPE
    latex: str
    unicode: str
    meaning: str = Field(description="what the letter stands for (a parameter's own description)")
    unit: str = Field(description="a parameter's unit; empty for the others")
    kind: Literal["coordinate", "parameter", "derived"]


class ParameterInfo(BaseModel):
    model_config = SHAPE
    default: float
    unit: str
    min: float | None
    max: float | None
    description: str


class FixedDistance(BaseModel):
    """Two particles (or a particle and the origin, ``from`` null) at a distance proven constant: a rod to draw."""

    model_config = SHAPE
    start: int | None = Field(alias="from", description="The first particle's index (from 0); null for the origin.")
    to: int = Field(description="The other particle's index (from 0).")


class Conserved(BaseModel):
    model_config = SHAPE
    name: str
    latex_name: str
    sympy: str
    latex: str
    tree: Any = Field(default=None, description=TREE)
    reason: str


class ConservedBoth(BaseModel):
    """A conserved quantity of the new coordinates, with its form in the original ones."""

    model_config = SHAPE
    name: str
    latex_name: str
    sympy: str
    latex: str
    tree: Any = Field(default=None, description=TREE)
    reason: str
    original: Pair


class Step(BaseModel):
    model_config = SHAPE
    key: str = Field(description="What the step is (euler-lagrange; derivatives:theta), whatever its title reads.")
    title: str
    latex: str
    sympy: str
    explanation: str


class Equilibrium(BaseModel):
    """An equilibrium of the effective potential (a steady motion where momenta are held)."""

    model_config = SHAPE
    position: Root
    omega_squared: Root
    stable: bool | None
    exists: Pair | None = Field(
        None, description="Where the equilibrium exists (arccos(a/b) needs b > a); null when always."
    )
    stable_when: Pair | None = Field(
        None, description="When stable is null: the condition on the parameters for ω² > 0."
    )
    unstable_when: Pair | None = Field(
        None, description="When stable is null: the condition for ω² < 0 (stable_when reversed)."
    )
    power: int = Field(description="n where the root is C^(1/n), so that r₀ⁿ = C (position_power); 1 otherwise.")
    position_power: Pair


class EffectivePotential(BaseModel):
    model_config = SHAPE
    coordinate: str
    momenta: list[str]
    potential: Pair
    mass: Pair
    inertia: Letter = Field(
        description=f"The letter the page prints `mass` with: {ANGLE_INERTIA.unicode}, an {ANGLE_INERTIA.words}, where "
        f"the coordinate is an angle; {MASS_INERTIA.unicode}, an {MASS_INERTIA.words}, where it is a length.",
    )
    condition: Pair
    omega_squared: Pair
    equilibria: list[Equilibrium]
    omega_squared_steady: Pair | None = Field(description="ω² about a steady motion in terms of its r₀; null for none.")


class SceneEvent(BaseModel):
    model_config = SHAPE
    name: str
    expression: str
    message: str


class SceneBlock(BaseModel):
    """A chapter scene as data: its statement, figure, panels, defaults, events and the family it is drawn as."""

    model_config = SHAPE
    id: str
    title: str
    section: str
    summary: str
    statement: str
    figure: str
    run_note: str
    coordinates: list[str]
    parameters: dict[str, ParameterInfo]
    initial: dict[str, float]
    t_end: float
    panels: list[str]
    beyond_chapter: bool
    events: list[SceneEvent]
    family: str
    marks: list[str]
    answers: list[str]
    exact_frequency: str


class Erratum(BaseModel):
    model_config = SHAPE
    chapter: str
    correct: str
    reason: str
    chapter_words: bool
    chapter_latex: str
    correct_latex: str
    approximate: bool


class ActsOn(BaseModel):
    model_config = SHAPE
    particle: int
    ratio_tree: Any
    direction_trees: list[Any]


class ConstraintForce(BaseModel):
    model_config = SHAPE
    name: str
    sympy: str
    latex: str
    tree: Any = Field(default=None, description=TREE)
    convention: str
    slack_when_negative: bool
    constraint: Pair
    particle: int
    direction: list[str]
    direction_trees: list[Any]
    acts_on: list[ActsOn]


class RelativeMotion(BaseModel):
    model_config = SHAPE
    equation: str
    frequency: str


class Transformed(BaseModel):
    """The derivation again in the declared new coordinates, with the maps between the two sets."""

    model_config = SHAPE
    coordinates: list[str]
    definitions: dict[str, Pair]
    inverse: dict[str, Pair]
    lagrangian: Pair
    accelerations: dict[str, Pair]
    momenta: dict[str, Pair]
    mass_matrix: list[list[Pair]]
    cyclic: list[str]
    effective_potential: EffectivePotential | None
    conserved: list[ConservedBoth]
    inertia: dict[str, Pair]
    reduced_mass: Pair | None
    relative_motion: RelativeMotion | None


class HamiltonEquation(BaseModel):
    model_config = SHAPE
    coordinate: str
    q_dot: Pair = Field(description="dH/dp_q, in q and the momenta p_q.")
    p_dot: Pair = Field(description="-dH/dq plus the generalized force, in q and the momenta p_q.")


class Hamilton(BaseModel):
    model_config = SHAPE
    hamiltonian: Pair = Field(description="H(q, p, t); the momentum of coordinate q is the symbol p_q.")
    momenta: dict[str, str] = Field(description="Each coordinate's momentum symbol.")
    equations: list[HamiltonEquation]


class Mode(BaseModel):
    model_config = SHAPE
    omega_squared: float = Field(description="At the default parameters; negative along an unstable direction.")
    shape: dict[str, float] = Field(description="Amplitude of each coordinate, largest component 1.")
    sympy: str | None = Field(description="omega^2 in closed form, when it is short.")
    latex: str | None


class ComplexMode(BaseModel):
    """A mode of a gyroscopic system: its exponent s = (Re, Im), each coordinate's amplitude and phase."""

    model_config = SHAPE
    exponent: list[float]
    amplitude: dict[str, float]
    phase: dict[str, float]


class NormalModesAt(BaseModel):
    model_config = SHAPE
    equilibrium: dict[str, float] = Field(description="The equilibrium, coordinate -> value at the default parameters.")
    exact: dict[str, Root] | None = Field(description="The equilibrium in closed form, by coordinate; null for none.")
    momenta: dict[str, float] = Field(
        description="Conserved momenta held fixed, for a steady motion of the one-coordinate reduction."
    )
    stable: bool = Field(description="No mode grows exponentially (kind stable or neutral).")
    kind: str = Field(description="stable (every omega^2 > 0), neutral (some omega^2 = 0) or unstable.")
    coordinates: list[str]
    everywhere: bool
    exponents: list[list[float]] = Field(description="Each exponent s of the linearised motion as (Re, Im).")
    frequencies: list[float]
    gyroscopic: bool
    complex_modes: list[ComplexMode]
    modes: list[Mode]


class Skipped(BaseModel):
    model_config = SHAPE
    member: str = Field(
        description="The member left out: accelerations (closed form), steps, effective_potential, "
        "constraint_forces, transformed, hamilton or normal_modes; it is then null or empty in the document."
    )
    reason: str = Field(description="Which part was left out and why (its own time bound, or a closed form too long).")


class Document(BaseModel):
    """The derivation document: GET /api/scenes/{id}/derivation (with ``id`` and ``scene``) and POST /api/derive."""

    model_config = SHAPE
    id: str | None = Field(default=None, description="The scene's id; absent for a system of your own.")
    coordinates: list[str]
    angles: list[str] = Field(description="The coordinates that are angles.")
    symbols: dict[str, Symbol] = Field(description="How every name the document uses is written.")
    notation: list[NotationEntry] = Field(
        description="the page's letters, each once: coordinates, parameters, then the derived quantities (the mass "
        "matrix is ℳ where a body's mass is M, a small-oscillation frequency Ω where ω is a parameter)"
    )
    parameters: dict[str, ParameterInfo]
    kinetic: Pair | None
    potential: Pair | None
    lagrangian: Pair
    hamiltonian: Pair
    energy: Pair
    equations_of_motion: list[Equation]
    accelerations: dict[str, Pair]
    dependent_accelerations: dict[str, Pair] = Field(
        description="The acceleration of each position of a chapter scene that the coordinates fix, by name."
    )
    mass_matrix: list[list[Pair]]
    forcing: list[Pair]
    momenta: dict[str, Pair]
    fixed_distances: list[FixedDistance]
    generalized_forces: dict[str, Pair]
    cyclic: list[str]
    conserved: list[Conserved]
    explicit_time_derivative: Pair
    hamiltonian_equals_energy: bool | None = Field(
        description="Whether h = E: true, false, or null when it cannot be decided (only L was given, so T and U "
        "cannot be told apart); hamiltonian_energy_reason says why."
    )
    hamiltonian_energy_reason: str
    hamiltonian_conserved: bool = Field(description="Whether h is conserved (dh/dt = −∂L/∂t + Σ Q q̇ = 0).")
    hamiltonian_conserved_reason: str
    energy_minus_hamiltonian: Pair
    kinetic_focus_possible: bool = Field(
        description="Whether a true path can reach a kinetic focus: false where L is at most linear in the "
        "coordinates, has no coordinate-velocity product and a constant mass matrix (the Jacobi fields are then "
        "η = a t, which never vanish again), so the true path is a minimum of S for every duration.",
    )
    effective_potential: EffectivePotential | None
    steps: list[Step]
    scene: SceneBlock | None
    errata: list[Erratum]
    constraint_forces: list[ConstraintForce]
    transformed: Transformed | None
    hamilton: Hamilton | None
    normal_modes: list[NormalModesAt]
    skipped: list[Skipped] = Field(
        description="Members of the document left out, each with its reason: every member beyond the equations "
        "of motion has its own time bound, and one that runs out is skipped here instead of refusing the system.",
    )

    def as_json(self) -> dict[str, Any]:
        """The document as JSON data, key for key as it is served (``id`` only for a scene)."""
        return self.model_dump(by_alias=True, exclude=None if self.id is not None else {"id"})


# the mass matrix's letter on every page, in the descriptions too
MM = MASS_MATRIX[1]


class Pending(BaseModel):
    model_config = SHAPE
    member: str = Field(description="A member of the whole document not in this answer (steps, hamilton, …).")
    name: str = Field(description="The member as the playground names it while it waits.")


class FirstStage(BaseModel):
    """The first stage of a derivation document (POST /api/derive/equations): the members below are as in the
    whole document; the playground shows them while the rest is derived."""

    model_config = SHAPE
    stage: Literal["equations", "whole"] = Field(
        description="`equations` for a first stage; `whole` when the whole document was ready (nothing pending)."
    )
    coordinates: list[str]
    angles: list[str]
    symbols: dict[str, Symbol]
    notation: list[NotationEntry] | None = Field(default=None, description="Absent when `stage` is whole.")
    parameters: dict[str, ParameterInfo]
    equations_of_motion: list[Equation]
    accelerations: dict[str, Pair] = Field(description=f"Empty when they stay {MM}⁻¹f (see `skipped`).")
    mass_matrix: list[list[Pair]]
    forcing: list[Pair] = Field(
        description=f"f in {MM} q̈ = f, {RIGHT_SIDE}; {MM} the mass matrix (a first stage gives them when the "
        f"accelerations stay {MM}⁻¹f)."
    )
    skipped: list[Skipped]
    pending: list[Pending] = Field(description="What POST /api/derive adds (empty when `stage` is whole).")

    def as_json(self) -> dict[str, Any]:
        """The first stage as JSON data, key for key as it is served."""
        return self.model_dump(by_alias=True, exclude=None if self.notation is not None else {"notation"})
