"""Errors a simulation can end with; each carries the HTTP status the API maps it to."""

from __future__ import annotations


class SimulationError(ValueError):
    """A request the numerics refuses or cannot finish; the message says what and what to change."""

    status_code = 422

    def __init__(self, message: str, part: str = ""):
        super().__init__(message)
        self.part = part


class TooMuchWork(SimulationError):
    """The run would exceed (or did exceed) its step or wall-clock budget."""


class Busy(SimulationError):
    """Too many simulations are running at once."""

    status_code = 429
