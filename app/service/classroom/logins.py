"""A student's institution login, which a class may ask for so its grades import into an LMS without matching
pseudonyms by hand: the one home of the column names a class may choose and of what a login may be.

The instructor chooses the column's name the LMS matches rows by: Canvas's "SIS Login ID", Moodle's "username",
or a plain "Login" for another.  The grades file then has that column first, under that header.
"""

from __future__ import annotations

import unicodedata
from typing import Literal, get_args

from app.errors import Refused

# the header an LMS matches a grades file's rows by
LoginColumn = Literal["SIS Login ID", "username", "Login"]
LOGIN_COLUMNS: tuple[str, ...] = get_args(LoginColumn)
# the LMS each column is for, as the instructor's page and the join form name it
LMS = {"SIS Login ID": "Canvas", "username": "Moodle", "Login": "another LMS"}
MAX_LOGIN = 64  # characters: longer than any LMS's login or e-mail address a student types


def asked(column: str) -> str:
    """What the join form says when the class asks for a login: "your institution login (the SIS Login ID your
    teacher's Canvas knows you by)"."""
    lms = LMS.get(column, "")
    if column == "Login":
        return "your institution login (the one your school's learning platform knows you by)"
    return f"your institution login (the {column} {lms} knows you by)"


def checked_login(column: str | None, login: str | None) -> str | None:
    """The login to store for a class that asks (``column``) or not; a Refused at ``login`` that says what is wrong
    and what is allowed."""
    # spaces around it are forgiven; a control character anywhere is not (Python's strip() would drop some)
    text = (login or "").strip(" ")
    if column is None:
        if text:
            raise Refused("This class does not ask for an institution login: leave it out.", "", ("login",))
        return None
    if not text:
        raise Refused(f"This class asks for {asked(column)}: type it as you sign in there.", "", ("login",))
    if len(text) > MAX_LOGIN:
        raise Refused(f"An institution login has at most {MAX_LOGIN} characters; this one has {len(text)}.",
                      "", ("login",))
    if any(unicodedata.category(c) == "Cc" for c in text):
        raise Refused("An institution login is one line of letters, digits and signs, without control characters "
                      "(a tab or a line break): type it as you sign in.", "", ("login",))
    return text
