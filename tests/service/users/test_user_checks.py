"""Refusals by size before work (issue 43, item 3): the hostile corpus's expression bombs, in every field, are
refused by the web process's check from their size and shape alone, before SymPy builds a single expression, so
the time of their refusal does not grow with the machine's load."""

from __future__ import annotations

import pytest

from app.engine.algebra import work
from app.service.users.user_checks import InvalidSystem, checked
from tests.web.test_hostile_corpus import BOMBS, in_every_field

CASES = [(f"{name}-{field}", spec) for name, text in BOMBS.items() for field, spec in in_every_field(text)]


@pytest.mark.parametrize(("name", "spec"), CASES, ids=[name for name, _ in CASES])
def test_a_bomb_is_refused_before_any_symbolic_work(name, spec):
    before = work.done()
    with pytest.raises(InvalidSystem) as refused:
        checked(spec)
    assert work.done() == before, name  # not one SymPy expression built
    assert str(refused.value)  # a refusal that says what was wrong
