"""What routes are given through ``Depends``: the services and who is asking.

The services are built once by the app's lifespan (``app.main``), with the scene
pages' cache beside them (``PageCache``), and reach the routes as lifespan state;
what a running app remembers is theirs (docs/state.md).  Tests replace any of them with
``app.dependency_overrides[...]`` (a fake service, a gate with other limits)
instead of patching module globals.

Every dependency here is ``async def``: each only reads an attribute or checks
a cookie's signature (microseconds), and FastAPI runs a plain ``def``
dependency in its thread pool, one thread hop (0.3-1 ms on a busy 2-core
machine) per dependency per request.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Annotated

from fastapi import Depends, Request
from fastapi.responses import Response

from app.service.answers import Answers
from app.service.chapter.derivations import Scenes
from app.service.runtime.fairness import COOKIE, COOKIE_MAX_AGE, Fairness
from app.service.services import Services
from app.service.simulations.simulation import Gates
from app.service.tutor.checking import Checking
from app.service.users.user_systems import UserSystems
from app.settings import Settings, settings
from app.web.http.address import client_address
from app.web.rendering.page_cache import PageCache


async def services(request: Request) -> Services:
    """The services the lifespan started for the app serving this request."""
    return request.state.services


ServicesDep = Annotated[Services, Depends(services)]


async def user_systems_service(running: ServicesDep) -> UserSystems:
    return running.users


async def checking_service(running: ServicesDep) -> Checking:
    return running.checking


async def simulation_gates(running: ServicesDep) -> Gates:
    return running.gates


async def remembered_answers(running: ServicesDep) -> Answers:
    return running.answers


async def scenes_chapter(running: ServicesDep) -> Scenes:
    """The scenes' derivations, documents and compiled systems the app serves (app/service/chapter/derivations.py)."""
    return running.chapter


async def page_cache(request: Request) -> PageCache:
    """The scene pages' models and rendered bytes, built by the lifespan beside the services."""
    return request.state.pages


async def app_settings() -> Settings:
    """The server's settings (app/settings.py); a test gives the routes settings of its own."""
    return settings()


UserSystemsDep = Annotated[UserSystems, Depends(user_systems_service)]
CheckingDep = Annotated[Checking, Depends(checking_service)]
GatesDep = Annotated[Gates, Depends(simulation_gates)]
AnswersDep = Annotated[Answers, Depends(remembered_answers)]
PagesDep = Annotated[PageCache, Depends(page_cache)]
ChapterDep = Annotated[Scenes, Depends(scenes_chapter)]
SettingsDep = Annotated[Settings, Depends(app_settings)]


async def fairness_gate(users: UserSystemsDep) -> Fairness:
    return users.gate


@dataclass(frozen=True)
class Client:
    """Who is asking: a signed session (the cookie), else the network address; fair shares are per ``key``."""

    key: str
    address: str
    minted: str | None = None  # a new session to hand back in a cookie
    request: Request | None = field(default=None, compare=False, repr=False)  # to notice the client leaving

    def keep(self, response: Response) -> Response:
        """Set the new session's cookie on the answer (whatever the answer is)."""
        if self.minted:
            response.set_cookie(COOKIE, self.minted, max_age=COOKIE_MAX_AGE, httponly=True, samesite="lax")
        return response


async def client_identity(request: Request, gate: Annotated[Fairness, Depends(fairness_gate)]) -> Client:
    """The request's session (app/service/runtime/fairness.py's ``key``), and a new one for a request without one."""
    address = client_address(request.scope)  # the peer, or a trusted proxy's word for it (app/web/http/address.py)
    session = gate.verify(request.cookies.get(COOKIE))
    return Client(gate.key(session, address), address, None if session else gate.mint(address), request)


ClientDep = Annotated[Client, Depends(client_identity)]
