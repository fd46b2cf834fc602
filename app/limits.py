"""The program's own defaults and time bounds, each defined once.

Below every layer (like ``app/settings.py``): a module that needs one of these numbers imports it from
here, so two modules meaning the same number cannot drift apart.  What an operator tunes for a machine
(hard time limits of user jobs, queue waits, connections, keep-alive) is a field of ``Settings`` instead;
the bounds of a simulation request (end time, samples, tolerances, the largest value) are the API's
documented ranges, in ``app/numerics/limits.py``.  The numbers here were chosen by measurement and are
not an operator's to change: a budget too small would leave members out of every derivation.
"""

from __future__ import annotations

# A run's defaults (simulated seconds)
DEFAULT_T_END = 10.0  # a run that gives no end time (a scene declares its own, this unless it says otherwise)
POINCARE_T_END = 200.0  # per orbit of a Poincaré section that gives no end time
POINCARE_PIECE = 50.0  # simulated time per compiled run of a section (a budget that ends it keeps earlier pieces)

# Time bounds of the engine's symbolic work (wall-clock seconds); a bound that runs out leaves its
# member out with a note, or keeps a plainer form, never a refusal of the system (app/engine/budget.py).
DISPLAY_SECONDS = 6.0  # the display simplifications of one document, shared
# From three coordinates on (no chapter scene has more than two), the display simplifications share less:
# the residuals and forces of a chain rarely simplify beyond sin² + cos² = 1, and the user waits for them.
LARGE_DISPLAY_SECONDS = 1.5
# The display simplifications of the playground's first stage (the equations and accelerations) share at
# most this much: the equations are shown in their textbook rows when that is quick, else as the engine
# wrote them; the whole document shows them again with its own, larger budget (app/service/staged.py).
FIRST_DISPLAY_SECONDS = LARGE_DISPLAY_SECONDS
# Each member of the document beyond the equations has its own time bound; one that runs out is left out
# with a note in "skipped" (app/engine/contract.py).
MEMBER_SECONDS = {
    "steps": 8.0,
    "constraint_forces": 3.0,
    "transformed": 3.0,
    "hamilton": 3.0,
    "normal_modes": 4.0,
}
# The chapter's scenes are derived with every bound this many times as long (app/engine/budget.patience):
# their documents are made once per version and kept on disk, so a loaded machine must not change what
# the book prints; a user's system keeps the bounds as they are.
SCENE_PATIENCE = 10.0
MEMBER_RESERVE_SECONDS = 1.0  # kept back from a member's bound for the rest of the document near an outer limit
SIMPLIFY_SECONDS = 0.5  # one tidy-up of an expression
FORM_SECONDS = 1.0  # one expression's textbook form
LATE_SECONDS = 0.3  # once the shared display budget is spent, each expression still gets this much
FALLBACK_SECONDS = 0.2  # the plainer form an expression falls back to
REDUCTION_SECONDS = 4.0  # the reduction to one coordinate (effective potential) as a whole
SOLVE_SECONDS = 2.0  # one symbolic solve of the derivation's (a reduction's roots, a coordinate change's inverse)
MODES_SECONDS = 12.0  # the equilibria and normal modes, closed forms and search included (typically < 1 s of CPU)
EQUILIBRIA_SOLVE_SECONDS = 1.5  # the equilibria in closed form
EIGEN_SECONDS = 1.0  # ω² in closed form
SEARCH_SECONDS = 1.5  # the numeric search for equilibria
SYMBOLIC_SECONDS = 0.25  # deciding symbolically that a difference is zero
NAME_SECONDS = 0.4  # recombining a factor's trigonometry to name it (once per catalogue of mistakes)

# Checking a student's step (app/engine/check.py)
CHECK_DISPLAY_SECONDS = 0.12  # typesetting a difference: past it, the difference is shown expanded
DIFFERENCE_SECONDS = 0.5  # at most: a difference's cancelling and trigonometry (what cancels never shows)
PARTS_SECONDS = 0.1  # comparing an unmatched answer part by part
FACTOR_SECONDS = 0.2  # naming the factor by which an answer is off

# The service's pacing (wall-clock seconds)
RUN_SECONDS = 2.0  # one run of a work-precision sweep; slower tolerances of that method are skipped
GIVE_WAY_SECONDS = 0.5  # the longest the warm-up waits for quiet before its next step
BACKOFF_SECONDS = 5.0  # a client's pause after its second job in a row out of time or memory; doubles after
# A refusal of an address's shared key (a script dropping its cookies) is answered this late: a flood
# that retries at once would otherwise cost the server hundreds of refusals a second (each request
# is read and checked first); held, twenty flooding threads send about twenty requests a second.
HOLD_SECONDS = 1.0
RATE_WINDOW_SECONDS = 60.0  # the window of every per-minute rate (the Settings' ``*_per_minute``)
RETRY_SECONDS = 1  # Retry-After of a 503 when no worker is to be had
