"""Request and response models of the user-system API (POST /api/derive, POST /api/simulate).

Shapes only; the limits a model cannot express (names, expressions) are
checked by ``app.service.users.user_checks.check_system`` with located messages.
Every float is finite: JSON's ``NaN`` and ``Infinity`` (which Python's
``json`` accepts) are refused with a 422.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, Field, create_model

from app.engine.document.trees import FUNCTIONS as TREE_FUNCTIONS
from app.engine.parser.parse import FUNCTIONS, MAX_LENGTH
from app.numerics import limits
from app.service.users.user_checks import MAX_COORDINATES, MAX_PARAMETERS, MAX_PARTICLES
from app.web.schemas.common import STRICT
from app.web.schemas.simulate import SimulateRequest

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
