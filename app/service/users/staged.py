"""The derivation in two stages: the equations first, the whole document after.

A student who types a system waits for its equations of motion; the rest of the document (the steps,
the conserved quantities, Hamilton's equations, the normal modes) takes seconds more for a chain. The
first stage is a small worker job of its own: the same derivation (``user_jobs.derive_checked``, kept
per worker, so a full job on the same worker starts from it) printed only as far as the equations, the
accelerations, the mass matrix and the forcing, under the same hard limit as a derivation.  Its
document says which members are still to come (``pending``), in the words the page shows.

Only the web layer's routes call this; SymPy runs in the worker pool, never here.
"""

from __future__ import annotations

import asyncio

from app.engine.document.contract import first_stage
from app.engine.document.model import Document, FirstStage
from app.engine.parser.user_system import UserSystem
from app.service.runtime.encoding import dumps
from app.service.users.user_checks import spec_key
from app.service.users.user_jobs import derive_checked, encoded, engine_budget, guarded
from app.service.users.user_systems import UserSystems


def equations_job(user: UserSystem) -> bytes:
    """Worker job: the first stage of a user system's derivation document (as JSON bytes)."""

    def run() -> FirstStage:
        with engine_budget(user):
            return FirstStage.model_validate(first_stage(derive_checked(user)))

    return guarded(run, encoded)


async def equations_or_whole(users: UserSystems, user: UserSystem, client: str, address: str) -> Document | FirstStage:
    """The whole document when it is cached already, else the first stage (a job of its own, cached too); each
    read from its JSON off the event loop."""
    whole = users.derivations.get(spec_key(user))
    if whole is not None:
        return await asyncio.to_thread(Document.model_validate_json, whole)
    body = await users.run_job(
        users.derivations, spec_key(user, "equations"), client, address, users.derive_seconds, equations_job, user
    )
    return await asyncio.to_thread(FirstStage.model_validate_json, body)


def _from_whole(whole: bytes) -> bytes:
    """The first stage's members of a whole document (``"stage": "whole"``, nothing pending), as JSON bytes: an
    API caller gets the same shape either way (the whole document's notation is not repeated)."""
    d = Document.model_validate_json(whole)
    stage = FirstStage(
        stage="whole", coordinates=d.coordinates, angles=d.angles, symbols=d.symbols, parameters=d.parameters,
        equations_of_motion=d.equations_of_motion, accelerations=d.accelerations, mass_matrix=d.mass_matrix,
        forcing=d.forcing, skipped=d.skipped, pending=[],
    )  # fmt: skip
    return dumps(stage.as_json())


async def equations_bytes(users: UserSystems, user: UserSystem, client: str, address: str) -> bytes:
    """POST /api/derive/equations: the first stage as JSON bytes; taken from the whole document when it is cached
    (then ``stage`` is ``whole`` and ``pending`` empty), decoded and encoded off the event loop."""
    whole = users.derivations.get(spec_key(user))
    if whole is not None:
        return await asyncio.to_thread(_from_whole, whole)
    return await users.run_job(
        users.derivations, spec_key(user, "equations"), client, address, users.derive_seconds, equations_job, user
    )
