"""Session cookies: a valid one is recognised, anything else is simply not a session."""

import pytest

from app.service.fairness import Fairness


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
