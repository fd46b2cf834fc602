"""The singular-mass-matrix verdict does not depend on units (issue 19).

Scaling every mass or length by 10⁻⁶ or 10⁶ changes M into c S M S; a valid system must stay
valid, with the same (scaled) accelerations, and a singular one must stay singular.
"""

import pytest
import sympy as sp

from app.engine.derivation.derive import accelerations_only, derive
from app.engine.errors import DerivationError
from app.scenes import SCENES
from app.scenes.types import Parameter, Particle, System
from tests.engine.scaling import check_scaled_accelerations, factors_for, scaling_cases

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

G = Parameter("g", 9.81, "m/s²", 0.1, 100.0)


def test_a_gram_in_three_coordinates_is_a_valid_system():
    # the report: a free particle of mass 0.001 in three coordinates was refused as singular
    system = System(
        coordinates=("x", "y", "z"),
        parameters=(G,),
        particles=(Particle("0.001", ("x", "y", "z")),),
        potential="0.001*g*z",
    )
    acc = derive(system).equations.accelerations
    assert [sp.simplify(a) for a in acc] == [0, 0, -sp.Symbol("g", real=True)]


def test_a_centimetre_double_pendulum_of_ten_grams_is_valid():
    system = System(
        coordinates=("a", "b"),
        parameters=(G,),
        particles=(
            Particle("0.01", ("0.01*sin(a)", "-0.01*cos(a)", "0")),
            Particle("0.01", ("0.01*sin(a) + 0.01*sin(b)", "-0.01*cos(a) - 0.01*cos(b)", "0")),
        ),
        potential="-0.01*g*0.01*(2*cos(a) + cos(b))",
    )
    assert len(accelerations_only(system).accelerations) == 2


@pytest.mark.parametrize("factor", [1e-6, 1.0, 1e6])
@pytest.mark.parametrize("lagrangian", ["(x_dot + y_dot)**2/2 - x**2", "x_dot**2/2", "(x_dot + 2*y_dot)**2 - y"])
def test_a_singular_matrix_stays_singular_at_any_scale(lagrangian, factor):
    system = System(coordinates=("x", "y"), lagrangian=f"{factor!r}*({lagrangian})")
    with pytest.raises(DerivationError, match="singular"):
        accelerations_only(system)


@pytest.mark.parametrize("factor", [1e-6, 1e6])
def test_coordinates_in_very_different_units_are_not_singular(factor):
    # x in kilometres, y in micrometres: M = diag(2e6 f, 2e-6 f), condition number 1e12, yet invertible
    system = System(coordinates=("x", "y"), lagrangian=f"{factor!r}*(1e6*x_dot**2 + 1e-6*y_dot**2 + x*y_dot)")
    assert len(accelerations_only(system).accelerations) == 2


def test_a_coordinate_missing_from_T_is_singular_at_any_scale():
    for factor in (1e-6, 1e6):
        system = System(coordinates=("x", "y"), kinetic=f"{factor!r}*x_dot**2/2", potential=f"{factor!r}*y**2")
        with pytest.raises(DerivationError, match="singular"):
            accelerations_only(system)


SCENE_SYSTEMS = {k: s.system for k, s in SCENES.items()}
CASES = scaling_cases(SCENE_SYSTEMS)


@pytest.fixture(scope="module")
def originals():
    return {}


@pytest.mark.parametrize(("scene_id", "units", "factor"), CASES, ids=[f"{s}-{'+'.join(u)}-{f:g}" for s, u, f in CASES])
def test_scaled_scene_keeps_its_accelerations(scene_id, units, factor, originals):
    system = SCENE_SYSTEMS[scene_id]
    if scene_id not in originals:
        originals[scene_id] = accelerations_only(system).accelerations
    check_scaled_accelerations(system, factors_for(system, units, factor), originals[scene_id])
