"""The kinds of failure every layer reports, in one place (below all layers; imports nothing from ``app``).

Each kind says what went wrong in words for the person who asked; none carries
an HTTP status.  The web layer maps each kind to one response, for JSON and HTML
routes alike (app/web/api/errors.py):

* ``Refused``: the input is not allowed; ``loc`` locates the field, ``part`` and
  ``start``/``end`` the offending piece of its text;
* ``TooMuchWork``: a refusal because the work would exceed (or did exceed) a
  time, step or size budget;
* ``OverCapacity``: not now, try again in ``retry_after`` seconds, because this
  client already has work running (``whole_server`` false) or because the
  server is full (``whole_server`` true);
* ``WorkerFailed``: a worker process did not finish a job (``kind``: timeout,
  memory, crashed, or unavailable when no worker could be had);
* ``UnknownScene``: no scene has this id;
* ``NoKey``: a class's route was asked without a key (``Authorization: Bearer``);
* ``WrongKey``: the key given does not open this route of this class (a wrong key,
  a student's key on an instructor's route, another class's key, or an unknown code);
* ``UnknownClass``: no class has this code (joining only: a keyed route says WrongKey);
* ``UnknownAssignment``: the class has no assignment of this number;
* ``ClassClosed``: the class's instructor has closed joining, or stopped answers (what was recorded is kept).
"""

from __future__ import annotations


class Refused(ValueError):
    """Input refused; the message says what is wrong and what is allowed.

    ``part`` is the offending piece of the input, ``loc`` the path of the offending
    field in the request (``None`` when the refusal is not about one field), and
    ``start``/``end`` the span of ``part`` in that field's text.
    """

    def __init__(
        self,
        message: str,
        part: str = "",
        loc: tuple | None = None,
        start: int | None = None,
        end: int | None = None,
    ):
        super().__init__(message)
        self.part = part
        self.loc = None if loc is None else tuple(loc)
        self.start = start
        self.end = end

    def __reduce__(self):
        # keep every field when the error crosses a process boundary (worker pool)
        return (_rebuild, (type(self), str(self), self.__dict__))


def _rebuild(kind: type[Exception], message: str, fields: dict) -> Exception:
    exc = kind.__new__(kind)
    Exception.__init__(exc, message)
    exc.__dict__.update(fields)
    return exc


class TooMuchWork(Refused):
    """The work would exceed (or did exceed) its time, step or size budget."""


class OverCapacity(Exception):
    """Work refused for now: retry in ``retry_after`` seconds.

    ``whole_server`` is false when this client's own work is in the way (one job at a
    time, a throttled kind of run already going), true when the server is full.
    """

    def __init__(self, message: str, retry_after: int, whole_server: bool = False):
        super().__init__(message)
        self.retry_after = retry_after
        self.whole_server = whole_server

    def __reduce__(self):
        return (type(self), (str(self), self.retry_after, self.whole_server))


class WorkerFailed(Exception):
    """A job that did not finish: ``kind`` is timeout, memory, crashed or unavailable."""

    def __init__(self, message: str, kind: str):
        super().__init__(message)
        self.kind = kind

    def __reduce__(self):
        return (type(self), (str(self), self.kind))


class UnknownScene(KeyError):
    """No scene has this id; the message lists the known ones."""

    def __init__(self, scene_id: str, known: tuple[str, ...] = ()):
        super().__init__(scene_id)
        self.scene_id = scene_id
        self.known = known

    def __str__(self) -> str:
        return f"no scene with id {self.scene_id[:60]!r}; known scenes: {', '.join(self.known)}"


class NoKey(Exception):
    """A class's route asked without a key; the message says which key it needs."""


class WrongKey(Exception):
    """The key does not open this route of this class; the same answer whether the code or the key is wrong."""


class UnknownClass(KeyError):
    """No class has this code (to join); the message says what a code looks like."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else "no class has this code"


class UnknownAssignment(KeyError):
    """The class has no assignment of this number; the message says which numbers it has."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else "the class has no assignment of this number"


class ClassClosed(Exception):
    """The instructor closed the class to this for now: joining (new students), or answers (every student); what the
    class recorded is kept, and the instructor may reopen it.  The message says which, for a student to read."""
