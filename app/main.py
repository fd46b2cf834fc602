"""The ASGI application: ``app.main:app``."""

from __future__ import annotations

import threading
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from fastapi import FastAPI

from app.service import derivations, simulation
from app.web import api_scenes, errors, limits, pages
from app.web.api_simulate import router as simulate_router
from app.web.api_user import router as user_router
from app.web.playground import router as playground_router
from app.web.templating import static_app


@asynccontextmanager
async def lifespan(app: FastAPI) -> AsyncIterator[None]:
    # Fill the derivation cache, then load the compiled integrators and the scenes'
    # right-hand sides, in the background: the server answers at once, and a request
    # for a scene not yet ready waits only for that scene.
    def warm() -> None:
        derivations.warm_all()
        simulation.warm_all()

    threading.Thread(target=warm, name="warm-up", daemon=True).start()
    yield


app = FastAPI(
    title="Lagrange",
    summary="An interactive textbook of Lagrangian mechanics: derivations, simulations and their errors.",
    version="0.1.0",
    lifespan=lifespan,
)
errors.install(app)
limits.install(app)  # every POST body capped before it is read

ROUTERS = [api_scenes.router, pages.router, user_router, simulate_router, playground_router]
app.mount("/static", static_app, name="static")
for router in ROUTERS:
    app.include_router(router)


@app.get("/healthz", tags=["service"], summary="Liveness and readiness probe")
def health() -> dict[str, str]:
    return {"status": "ok"}
