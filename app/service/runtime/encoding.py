"""JSON bytes of the documents the service produces (simulations, derivations), numpy arrays included.

orjson encodes a default simulation document in well under a millisecond
(``json.dumps`` after FastAPI's ``jsonable_encoder`` took 11-16 ms), and writes
NaN and Infinity as null, as the documented JSON has them.
"""

from __future__ import annotations

import json
import math
from typing import Any

import orjson

OPTIONS = orjson.OPT_SERIALIZE_NUMPY


def dumps(document: Any) -> bytes:
    try:
        return orjson.dumps(document, option=OPTIONS)
    except orjson.JSONEncodeError:  # e.g. an integer beyond 64 bits in a derivation document
        return json.dumps(_finite(document), allow_nan=False, separators=(",", ":")).encode()


def _finite(value: Any) -> Any:
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_finite(v) for v in value]
    if hasattr(value, "tolist"):
        return _finite(value.tolist())
    return value
