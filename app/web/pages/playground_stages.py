"""The playground's first stage: what the page shows while the rest of the derivation is worked out.

``GET /playground`` answers with the equations of motion and the accelerations as soon as they are
printed (``app.service.users.staged``); the page then asks for ``GET /playground?…&stage=whole`` and puts
the whole derivation, the simulation and the skipped notes in place of this view (static/js/
playground.js).  Without JavaScript the view links to that address.  Pure Python on the document.
"""

from __future__ import annotations

from typing import Any
from urllib.parse import parse_qsl, urlencode

from app.engine.display.names import MASS_MATRIX, latex
from app.engine.document.model import FirstStage
from app.viz.page_model import letter_of

STAGE_PARAMETER = {
    "name": "stage",
    "in": "query",
    "required": False,
    "description": (
        "`whole` waits for the whole derivation; otherwise the page shows the equations first when the whole "
        "document is not ready yet, and fetches the rest."
    ),
    "schema": {"type": "string", "enum": ["whole"]},
}


def whole_href(query: str) -> str:
    """The address of the same system with the whole derivation (``stage=whole``), landing on the outcome."""
    pairs = [(k, v) for k, v in parse_qsl(query, keep_blank_values=True) if k != "stage"]
    return "/playground?" + urlencode([*pairs, ("stage", "whole")]) + "#outcome"


def _listed(names: list[str]) -> str:
    """"a, b and c" """
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def first_view(doc: FirstStage, href: str, key: str) -> dict[str, Any]:
    """The first stage as the page shows it: LaTeX of the equations and of the accelerations (or of M and f,
    when the accelerations stay M⁻¹f), the notes of what is left out, and what is still being worked on;
    ``key``, the whole derivation's, addresses its progress and its cancelling (app/web/api/staged.py)."""
    q = doc.coordinates
    accelerations = doc.accelerations
    view: dict[str, Any] = {
        "equations": [e.latex for e in doc.equations_of_motion],
        "accelerations": [rf"{latex(c + '_ddot')} = {accelerations[c].latex}" for c in q if c in accelerations],
        "mass_matrix": None,
        "forcing": [],
        "skipped": [s.reason for s in doc.skipped],
        # the page shows the simulation with the whole document too
        "pending": _listed([*(p.name for p in doc.pending), "the simulation"]),
        "whole_href": href,
        "progress_url": f"/api/derive/progress/{key}",
        "cancel_url": f"/api/derive/cancel/{key}",
    }
    # each equation's factor (app/engine/document/report.py equation_scales): said under the equations, so that ℳ
    # and f, of the equations undivided, can be read off the rows shown
    view["divided_by"] = [
        {"coordinate": latex(e.coordinate), "factor": e.divided_by.latex}
        for e in doc.equations_of_motion
        if e.divided_by is not None
    ]
    if not accelerations:
        # ℳ q̈ = f, with ℳ and f printed: what the numerics solves at each step
        rows = [" & ".join(x.latex for x in row) for row in doc.mass_matrix]
        # the page's letter for the mass matrix (app/engine/document/notation.py, from app/engine/names.MASS_MATRIX)
        letter = letter_of(doc, "mass matrix", MASS_MATRIX[0])
        view["letter"] = letter
        view["system"] = letter + r" \ddot{q} = f"
        view["mass_matrix"] = letter + r" = \begin{pmatrix} " + r" \\ ".join(rows) + r" \end{pmatrix}"
        view["forcing"] = [f"f_{{{latex(c)}}} = {f.latex}" for c, f in zip(q, doc.forcing, strict=True)]
    return view
