"""Errors the engine raises for declarations it cannot derive."""

from app.errors import Refused, TooMuchWork


def excerpt(text: object, limit: int = 40) -> str:
    """A short excerpt of user input for a message: never more than ``limit`` characters echoed back."""
    shown = str(text)
    return shown if len(shown) <= limit else shown[: limit - 3] + "..."


class DerivationError(Refused):
    """A system the engine refuses; the message says what is wrong and what is allowed.

    ``part`` names the offending piece of the input when there is one.
    """

    def __init__(self, message: str, part: str = ""):
        super().__init__(message, part)


class EquationsTooCostly(DerivationError, TooMuchWork):
    """A system whose equations of motion need more work than the engine gives them (``EQUATIONS_WORK``): refused
    at the same count of work on an idle machine and a loaded one."""
