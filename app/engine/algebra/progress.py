"""Which part of a derivation the engine is working on, told to whoever listens.

A worker's derivation job listens (app/service/runtime/progress.py) so that the page waiting for it can say "now:
Hamilton's equations, for 4 s"; with no listener, telling costs a lookup.  The parts are named as the page
names them, in lower case: "the equations of motion", "the step-by-step derivation", "Hamilton's equations".
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

_listener: ContextVar[Callable[[str], None] | None] = ContextVar("progress_listener", default=None)


@contextmanager
def listening(listener: Callable[[str], None]) -> Iterator[None]:
    """Within the block, ``listener(part)`` is called as each part of a derivation begins."""
    token = _listener.set(listener)
    try:
        yield
    finally:
        _listener.reset(token)


def now(part: str) -> None:
    """The engine begins ``part`` (told to the listener, if any; a listener's failure never stops the work)."""
    listener = _listener.get()
    if listener is not None:
        try:
            listener(part[:1].lower() + part[1:] if not part.startswith("Hamilton") else part)
        except OSError:
            pass
