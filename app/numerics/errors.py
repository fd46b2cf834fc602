"""Errors a simulation can end with (kinds from app/errors.py; the web layer maps them to responses)."""

from __future__ import annotations

from app import errors
from app.engine.errors import DerivationError


class SimulationError(DerivationError):
    """A request the numerics refuses or cannot finish; the message says what and what to change.

    A ``DerivationError`` (a ``Refused``), so every layer that reports those
    (the app's handlers, the user-system worker) reports it with its message.
    """


class TooMuchWork(SimulationError, errors.TooMuchWork):
    """The run would exceed (or did exceed) its step or wall-clock budget."""
