"""Schemathesis against the app's own OpenAPI schema: no server errors, no schema violations.

Every operation is called with generated requests (valid and invalid by the
schema) and every answer is checked: not a 5xx, a documented status code and
content type, a body that matches the documented schema, documented headers,
and invalid requests rejected (errors are RFC 9457 problems, application/problem+json, one schema for all:
app/web/api/openapi.py).  ``positive_data_acceptance`` is left out: an
expression field is a string in the schema, and most schema-valid strings are
not expressions, so a 422 for them is the right answer.
"""

import pytest
import schemathesis
from hypothesis import HealthCheck, settings
from schemathesis.specs.openapi.checks import positive_data_acceptance

from app.main import app
from app.service.classroom.service import Classroom
from app.service.services import Services
from app.service.simulations.simulation import Gates
from app.service.tutor.checking import Checking
from app.service.users.user_systems import UserSystems
from app.settings import Settings
from app.web.api import deps

# every test here is slow; marked as a module, the module is not even imported in the fast tier, where building
# its generated cases took most of the collection's time
pytestmark = pytest.mark.slow

# The schema comes from the app object itself: no request and no start-up (``from_asgi`` runs the app's
# lifespan while the suite is collected).  schemathesis.pytest.from_fixture would defer it to a fixture,
# but fails under pytest 9 (it sets ``node._nodeid``).
schema = schemathesis.openapi.from_dict(app.openapi())
schema.app = app
schema.location = "/openapi.json"
# a body over the size cap is refused (413) before it is read: that is a rejection of invalid data too
_rejection = schema.config.checks.negative_data_rejection
_rejection.expected_statuses = [*_rejection.expected_statuses, "413"]


@pytest.fixture(scope="module")
def generated_requests_services(client, tmp_path_factory):
    """Services of their own (fair shares, session minting, caches, classes in a temporary database) on the
    session's worker pool."""
    session = client.app_state["services"]
    users = UserSystems(session.pool)
    checking = Checking(users)
    classes = Classroom(checking, Settings(data_dir=tmp_path_factory.mktemp("classes")))
    return Services(session.pool, users, checking, Gates(), session.scenes, classes, session.answers, session.chapter)


# operations that derive, simulate or judge (each case a worker job of up to seconds): few examples each, so
# that the run stays within minutes on a shared machine; the rest answer from caches or the database
HEAVY = (
    "derive_system|derive_equations|simulate_system|export_system|user_poincare|user_modes|user_action|user_relax"
    "|scene_poincare|scene_modes|scene_modes_at|scene_action|scene_relax|simulate_scene|scene_work_precision"
    "|scene_export|check_scene_step|check_system_step|system_exercises|typeset|playground|check_step"
)
heavy = schema.include(operation_id_regex=f"^({HEAVY})$")
light = schema.exclude(operation_id_regex=f"^({HEAVY})$")


def _conforms(case, services) -> None:
    # schemathesis starts the app's lifespan for each operation: its calls use services on the session's
    # pool (started once) instead of a pool of their own, and leave the session's fair shares alone
    app.dependency_overrides[deps.services] = lambda: services
    try:
        # a derivation may take a while (the double pendulum example does); the worker bounds it
        case.call_and_validate(excluded_checks=[positive_data_acceptance], timeout=120)
    finally:
        app.dependency_overrides.pop(deps.services)


@light.parametrize()
@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck), derandomize=True)
def test_every_light_operation_conforms_to_its_schema(case, generated_requests_services):
    _conforms(case, generated_requests_services)


@heavy.parametrize()
@settings(max_examples=6, deadline=None, suppress_health_check=list(HealthCheck), derandomize=True)
def test_every_heavy_operation_conforms_to_its_schema(case, generated_requests_services):
    _conforms(case, generated_requests_services)
