"""Errors a simulation can end with; each carries the HTTP status the API maps it to."""

from __future__ import annotations

from app.engine.errors import DerivationError


class SimulationError(DerivationError):
    """A request the numerics refuses or cannot finish; the message says what and what to change.

    A ``DerivationError``, so every layer that already maps those to a 422
    (the app's handlers, the user-system worker) reports it with its message.
    """

    status_code = 422


class TooMuchWork(SimulationError):
    """The run would exceed (or did exceed) its step or wall-clock budget."""


class Busy(SimulationError):
    """Too many simulations are running at once."""

    status_code = 429
