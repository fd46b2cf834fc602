"""The program's own defaults and bounds, each defined once.

Below every layer (like ``app/settings.py``): a module that needs one of these numbers imports it from
here, so two modules meaning the same number cannot drift apart.  What an operator tunes for a machine
(hard time limits of user jobs, queue waits, connections, keep-alive) is a field of ``Settings`` instead;
the bounds of a simulation request (end time, samples, tolerances, the largest value) are the API's
documented ranges, in ``app/numerics/limits.py``.  The numbers here were chosen by measurement and are
not an operator's to change: a bound too small would leave members out of every derivation.
"""

from __future__ import annotations

# A run's defaults (simulated seconds)
DEFAULT_T_END = 10.0  # a run that gives no end time (a scene declares its own, this unless it says otherwise)
POINCARE_T_END = 200.0  # per orbit of a Poincaré section that gives no end time
POINCARE_PIECE = 50.0  # simulated time per compiled run of a section (a budget that ends it keeps earlier pieces)

# Bounds of the engine's symbolic work, in units of work (app/engine/algebra/work.py: SymPy expressions built,
# counted whether SymPy's cache answers them or not), never in seconds: what a document holds, how it is
# shown and what the tutor says are then a function of the input alone, on an idle machine or a loaded one.
# A bound used up leaves its member out with a note, or keeps a plainer form, never a refusal of the system
# (app/engine/algebra/budget.py), but for the equations of motion themselves (EQUATIONS_WORK); the one clock is
# the worker job's, at the edge (Settings.derive_seconds).
# This machine, idle, does about WORK_PER_SECOND units a second on the chapter's derivations (measured on
# all twelve scenes' documents, CPU time), and each bound below is the time bound it replaced times that
# rate, so that it ends about where that one did on an idle machine (the seconds are in the comments).
WORK_PER_SECOND = 20_000
# The equations of motion have no plainer form to fall back to: a system whose equations need more than this is
# refused, at the same count on any machine at any load, where the job's clock would refuse it later, by the
# load of the moment.  Ten times the 12-link chain's (65,550 units); (x + ẋ + 1)⁶⁰ in L needs 925,673.
EQUATIONS_WORK = 400_000  # 20 s
DISPLAY_WORK = 120_000  # 6 s: the display simplifications of one document, shared
# From three coordinates on (no chapter scene has more than two), the display simplifications share less:
# the residuals and forces of a chain rarely simplify beyond sin² + cos² = 1, and the user waits for them.
LARGE_DISPLAY_WORK = 30_000  # 1.5 s
# The display simplifications of the playground's first stage (the equations and accelerations) share at
# most this much: the equations are shown in their textbook rows when that is quick, else as the engine
# wrote them; the whole document shows them again with its own, larger budget (app/service/users/staged.py).
FIRST_DISPLAY_WORK = LARGE_DISPLAY_WORK
# Each member of the document beyond the equations has its own bound; one that uses it up is left out
# with a note in "skipped" (app/engine/document/contract.py).
MEMBER_WORK = {
    "steps": 160_000,  # 8 s
    "constraint_forces": 60_000,  # 3 s
    "transformed": 60_000,  # 3 s
    "hamilton": 60_000,  # 3 s
    "normal_modes": 80_000,  # 4 s
}
# The chapter's scenes are derived with every bound this many times as large (app/engine/budget.patience):
# their documents are made once per version and kept on disk, and the book prints each of them whole; a
# user's system keeps the bounds as they are.
SCENE_PATIENCE = 10.0
MEMBER_RESERVE_WORK = 20_000  # 1 s: kept back from a member's bound for the rest of an enclosing bound
SIMPLIFY_WORK = 10_000  # 0.5 s: one tidy-up of an expression
FORM_WORK = 20_000  # 1 s: one expression's textbook form
LATE_WORK = 6_000  # 0.3 s: once the shared display budget is spent, each expression still gets this much
FALLBACK_WORK = 4_000  # 0.2 s: the plainer form an expression falls back to
REDUCTION_WORK = 80_000  # 4 s: the reduction to one coordinate (effective potential) as a whole
SOLVE_WORK = 40_000  # 2 s: one symbolic solve of the derivation's (a reduction's roots, a coordinate change's inverse)
MODES_WORK = 240_000  # 12 s: the equilibria and normal modes, closed forms included (typically < 1 s of CPU)
EQUILIBRIA_SOLVE_WORK = 30_000  # 1.5 s: the equilibria in closed form
EIGEN_WORK = 20_000  # 1 s: ω² in closed form
SYMBOLIC_WORK = 5_000  # 0.25 s: deciding symbolically that a difference is zero
NAME_WORK = 8_000  # 0.4 s: recombining a factor's trigonometry to name it (once per catalogue of mistakes)
CANCEL_WORK = 4_000  # 0.2 s: one cancellation of a quotient while looking for equilibria in closed form
# The numeric search for equilibria counts the evaluations of the equations and their Jacobian (each
# start's Newton steps), not seconds: the search ends after the start at which this many were used.
SEARCH_EVALUATIONS = 20_000

# Checking a student's step (app/engine/tutor/check.py)
CHECK_DISPLAY_WORK = 2_400  # 0.12 s: typesetting a difference: past it, the difference is shown expanded
DIFFERENCE_WORK = 10_000  # 0.5 s at most: a difference's cancelling and trigonometry (what cancels never shows)
PARTS_WORK = 2_000  # 0.1 s: comparing an unmatched answer part by part
FACTOR_WORK = 4_000  # 0.2 s: naming the factor by which an answer is off
ANSWER_SLIP_WORK = 4_000  # 0.2 s: a slip read from the answer (a square left out, an equation linearised)
PIECE_WORK = 2_000  # 0.1 s: what the piece under a named mistake is (the correct term, what is left out)

# The service's pacing (wall-clock seconds)
# The hard limit of building one step's catalogue of mistakes for a scene in the worker pool: the server's own
# work, once per version of the engine (kept on disk), never a student's wait (a check waits for it at most
# Settings.check_seconds, then says the server is busy while the build goes on).
CATALOGUE_SECONDS = 180.0
# a check answered "the server is busy" asks the page to try again after this long
BUSY_RETRY_SECONDS = 2
RUN_SECONDS = 2.0  # one run of a work-precision sweep; slower tolerances of that method are skipped
LYAPUNOV_SECONDS = 60.0  # the runs of a Lyapunov measurement (set-up measures it; a first page waits once)
GIVE_WAY_SECONDS = 0.5  # the longest the warm-up waits for quiet before its next step
BACKOFF_SECONDS = 5.0  # a client's pause after its second job in a row out of time or memory; doubles after
# A refusal of an address's shared key (a script dropping its cookies) is answered this late: a flood
# that retries at once would otherwise cost the server hundreds of refusals a second (each request
# is read and checked first); held, twenty flooding threads send about twenty requests a second.
HOLD_SECONDS = 1.0
RATE_WINDOW_SECONDS = 60.0  # the window of every per-minute rate (the Settings' ``*_per_minute``)
STORE_SECONDS = 0.5  # a call to the shared store of the rate windows; past it a replica counts alone
RETRY_SECONDS = 1  # Retry-After of a 503 when no worker is to be had
