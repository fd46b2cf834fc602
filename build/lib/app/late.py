"""Heavy libraries imported on first use, one thread at a time.

scipy's subpackages cost 0.3-1 s each to import (scipy.integrate, scipy.linalg, scipy.optimize):
a server that answers from its compiled kernels, or a page that never measures normal modes,
need not pay for them before it answers.  Two threads importing the same subpackage at once can
each meet the other's half-initialised submodules and fail (seen with scipy.integrate between the
warm-up and a first request), so every such import goes through one lock.  This module sits left
of every layer, beside the settings: it imports nothing from ``app``.
"""

from __future__ import annotations

import importlib
import threading
from types import ModuleType

_IMPORTING = threading.RLock()


def module(name: str) -> ModuleType:
    """``import name``, once per process and by one thread at a time (after that a dictionary lookup)."""
    with _IMPORTING:
        return importlib.import_module(name)
