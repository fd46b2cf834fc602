"""The ASGI application: ``app.main:app``."""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from typing import Any

from fastapi import FastAPI

from app.service.chapter.derivations import PROCESS_SCENES
from app.service.runtime import resident
from app.service.runtime.memory import freeze_imported, freeze_when_done
from app.service.services import Services
from app.service.simulations import simulation
from app.settings import settings
from app.web.api import action as api_action
from app.web.api import beyond as api_beyond
from app.web.api import docs, errors, limits, openapi
from app.web.api import scenes as api_scenes
from app.web.api.check import router as check_router
from app.web.api.simulate import router as simulate_router
from app.web.api.staged import router as staged_router
from app.web.api.typeset import router as typeset_router
from app.web.api.user import router as user_router
from app.web.http import slow_clients
from app.web.http.compression import ApiCompression
from app.web.http.etags import ETags
from app.web.http.headers import SecurityHeaders
from app.web.pages import chapter as pages
from app.web.pages import embed
from app.web.pages.classes import router as classes_router
from app.web.pages.playground import router as playground_router
from app.web.pages.playground import warm_examples
from app.web.rendering.page_cache import PageCache
from app.web.rendering.templating import static_app


@asynccontextmanager
async def lifespan(app: FastAPI) -> AsyncIterator[dict[str, Any]]:
    # the services (worker pool, user systems, checking, simulation slots), given to the routes by app/web/api/deps.py
    config = settings()
    # the chapter's scenes: this process's one copy (app/service/chapter/derivations.py), handed to the routes from here
    services = Services.start(config, PROCESS_SCENES)
    recording = resident.start_recording(config)  # this process's size, for the memory budget of the workers it starts
    # Fill the derivation cache, then load the compiled integrators and the scenes'
    # right-hand sides, in the background: the server answers at once, with scipy
    # while a compiled integrator is not ready yet.
    if settings().warm:
        # the imported modules out of the collector's full scans before the warm-up's allocations trigger some
        freeze_imported()
        warming = simulation.start_warming(services.chapter, services.gates)
        # then the playground's examples (from the disk cache set-up filled), so that a first reader of one
        # does not wait for its derivation
        examples = warm_examples(services.users, services.answers.examples, after=warming)
        # and the scenes' worker process, with the chapter's systems loaded
        services.warm(after=warming)
        # then what they loaded lives for the process: out of the garbage collector's full scans
        freeze_when_done(warming, examples)
    try:
        # the scene pages' models and rendered bytes beside them (app/web/rendering/page_cache.py, app/web/api/deps.py)
        yield {"services": services, "pages": PageCache()}
    finally:
        recording.set()
        services.stop()  # the worker pool's processes joined


app = FastAPI(
    title="Lagrange",
    summary="An interactive textbook of Lagrangian mechanics: derivations, simulations and their errors.",
    version="0.1.0",
    lifespan=lifespan,
    docs_url=None,  # app/web/api/docs.py serves /docs from our own copy of swagger-ui
    redoc_url=None,  # FastAPI's ReDoc page loads from a CDN
    generate_unique_id_function=openapi.operation_id,
)
errors.install(app)
openapi.install(app)  # the document with the API's HTTP conventions (problems, 415, Location, ETags)
app.add_middleware(ETags)  # inside the compression: the digest of the answer's own bytes
app.add_middleware(ApiCompression)
limits.install(app)  # every POST body capped before it is read
slow_clients.install()  # connection caps and deadlines on uvicorn's protocols, however the app is served
app.add_middleware(SecurityHeaders)  # outermost: on every response, errors included

ROUTERS = [
    api_scenes.router,
    api_beyond.router,
    api_action.router,
    pages.router,
    embed.router,
    docs.router,
    user_router,
    staged_router,
    simulate_router,
    playground_router,
    check_router,
    typeset_router,
    classes_router,
]
app.mount("/static", static_app(), name="static")
for router in ROUTERS:
    app.include_router(router)


@app.get("/healthz", tags=["service"], summary="Liveness and readiness probe")
async def health() -> dict[str, str]:
    # on the event loop, doing nothing: never queued behind simulations in the thread pool
    return {"status": "ok"}
