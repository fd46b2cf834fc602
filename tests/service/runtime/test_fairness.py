"""Session cookies: a valid one is recognised, anything else is simply not a session."""

import pytest

from app.service.runtime.fairness import Fairness


@pytest.fixture
def gate():
    return Fairness(capacity=4)


def test_a_minted_cookie_verifies(gate):
    token = gate.mint("127.0.0.1")
    assert gate.verify(token) == token.partition(".")[0]


@pytest.mark.parametrize(
    "token",
    [None, "", "é.abc", "ünïcode.sig", "abc", "a.b.c", "x" * 101, "abc.", ".abc", "\x00.\x00", "abc.\u2028"],
)
def test_anything_else_is_not_a_session(gate, token):
    assert gate.verify(token) is None


def test_a_tampered_signature_is_not_a_session(gate):
    session, _, signature = gate.mint("127.0.0.1").partition(".")
    assert gate.verify(f"{session}.{signature[::-1]}") is None
    assert gate.verify(f"{session}x.{signature}") is None


def test_a_class_has_a_budget_of_its_own_not_its_networks():
    """Sixty students of one class behind one address: each student one check at a time, the class up to
    ``class_check_slots`` in flight beyond the server's capacity; a network's anonymous jobs keep their share."""
    from app.service.runtime.fairness import Busy
    from app.settings import settings

    gate = Fairness(capacity=8, workers=2)
    slots = settings().class_check_slots
    tickets = [gate.admit(f"class-student:1:{i}", "class:1") for i in range(slots)]
    with pytest.raises(Busy, match="checks of your class are already running"):
        gate.admit(f"class-student:1:{slots}", "class:1")
    with pytest.raises(Busy, match="you already have"):  # a student's second check waits for the first
        gate.admit("class-student:1:0", "class:1")
    other = gate.admit("class-student:2:0", "class:2")  # another class is not held back by this one's budget
    anonymous = [gate.admit(f"session:{i}", "10.0.0.1") for i in range(gate.per_address)]
    with pytest.raises(Busy, match="from your network address"):
        gate.admit("new:10.0.0.1", "10.0.0.1")
    for ticket in [*tickets, other, *anonymous]:
        ticket.release()
    assert gate.in_flight == 0
