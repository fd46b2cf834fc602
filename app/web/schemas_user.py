"""Request and response models of the user-system API (POST /api/derive, POST /api/simulate).

Shapes only; the limits a model cannot express (names, expressions) are
checked by ``app.service.user_checks.check_system`` with located messages.
Every float is finite: JSON's ``NaN`` and ``Infinity`` (which Python's
``json`` accepts) are refused with a 422.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, create_model

from app.engine.notation import ANGLE_INERTIA, MASS_INERTIA
from app.engine.parse import FUNCTIONS, MAX_LENGTH
from app.engine.trees import FUNCTIONS as TREE_FUNCTIONS
from app.numerics import limits
from app.service.user_checks import MAX_COORDINATES, MAX_PARAMETERS, MAX_PARTICLES
from app.web.schemas import STRICT, ParameterInfo
from app.web.schemas_simulate import SimulateRequest

Expression = Annotated[
    str,
    Field(
        min_length=1,
        max_length=MAX_LENGTH,
        description="An expression: numbers, declared names, + - * / **, parentheses and "
        f"{' '.join(FUNCTIONS)} (atan2(y, x) takes two arguments); pi and time t.",
    ),
]
Name = Annotated[
    str,
    Field(min_length=1, max_length=40, description="A letter then up to 15 ASCII letters or digits."),
]
Number = Annotated[float, Field(ge=-limits.VALUE_MAX, le=limits.VALUE_MAX)]


class ParameterSpec(BaseModel):
    model_config = STRICT

    name: Name
    value: Number = Field(1.0, description="The value used to simulate (and shown as the default).")
    unit: str = Field("", max_length=24)
    min: Number | None = Field(None, description="Lower end of the allowed range; min > 0 marks a positive quantity.")
    max: Number | None = None
    description: str = Field("", max_length=200)


class ParticleSpec(BaseModel):
    model_config = STRICT

    mass: Expression
    position: list[Expression] = Field(
        min_length=2, max_length=3, description="Cartesian (x, y[, z]) as expressions of the coordinates and t."
    )
    label: str = Field("", max_length=40)


class SystemSpec(BaseModel):
    """A mechanical system in one of three forms: particles + potential, kinetic + potential, or lagrangian."""

    model_config = STRICT

    coordinates: list[Name] = Field(min_length=1, max_length=MAX_COORDINATES)
    parameters: list[ParameterSpec | Name] = Field(
        default_factory=list,
        max_length=MAX_PARAMETERS,
        description="Each a name (value 1) or an object with a value, unit and range.",
    )
    lagrangian: Expression | None = None
    kinetic: Expression | None = None
    potential: Expression | None = None
    particles: list[ParticleSpec] = Field(default_factory=list, max_length=MAX_PARTICLES)
    forces: dict[Name, Expression] = Field(
        default_factory=dict,
        max_length=MAX_COORDINATES,
        description="Generalized non-conservative forces Q by coordinate: d/dt dL/dq_dot - dL/dq = Q.",
    )
    nonnegative: list[Name] = Field(
        default_factory=list, max_length=MAX_COORDINATES, description="Coordinates that are distances (r >= 0)."
    )

    def to_spec(self) -> dict[str, Any]:
        """Plain data for the service and the worker (parameters always as objects)."""
        data = self.model_dump(include=set(SystemSpec.model_fields))
        data["parameters"] = [
            ParameterSpec(name=p).model_dump() if isinstance(p, str) else p for p in data["parameters"]
        ]
        return data


# ---- responses ---------------------------------------------------------------------------

OPEN = ConfigDict(extra="allow")


class ExprPair(BaseModel):
    model_config = OPEN
    sympy: str = Field(description="In the symbol convention: q, q_dot, q_ddot, t, parameters by name.")
    latex: str
    tree: Any = Field(
        default=None,
        description=(
            "The same expression as a JSON tree, to evaluate without a parser (the pages do): a number, a "
            "symbol's name, or [op, ...arguments] with op one of '+', '*', 'neg', '/', 'pow' or a function "
            f"({', '.join(sorted(TREE_FUNCTIONS))}; atan2 takes y then x). null when it has none (another "
            "function, or too large)."
        ),
    )


class Factor(BaseModel):
    sympy: str
    latex: str


class EquationOfMotion(ExprPair):
    coordinate: str
    divided_by: Factor | None = Field(
        default=None,
        description=(
            "The factor common to the equation's terms that it is shown divided by (null: shown as derived); row k "
            "of mass_matrix and forcing is equation k times its factor."
        ),
    )


class ConservedQuantity(ExprPair):
    name: str
    latex_name: str
    reason: str


class Step(BaseModel):
    model_config = OPEN
    key: str = Field(description="What the step is (euler-lagrange; derivatives:theta), whatever its title reads.")
    title: str
    latex: str
    sympy: str
    explanation: str


class Equilibrium(BaseModel):
    model_config = OPEN
    position: ExprPair
    omega_squared: ExprPair
    stable: bool | None
    exists: ExprPair | None = Field(
        None, description="Where the equilibrium exists (arccos(a/b) needs b > a); null when always."
    )
    stable_when: ExprPair | None = Field(
        None, description="When stable is null: the condition on the parameters for ω² > 0."
    )
    unstable_when: ExprPair | None = Field(
        None, description="When stable is null: the condition for ω² < 0 (stable_when reversed)."
    )


class Letter(BaseModel):
    latex: str
    unicode: str


class EffectivePotential(BaseModel):
    model_config = OPEN
    coordinate: str
    momenta: list[str]
    potential: ExprPair
    mass: ExprPair
    inertia: Letter | None = Field(
        default=None,
        description=f"The letter the page prints `mass` with: {ANGLE_INERTIA.unicode}, an {ANGLE_INERTIA.words}, where "
        f"the coordinate is an angle; {MASS_INERTIA.unicode}, an {MASS_INERTIA.words}, where it is a length.",
    )
    condition: ExprPair
    omega_squared: ExprPair
    equilibria: list[Equilibrium]


class Mode(BaseModel):
    model_config = OPEN
    omega_squared: float = Field(description="At the default parameters; negative along an unstable direction.")
    shape: dict[str, float] = Field(description="Amplitude of each coordinate, largest component 1.")
    sympy: str | None = Field(description="omega^2 in closed form, when it is short.")
    latex: str | None


class NormalModesAt(BaseModel):
    model_config = OPEN
    equilibrium: dict[str, float] = Field(description="The equilibrium, coordinate -> value at the default parameters.")
    stable: bool = Field(description="No mode grows exponentially (kind stable or neutral).")
    kind: str = Field(description="stable (every omega^2 > 0), neutral (some omega^2 = 0) or unstable.")
    momenta: dict[str, float] = Field(
        description="Conserved momenta held fixed, for a steady motion of the one-coordinate reduction."
    )
    modes: list[Mode]


class HamiltonEquation(BaseModel):
    model_config = OPEN
    coordinate: str
    q_dot: ExprPair = Field(description="dH/dp_q, in q and the momenta p_q.")
    p_dot: ExprPair = Field(description="-dH/dq plus the generalized force, in q and the momenta p_q.")


class Hamilton(BaseModel):
    model_config = OPEN
    hamiltonian: ExprPair = Field(description="H(q, p, t); the momentum of coordinate q is the symbol p_q.")
    equations: list[HamiltonEquation]


class SkippedMember(BaseModel):
    model_config = OPEN
    member: str = Field(
        description="The member left out: accelerations (closed form), steps, effective_potential, "
        "constraint_forces, transformed, hamilton or normal_modes; it is then null or empty in the document."
    )
    reason: str = Field(description="Which part was left out and why (its own time bound, or a closed form too long).")


class NotationEntry(BaseModel):
    """One letter of a document's "Symbols" table: each letter means one quantity on its page."""

    model_config = OPEN
    latex: str
    unicode: str
    meaning: str = Field(description="what the letter stands for (a parameter's own description)")
    unit: str = Field(description="a parameter's unit; empty for the others")
    kind: Literal["coordinate", "parameter", "derived"]


class DerivationDocument(BaseModel):
    """The derivation JSON, the same document as GET /api/scenes/{id}/derivation."""

    model_config = OPEN
    coordinates: list[str]
    notation: list[NotationEntry] = Field(
        description="the page's letters, each once: coordinates, parameters, then the derived quantities (the mass "
        "matrix is ℳ where a body's mass is M, a small-oscillation frequency Ω where ω is a parameter)"
    )
    parameters: dict[str, ParameterInfo]
    kinetic: ExprPair | None
    potential: ExprPair | None
    lagrangian: ExprPair
    hamiltonian: ExprPair
    energy: ExprPair
    equations_of_motion: list[EquationOfMotion]
    accelerations: dict[str, ExprPair]
    mass_matrix: list[list[ExprPair]]
    forcing: list[ExprPair]
    momenta: dict[str, ExprPair]
    generalized_forces: dict[str, ExprPair]
    cyclic: list[str]
    conserved: list[ConservedQuantity]
    explicit_time_derivative: ExprPair
    hamiltonian_equals_energy: bool | None = Field(
        description="Whether h = E: true, false, or null when it cannot be decided (only L was given, so T and U "
        "cannot be told apart); hamiltonian_energy_reason says why."
    )
    hamiltonian_energy_reason: str
    hamiltonian_conserved: bool = Field(description="Whether h is conserved (dh/dt = −∂L/∂t + Σ Q q̇ = 0).")
    hamiltonian_conserved_reason: str
    energy_minus_hamiltonian: ExprPair
    kinetic_focus_possible: bool = Field(
        True,
        description="Whether a true path can reach a kinetic focus: false where L is at most linear in the "
        "coordinates, has no coordinate-velocity product and a constant mass matrix (the Jacobi fields are then "
        "η = a t, which never vanish again), so the true path is a minimum of S for every duration.",
    )
    effective_potential: EffectivePotential | None
    steps: list[Step]
    hamilton: Hamilton | None = None
    normal_modes: list[NormalModesAt] = Field(default_factory=list)
    skipped: list[SkippedMember] = Field(
        default_factory=list,
        description="Members of the document left out, each with its reason: every member beyond the equations "
        "of motion has its own time bound, and one that runs out is skipped here instead of refusing the system.",
    )


# ---- simulate ----------------------------------------------------------------------------


def _simulate_fields() -> dict[str, Any]:
    """The scene simulate request's fields except ``parameters`` (a user system declares its values)."""
    return {
        name: (field.annotation, field) for name, field in SimulateRequest.model_fields.items() if name != "parameters"
    }


UserSimulateRequest = create_model(
    "UserSimulateRequest",
    __base__=SystemSpec,
    __doc__="A system as for POST /api/derive (parameter values from its `parameters`), plus what to simulate.",
    **_simulate_fields(),
)


def system_of(body: BaseModel) -> dict[str, Any]:
    """The declared system of a body that extends ``SystemSpec`` (simulate, Poincaré), as plain data."""
    return SystemSpec.model_validate(body.model_dump(include=set(SystemSpec.model_fields))).to_spec()


def simulate_request(body: BaseModel) -> SimulateRequest:
    """The numerics' request for a user system: parameter values from the declaration."""
    values = {p["name"]: p["value"] for p in system_of(body)["parameters"]}
    rest = body.model_dump(include=set(SimulateRequest.model_fields) - {"parameters"})
    # every field was validated with the same rules in the body; the numerics check the values by name
    return SimulateRequest.model_construct(parameters=values, **rest)
