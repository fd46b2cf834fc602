"""Rods inferred from the particles, and no invented picture for a system without particles."""

import pytest

from app.engine.derivation.derive import derive
from app.engine.derivation.rods import fixed_distances
from app.engine.document.model import FixedDistance
from app.scenes.types import Parameter, Particle, System
from app.viz.mechanism import NO_PICTURE, mechanism
from app.viz.rods import rods

DOUBLE = [
    ("", ("l1*sin(theta1)", "-l1*cos(theta1)", "0")),
    ("", ("l1*sin(theta1) + l2*sin(theta2)", "-l1*cos(theta1) - l2*cos(theta2)", "0")),
]
LENGTHS = {"m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 0.7, "g": 9.81}


def test_double_pendulum_numerically_two_rods_and_a_pivot():
    found = rods(DOUBLE, ["theta1", "theta2"], LENGTHS)
    assert found == [(None, 0, True), (0, 1, True)]
    spec = mechanism("playground", DOUBLE, ["theta1", "theta2"], False, defaults=LENGTHS)
    assert [p["label"] for p in spec["points"]] == ["mass 1", "mass 2", "pivot"]
    assert [(link["from"], link["to"], link["style"]) for link in spec["links"]] == [(2, 0, "rod"), (0, 1, "rod")]
    assert all(link["check"] for link in spec["links"])  # found numerically: the browser confirms them
    assert spec["axes"] == ["x", "y"]  # the example's vertical is y


@pytest.mark.slow
def test_double_pendulum_symbolically_from_the_engine():
    system = System(
        coordinates=("theta1", "theta2"),
        parameters=tuple(Parameter(n, v) for n, v in LENGTHS.items()),
        particles=(Particle("m1", DOUBLE[0][1]), Particle("m2", DOUBLE[1][1])),
        potential="-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)",
    )
    proven = fixed_distances(derive(system))
    assert proven == [{"from": None, "to": 0}, {"from": 0, "to": 1}]
    found = rods(DOUBLE, ["theta1", "theta2"], LENGTHS, [FixedDistance.model_validate(p) for p in proven])
    assert found == [(None, 0, False), (0, 1, False)]


def test_a_pendulum_given_by_its_particle_gets_a_rod_of_its_length():
    bob = [("bob", ("R*sin(q)", "0", "-R*cos(q)"))]
    spec = mechanism("playground", bob, ["q"], False, defaults={"R": 2.5})
    pivot = [p["label"] for p in spec["points"]].index("pivot")
    assert [(link["from"], link["to"]) for link in spec["links"]] == [(pivot, 0)]


@pytest.mark.parametrize(
    "particles",
    [
        [("", ("x", "0", "0"))],  # a particle on a line: its distance to the origin changes
        [("", ("r*cos(q)", "r*sin(q)", "0"))],  # a polar particle with a free radius
        [("", ("cos(t) + q", "0", "0")), ("", ("q", "1", "0"))],  # distance between them varies with t
    ],
)
def test_varying_distances_get_no_rod(particles):
    coordinates = sorted({c for c in ("x", "r", "q") if any(c in "".join(p) for _, p in particles)})
    assert rods(particles, coordinates, {}) == []


def test_a_fixed_particle_gets_no_rod():
    assert rods([("", ("1", "0", "0")), ("", ("sin(q)", "cos(q)", "0"))], ["q"], {}) == [(None, 1, True)]


def test_a_system_without_particles_has_no_picture():
    spec = mechanism("playground", [], ["theta"], False, defaults={"R": 1.0})
    assert spec["none"] and spec["points"] == [] and spec["caption"] == NO_PICTURE
    assert "no particle positions" in NO_PICTURE


def test_an_elastic_pendulum_hangs_on_a_spring_from_a_pivot():
    from app.engine.document.trees import of_text
    from app.viz.mechanism import mechanism

    particles = [("bob", ("r*sin(theta)", "0", "-r*cos(theta)"))]
    potential = of_text("k*(r - l)**2/2 - m*g*r*cos(theta)")
    spec = mechanism(
        "playground",
        particles,
        ["r", "theta"],
        False,
        defaults={"k": 10, "l": 1, "m": 1, "g": 9.81},
        potential=potential,
    )
    assert [p["label"] for p in spec["points"]] == ["bob", "pivot"]
    assert spec["links"] == [{"from": 1, "to": 0, "style": "spring"}]
    assert "spring from the fixed pivot (its length is r)" in spec["caption"]
    # without a spring's energy in U the same positions get no spring: nothing is invented
    plain = mechanism(
        "playground",
        particles,
        ["r", "theta"],
        False,
        defaults={"m": 1, "g": 9.81},
        potential=of_text("-m*g*r*cos(theta)"),
    )
    assert plain["links"] == []
