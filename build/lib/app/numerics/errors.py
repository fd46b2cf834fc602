"""Errors a simulation can end with (kinds from app/errors.py; the web layer maps them to responses)."""

from __future__ import annotations

from typing import Any

from app import errors
from app.engine.errors import DerivationError


class SimulationError(DerivationError):
    """A request the numerics refuses or cannot finish; the message says what and what to change.

    A ``DerivationError`` (a ``Refused``), so every layer that reports those
    (the app's handlers, the user-system worker) reports it with its message.
    """


class TooMuchWork(SimulationError, errors.TooMuchWork):
    """The run would exceed (or did exceed) its step or wall-clock budget.

    ``partial``: the samples the run had reached when it stopped (a ``Trajectory``, incomplete, saying how
    far it got), when the method keeps them; ``auto`` answers with them instead of refusing."""

    partial: Any = None
    what: str = ""  # what ran out, e.g. "the wall-clock budget ran out" (set by ``Method.too_much``)
