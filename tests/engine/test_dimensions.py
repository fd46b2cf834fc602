"""Units as a reader reads them (app/engine/dimensions.py)."""

from fractions import Fraction

from app.engine.dimensions import unit_text


def test_a_denominator_of_several_units_is_bracketed():
    # student-i 5: "a quantity in 1/m·s²" read as (1/m)·s²
    assert unit_text({"m": Fraction(-1), "s": Fraction(-2)}) == "1/(m·s²)"
    assert unit_text({"s": Fraction(2), "kg": Fraction(-1), "m": Fraction(-1)}) == "s²/(kg·m)"
    # one unit below needs none, and an energy is as it was
    assert unit_text({"m": Fraction(1), "s": Fraction(-2)}) == "m/s²"
    assert unit_text({"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-2)}) == "kg·m²/s²"
    assert unit_text({}) == "1"
