"""Same question, same answer, at any load (issue 43, item 5).

A fixed set of requests (tests/web/determinism.py: user derivations of one to four links, the equations stage,
practice checks whose feedback compares part by part, scene derivations, modes at changed parameters, a user
simulation) is answered by a fresh server on an idle machine, by a fresh server with four busy processes per
core, and by that server again once the load has stopped (which catches a poorer answer that was cached).  The
bodies, minus the fields that are timings by definition, must be identical.

On the code before bounds by work (the engine's bounds were wall-clock time bounds), 8 of these 16 bodies
differed under load, and all 8 stayed different after the load, served from the cache: the triple pendulum's
and the double pendulum scene's wrong T lost their part-by-part comparison (``partial: null``), the 3- and
4-link chains' equations and momenta were printed expanded instead of collected (also on the equations
stage), a 3-link chain's normal modes were left out, the spherical pendulum's effective potential and its steps
were printed in another form, and the hoop's ω² as ``(-R*w**2*cos(2*theta) + g*cos(theta))/R``.
"""

from __future__ import annotations

import pytest

from tests.web.determinism import differences, three_runs

pytestmark = [pytest.mark.slow, pytest.mark.load]


def test_the_same_requests_get_the_same_bodies_idle_under_load_and_after():
    idle, loaded, after = three_runs(per_core=4)
    assert all(status == 200 for status, _ in idle.values()), {k: v for k, v in idle.items() if v[0] != 200}
    assert differences(idle, loaded) == []
    assert differences(idle, after) == []
