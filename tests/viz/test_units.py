"""Units of a user's coordinates: rad for angles, m where the dimensions say so, nothing where they cannot tell."""

from fractions import Fraction

import pytest

from app.engine.document.model import Document, Pair, ParameterInfo
from app.viz.units import coordinate_units, parse_unit


@pytest.mark.parametrize(
    ("text", "dims"),
    [
        ("kg", {"kg": 1}),
        ("N/m", {"kg": 1, "s": -2}),
        ("m/s²", {"m": 1, "s": -2}),
        ("m/s**2", {"m": 1, "s": -2}),
        ("kg·m²", {"kg": 1, "m": 2}),
        ("rad", {}),
        ("furlong", None),
        ("", None),
    ],
)
def test_units_are_read_as_dimensions(text, dims):
    got = parse_unit(text)
    assert got == (None if dims is None else {k: Fraction(v) for k, v in dims.items()})


def doc(coordinates, parameters, mass_matrix, angles=()):
    """A document with only the members the units are read from (the model's types, nothing else filled in)."""
    return Document.model_construct(
        coordinates=coordinates,
        angles=list(angles),
        parameters={n: ParameterInfo.model_construct(unit=u) for n, u in parameters.items()},
        mass_matrix=[[Pair.model_construct(tree=t) for t in row] for row in mass_matrix],
    )


def test_kepler_r_in_metres_theta_in_radians():
    # T = m/2 (r_dot² + r² theta_dot²): theta is cyclic (no trig function), named as an angle
    d = doc(["r", "theta"], {"m": "kg", "k": "N*m"}, [["m", 0], [0, ["*", "m", ["pow", "r", 2]]]])
    out = coordinate_units(d, scene=False)
    assert out["units"] == {"r": "m", "theta": "rad"}
    assert out["rate_units"] == {"r": "m/s", "theta": "rad/s"}
    assert out["momentum_units"] == {"r": "kg·m/s", "theta": "kg·m²/s"}


def test_an_angle_not_named_as_one_follows_from_its_mass_matrix_entry_and_unknown_stays_unitless():
    # u with M = m R² (R in m) is dimensionless but not named or used as an angle: no unit, never "m"
    d = doc(["u", "x"], {"m": "kg", "R": "m", "c": ""}, [[["*", "m", ["pow", "R", 2]], 0], [0, "c"]])
    assert coordinate_units(d, scene=False)["units"] == {"u": "", "x": ""}
    assert coordinate_units(d, scene=False)["rate_units"] == {"u": "1/s", "x": "1/s"}


def test_a_mass_matrix_with_the_velocity_in_it_still_gives_metres():
    # L = −mc²√(1 − ẋ²/c²): M_xx = m (1 − ẋ²/c²)^(−3/2), the tree the engine serves for it
    root = ["+", 1, ["neg", ["*", ["pow", "c", -2], ["pow", "x_dot", 2]]]]
    entry = ["+", ["*", "m", ["pow", root, -0.5]], ["*", "m", ["pow", "c", -2], ["pow", "x_dot", 2], ["pow", root, -1.5]]]
    assert coordinate_units(doc(["x"], {"m": "kg", "c": "m/s"}, [[entry]]), scene=False)["units"] == {"x": "m"}
    # with c in no unit nothing can be told, and nothing is printed
    assert coordinate_units(doc(["x"], {"m": "kg", "c": ""}, [[entry]]), scene=False)["units"] == {"x": ""}


def test_a_number_reads_with_its_unit_never_per_second():
    from app.viz.units import rate_unit, with_unit

    assert [with_unit("1", rate_unit(u)) for u in ("m", "rad", "")] == ["1 m/s", "1 rad/s", "1 s⁻¹"]
    assert with_unit("2.5", "") == "2.5"


def test_a_reciprocal_unit_is_printed_as_a_negative_power():
    from app.viz.page_model import allowed_text, unit_text

    # prof-g 43: "The slider marks 0.8155 1/m" on the rotating parabola
    assert unit_text("1/m") == "m⁻¹" and unit_text("1/s") == "s⁻¹" and unit_text("m/s^2") == "m/s²"
    assert allowed_text(0.01, 100, "1/m") == "0.01 to 100 m⁻¹"
