"""A bead's momentum conjugate to its coordinate is not its momentum along the wire (prof-o F1): on the helix and the
turning parabola the bead moves along the wire at the speed (dℓ/dq) q̇, and p_q is that momentum times dℓ/dq again.
The pages' sentences say so, and the engine's momenta hold it."""

from __future__ import annotations

import pytest
import sympy as sp

from app.scenes import SCENES
from tests.scenes.common import S, derivation

# each scene's coordinate, and the point on its wire as the coordinate sets it in the wire's own (turning) frame
WIRES = {
    "helix-bead": ("z", lambda q: (S("R") * sp.cos(S("alpha") * q), S("R") * sp.sin(S("alpha") * q), q)),
    "rotating-parabola": ("rho", lambda q: (q, sp.Integer(0), S("alpha") * q**2)),
}


@pytest.mark.parametrize("scene_id", sorted(WIRES))
def test_the_momentum_is_the_momentum_along_the_wire_times_the_wires_length_per_unit_of_coordinate(scene_id):
    name, wire = WIRES[scene_id]
    q, qd = S(name), S(f"{name}_dot")
    # dℓ/dq = |dr/dq| along the wire
    dl = sp.sqrt(sum(sp.diff(c, q) ** 2 for c in wire(q)))
    along = S("m") * dl * qd  # the bead's momentum along the wire
    d = derivation(scene_id)
    k = d.table.names.index(name)
    # the engine's p_q = ∂L/∂q̇, in its own symbols, put in ours
    p = sp.diff(d.mechanics.L, d.table.qd[k]).subs({s: S(s.name) for s in d.mechanics.L.free_symbols})
    assert sp.simplify(p - along * dl) == 0
    # and the page does not call p_q the momentum along the wire
    reasons = SCENES[scene_id].reasons
    assert "conjugate" in reasons["momenta"] and "not the bead's momentum along the wire" in reasons["momenta"]
    assert "is the momentum along the wire" not in " ".join(reasons.values())
