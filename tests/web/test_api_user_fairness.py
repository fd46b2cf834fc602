"""Fair shares of the worker pool: sessions, per-address caps, a global cap, minting limits."""

import pytest

from app.service.fairness import Busy, Fairness


@pytest.fixture
def gate():
    return Fairness(capacity=4, workers=2, per_address=2, mint_per_minute=3)


def test_one_job_per_client(gate):
    ticket = gate.admit("session:a", "10.0.0.1")
    with pytest.raises(Busy) as caught:
        gate.admit("session:a", "10.0.0.1")
    assert not caught.value.whole_server and caught.value.retry_after >= 1
    ticket.release()
    gate.admit("session:a", "10.0.0.1").release()


def test_a_classroom_behind_one_address_shares_it_up_to_the_cap(gate):
    first = gate.admit("session:a", "school")
    second = gate.admit("session:b", "school")
    with pytest.raises(Busy) as caught:
        gate.admit("session:c", "school")
    assert not caught.value.whole_server and "network address" in str(caught.value)
    # another address is not affected by the classroom's share
    other = gate.admit("session:d", "home")
    for ticket in (first, second, other):
        ticket.release()


def test_the_global_cap_answers_503(gate):
    tickets = [gate.admit(f"session:{i}", f"10.0.0.{i}") for i in range(4)]
    with pytest.raises(Busy) as caught:
        gate.admit("session:late", "10.0.0.99")
    assert caught.value.whole_server and 1 <= caught.value.retry_after <= 30
    tickets[0].release()
    gate.admit("session:late", "10.0.0.99").release()
    for ticket in tickets[1:]:
        ticket.release()
    assert gate.in_flight == 0


def test_release_is_idempotent(gate):
    ticket = gate.admit("session:a", "x")
    ticket.release()
    ticket.release()
    assert gate.in_flight == 0
    gate.admit("session:a", "x")
    assert gate.in_flight == 1


def test_sessions_are_signed(gate):
    token = gate.mint("10.0.0.1")
    session = gate.verify(token)
    assert session and token.startswith(session + ".")
    assert gate.verify(session + ".forged") is None
    assert gate.verify("no-signature") is None
    assert gate.verify(None) is None
    assert gate.verify("a." * 200) is None
    # a server with another key does not accept this one's tokens
    assert Fairness(capacity=1, secret="another key").verify(token) is None


def test_minting_is_rate_limited_per_address(gate):
    assert all(gate.mint("10.0.0.1") for _ in range(3))
    assert gate.mint("10.0.0.1") is None
    assert gate.mint("10.0.0.2") is not None
