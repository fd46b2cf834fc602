"""``auto``: pick a method per system and request, and say why.

The decision uses the linearisation at the start, J = dF/dy (the engine's
generated Jacobian, or central differences where none is generated), with
eigenvalues lambda_i and eigenvectors v_i:

* stiff: the fastest rate |lambda|_max exceeds the slow rates (the rest of the
  spectrum, or 1 / t_end) by more than ``STIFF_RATIO``, and the fast modes are
  not excited.  The fast modes span an invariant subspace of J: with the
  ordered Schur form J = Q [[T11, T12], [0, T22]] Q^H (slow block first) and X
  solving T11 X - X T22 = -T12, the fast part of F(y0) has coordinates
  z2 = (Q^H F)_fast and the fast displacement is d = T22^-1 z2 (F_fast = J d on
  that subspace).  Split into the modes of T22 (T22 w_i = lambda_i w_i,
  d = sum_i c_i w_i), mode i swings component l by |c_i| |(Q [X; I] w_i)_l|.
  When that swing is below the tolerance (atol + rtol |y|) in every component,
  only the slow motion matters and an implicit method (the compiled Radau IIA) steps over the
  fast one.  (The Schur form copes with a defective J, e.g. a cyclic angle
  whose eigenvalue 0 is doubled, where a full eigenvector basis does not exist.)
* conservative (the engine says E or h is conserved) and either long (more
  than ``LONG_RUN`` characteristic times 2 pi / |lambda|_max) or starting near
  an unstable equilibrium (J has a real eigenvalue lambda > 0 while
  |F(y0)| < ``SADDLE_SPEED`` lambda |y0|: the motion creeps away from a saddle,
  so the energy level alone decides on which side of the separatrix it goes):
  a symplectic method (Gauss-Legendre, else Yoshida-4) keeps the energy error
  bounded instead of letting it drift -- unless a fast mode stands STIFF_RATIO
  above the slow rates (excited, or the problem would be stiff): a fixed step
  would have to resolve it over the whole run;
* otherwise Verner's efficient 8(7) pair with a compiled step loop (high order, adaptive, and it
  detects stiffness that appears on the way).  At equal final error 1e-8 it took 18 % (pendulum,
  100 periods) and 30 % (double pendulum, 50 s) fewer steps than the compiled DOP853, the same steps
  as CyRK's Vern8, and 1.7x less time (benchmarks/bench_cyrk.py).  At the same tolerance its error is
  about DOP853's, and its estimate stays honest: past the spherical pendulum's pole (rtol 1e-8) the
  true error was 1.4e-6 against DOP853's 1.1e-6 (5.5e-7 with an earlier build of the same loop: there
  the error hangs on the exact step sequence), the estimate 1.4e-6, in 316 steps against 434; p_phi,
  conserved, drifted 2.5e-6 of itself (DOP853: 7e-8), within the error.

A stiff problem whose fast mode *is* excited must resolve that mode whatever
the method, so it is treated as non-stiff (explicit or symplectic) -- as long as
resolving it fits in the budget: an explicit step is held at h |lambda|_max <=
``EXPLICIT_STABILITY`` (Vern8's stability boundary, about 5.9), so the run needs
about |lambda|_max t_end / 5.9 steps.  Beyond ``RESOLVABLE_STEPS`` no explicit or
symplectic run could finish (the chain of masses 1e-9 and 1e9 kg on springs of
1e9 N/m: |lambda| = 1.4e9/s, 2.4e9 steps over 10 s), and auto runs the implicit
method anyway, which damps the fast swing and follows the slow motion; the reason
and a warning say how large the swing it leaves out was.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from app import late
from app.numerics import limits
from app.numerics.methods import NONSTIFF, STIFF, symplectic_for
from app.numerics.system import NumericSystem

try:  # numpy's own eigenvalue ufunc, private: used only where it answers as its public wrapper does
    from numpy.linalg import _umath_linalg

    _PROBE = np.array([[0.0, 1.0], [-2.0, -0.5]])
    if _umath_linalg.eigvals(_PROBE, signature="d->D").tolist() != np.linalg.eigvals(_PROBE).astype(complex).tolist():
        _umath_linalg = None  # type: ignore[assignment]  # pragma: no cover - a numpy whose ufunc answers otherwise
except Exception:  # pragma: no cover - a numpy that moved it or changed its signature
    _umath_linalg = None  # type: ignore[assignment]

STIFF_RATIO = 1.0e3
EXPLICIT_STABILITY = 5.864  # |R(-x)| = 1 for Vern8 at x = 5.864 (app/numerics/kernels/vern8.py)
# beyond the compiled step limit an explicit run is refused: only the implicit method can finish then
RESOLVABLE_STEPS = float(limits.COMPILED_STEPS)
LONG_RUN = 1.0e3  # characteristic times
SADDLE_SPEED = 1.0e-2


@dataclass(frozen=True)
class Analysis:
    spectral_radius: float
    slow_rate: float
    fast_amplitude: float  # the fast modes' amplitude, in units of the tolerance (NaN: no stiff gap, not computed)
    stiff: bool
    characteristic_times: float
    near_saddle: bool = False
    # |λ|max over the largest smaller nonzero |λ| of J (1 when the spectrum has one size): a fast mode's lead
    mode_gap: float = 1.0
    # an excited fast mode too fast to resolve in the budget (then ``stiff`` too: the implicit method damps it)
    unresolvable: bool = False

    def as_dict(self) -> dict[str, float | bool]:
        return {
            "spectral_radius": self.spectral_radius,
            "slow_rate": self.slow_rate,
            "fast_mode_amplitude_over_tolerance": self.fast_amplitude,
            "stiff": self.stiff,
            "characteristic_times": self.characteristic_times,
            "near_saddle": self.near_saddle,
        }


def jacobian(system: NumericSystem, t: float, y: np.ndarray, k: np.ndarray) -> np.ndarray:
    """dF/dy: the engine's expressions differentiated (one call), else central differences (step ~ eps^(1/3) |y_j|)."""
    exact = system.jacobian(t, y, k)
    if exact is not None:
        return exact
    return central_differences(lambda x: system.f(t, x, k), y, 6e-6)


def central_differences(f: Callable[[np.ndarray], np.ndarray], x: np.ndarray, step: float) -> np.ndarray:
    """The square matrix df/dx at x, column j from f(x ± h e_j) with h = step · max(1, |x_j|)."""
    n = x.size
    J = np.empty((n, n))
    for j in range(n):
        h = step * max(1.0, abs(x[j]))
        up, down = x.copy(), x.copy()
        up[j] += h
        down[j] -= h
        # f'(x) ≈ (f(x + h) - f(x - h)) / 2h, its error O(h²)
        J[:, j] = (f(up) - f(down)) / (2 * h)
    return J


def fast_swing(J: np.ndarray, F: np.ndarray, threshold: float) -> np.ndarray:
    """Per component, how far the fast modes (|lambda| >= threshold) swing the state about the slow motion."""
    linalg = late.module("scipy.linalg")  # imported with the first analysis, not with the app
    T, Q, slow_count = linalg.schur(J, output="complex", sort=lambda x: abs(x) < threshold)
    m = J.shape[0]
    if slow_count == m:
        return np.zeros(m)
    z = Q.conj().T @ F.astype(complex)
    T11, T12, T22 = T[:slow_count, :slow_count], T[:slow_count, slow_count:], T[slow_count:, slow_count:]
    # T11 X - X T22 = -T12 decouples the blocks (their spectra are disjoint)
    X = linalg.solve_sylvester(T11, -T22, -T12) if slow_count else np.zeros((0, m - slow_count))
    basis = Q @ np.vstack([X, np.eye(m - slow_count)])  # the fast invariant subspace
    # fast displacement d = T22^-1 z_fast; its modes T22 w_i = lambda_i w_i swing with amplitude |c_i| |basis w_i|
    lam, W = np.linalg.eig(T22)
    c = np.linalg.solve(W, np.linalg.solve(T22, z[slow_count:]))
    return np.abs(basis @ W) @ np.abs(c)


def eigenvalues(J: np.ndarray) -> list[complex]:
    """The eigenvalues of a real square matrix, the numbers ``np.linalg.eigvals`` returns (the same LAPACK
    routine, dgeev, through numpy's own ufunc), without its wrapper: right after other work, as in a
    server between requests, the wrapper's checks, its error-state context and its real-or-complex
    conversion took 30-150 us of a default simulation, the routine itself 10-40 us.  A matrix with an
    infinite or undefined entry is refused as ``np.linalg.eigvals`` refuses it (LinAlgError); a
    routine that does not converge gives NaN eigenvalues, which ``analyse`` treats as the refusal."""
    if _umath_linalg is None:
        return np.linalg.eigvals(J).astype(complex).tolist()
    if not np.isfinite(J).all():
        raise np.linalg.LinAlgError("Array must not contain infs or NaNs")
    # numpy's own settings around the routine: its floating-point flags are no one's warning
    with np.errstate(all="ignore"):
        return _umath_linalg.eigvals(J, signature="d->D").tolist()


def analyse(
    system: NumericSystem, k: np.ndarray, y0: np.ndarray, t_end: float, rtol: float, atol: np.ndarray | float
) -> Analysis:
    """The linearisation's facts at the start (see the module's note); ``atol`` per component, or one number for all."""
    try:
        J = jacobian(system, 0.0, y0, k)
        F = system.f(0.0, y0, k)
        lam = eigenvalues(J)
    except (ArithmeticError, ValueError, np.linalg.LinAlgError):
        return Analysis(math.nan, math.nan, math.inf, False, 0.0)
    # the spectrum's few numbers as Python floats: numpy's per-call overhead on arrays of 2-12 entries was
    # most of this function's time (about 65 us of a default simulation's 200 us outside the kernel)
    pairs = [(abs(x), x.real, x.imag) for x in lam]
    if not all(math.isfinite(size) for size, _, _ in pairs) or not all(math.isfinite(v) for v in F.tolist()):
        return Analysis(math.nan, math.nan, math.inf, False, 0.0)
    rho = max(size for size, _, _ in pairs)
    slow_rate = max([size for size, _, _ in pairs if size < rho / 10.0] + [1.0 / t_end])
    if rho <= STIFF_RATIO * slow_rate:
        # no rate stands STIFF_RATIO above the slow ones, so the problem is not stiff whatever the fast
        # modes' amplitude: the Schur form and Sylvester solve (most of this function's time) are skipped
        fast_amplitude = math.nan
    else:
        try:
            fast_amplitude = float(np.max(fast_swing(J, F, rho / 10.0) / (atol + rtol * np.abs(y0))))
        except (ValueError, np.linalg.LinAlgError):
            fast_amplitude = math.inf
    gap_over_slow = rho > STIFF_RATIO * slow_rate
    # excited, but an explicit run would need more than RESOLVABLE_STEPS steps at its stability limit
    unresolvable = bool(gap_over_slow and fast_amplitude > 1.0 and rho * t_end / EXPLICIT_STABILITY > RESOLVABLE_STEPS)
    stiff = bool(gap_over_slow and fast_amplitude <= 1.0) or unresolvable
    # real eigenvalues lambda > 0: a saddle; the motion creeps when |F| < SADDLE_SPEED lambda max(|y0|, 1)
    unstable = [re for size, re, im in pairs if re > 0 and abs(im) <= 1e-8 * size]
    creeping = bool(unstable) and math.sqrt(float(F @ F)) < SADDLE_SPEED * max(unstable) * max(
        math.sqrt(float(y0 @ y0)), 1.0
    )
    # the fast modes' lead over the slower modes of the spectrum itself (not over 1 / t_end)
    slower = [size for size, _, _ in pairs if 1e-12 * rho < size < rho / 10.0]
    gap = rho / max(slower) if slower else 1.0
    return Analysis(
        rho, slow_rate, fast_amplitude, stiff, rho * t_end / (2 * math.pi), bool(creeping), gap, unresolvable
    )


def choose(system: NumericSystem, analysis: Analysis) -> tuple[str, str]:
    """The method ``auto`` runs, and the reason in one sentence."""
    a = analysis
    if a.unresolvable:
        return STIFF, (
            f"stiff: the fastest rate at the start, |λ| = {a.spectral_radius:.3g}/s, is "
            f"{a.spectral_radius / a.slow_rate:.2g} times the slow rate; its mode is excited (amplitude "
            f"{a.fast_amplitude:.2g} of the tolerance), but resolving it would take an explicit method about "
            f"{a.characteristic_times * 2 * math.pi / EXPLICIT_STABILITY:.2g} "
            "steps, far too many, so the implicit Radau IIA method of order 5, with the exact Jacobian of the equations, "
            "follows the slow motion and damps that fast swing"
        )
    if a.stiff:
        return STIFF, (
            f"stiff: the fastest rate at the start, |λ| = {a.spectral_radius:.3g}/s, is "
            f"{a.spectral_radius / a.slow_rate:.2g} times the slow rate and its mode is not excited "
            f"(amplitude {a.fast_amplitude:.2g} of the tolerance), so the implicit Radau IIA method of order 5, with the "
            "exact Jacobian of the equations, steps over it"
        )
    # symplectic methods step at a fixed size: only where no fast mode (excited, since not stiff) would force
    # that size down over the whole run -- a chain with masses 1e-9 and 1e9 took Yoshida-4 past its step limit
    fast_mode = a.mode_gap > STIFF_RATIO
    long_or_saddle = a.characteristic_times >= LONG_RUN or a.near_saddle
    # the symplectic method is looked for (every method asked whether it applies) only where one would run
    wanted = system.energy_name is not None and not fast_mode and long_or_saddle
    symplectic = symplectic_for(system) if wanted else None
    if symplectic is not None:
        name = symplectic.name
        why = f"{name} is the highest-order symplectic method that applies" + (
            " (H separates into T(p) + U(q))" if system.separable else " (H(q, p) does not separate)"
        )
        if a.near_saddle:
            what = (
                "the motion starts next to an unstable equilibrium, where the energy level alone decides on which side "
                "of the separatrix it goes"
            )
        else:
            what = f"long run (about {a.characteristic_times:.3g} characteristic times)"
        return name, (
            f"{what}, and {system.energy_name} is conserved: a symplectic method keeps the energy error "
            f"bounded instead of letting it drift; {why}"
        )
    excited = ""
    if a.spectral_radius > STIFF_RATIO * a.slow_rate:
        excited = f", though its fast mode at |λ| = {a.spectral_radius:.3g}/s is excited and must be followed"
    return NONSTIFF, (
        f"non-stiff{excited}: Verner's explicit 8(7) method, which needs the fewest evaluations for a given accuracy "
        "here and hands the run to the implicit Radau IIA method if the equations turn stiff"
    )
