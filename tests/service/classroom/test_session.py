"""Ending a session without deleting the class (issue 44, item 7), in the store: joining closed refuses a new
student and lets a student who joined back in; answers stopped are said on every key's access; closing again keeps
the first time; reopening clears it."""

from __future__ import annotations

import pytest

from app.errors import ClassClosed
from app.service.classroom import store
from app.service.classroom.database import Database
from app.settings import Settings

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


def test_joining_closed_and_answers_stopped_are_kept_in_the_class(tmp_path):
    db = Database(Settings(data_dir=tmp_path))
    try:
        code, key, _recovery = store.create_class(db, "Mechanics")
        class_id = store.access(db, code, key).class_id
        ada_key, ada, ada_recovery = store.join(db, code, "Ada")
        assert store.class_session(db, class_id) == {"joining_open": True, "joining_closed_at": None,
                                                     "answers_open": True, "answers_stopped_at": None}

        closed = store.set_session(db, class_id, False, None)
        assert (closed["joining_open"], closed["answers_open"]) == (False, True)
        with pytest.raises(ClassClosed, match="closed joining"):
            store.join(db, code, "Quentin")
        # Ada joined before: her record opens on another device, and her key still opens the class
        store.rejoin(db, code, "Ada", ada_recovery)
        assert store.access(db, code, key).joining_closed and not store.access(db, code, key).answers_stopped

        # closing again keeps the time it was first closed; stopping answers is said on a student's access too
        again = store.set_session(db, class_id, False, False)
        assert again["joining_closed_at"] == closed["joining_closed_at"] and again["answers_stopped_at"] is not None
        new_key, _who = store.rejoin(db, code, "Ada", ada_recovery)
        assert store.access(db, code, new_key).answers_stopped

        opened = store.set_session(db, class_id, True, True)
        assert opened == {"joining_open": True, "joining_closed_at": None, "answers_open": True, "answers_stopped_at": None}
        store.join(db, code, "Quentin")
        assert ada_key and ada.name == "Ada"
    finally:
        db.stop()
