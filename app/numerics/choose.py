"""``auto``: pick a method per system and request, and say why.

The decision uses the linearisation at the start, J = dF/dy by central
differences, with eigenvalues lambda_i and eigenvectors v_i:

* stiff: the fastest rate |lambda|_max exceeds the slow rates (the rest of the
  spectrum, or 1 / t_end) by more than ``STIFF_RATIO``, and the fast modes are
  not excited: writing F(y0) = sum_i c_i v_i, a mode with eigenvalue lambda_i
  oscillates with amplitude |c_i / lambda_i| |v_i|; when that is below the
  tolerance (atol + rtol |y|) for every fast mode, only the slow motion matters
  and an implicit method (Radau) steps over the fast one;
* long and conservative: the engine says E or h is conserved and the run lasts
  more than ``LONG_RUN`` characteristic times 2 pi / |lambda|_max: a symplectic
  method (Yoshida-4 when H separates, else Gauss-Legendre) keeps the energy
  error bounded instead of letting it grow with time;
* otherwise the compiled DOP853 (high order, adaptive, cheapest per digit).

A stiff problem whose fast mode *is* excited must resolve that mode whatever
the method, so it is treated as non-stiff (explicit or symplectic).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from app.numerics.system import NumericSystem

STIFF_RATIO = 1.0e3
LONG_RUN = 1.0e3  # characteristic times


@dataclass(frozen=True)
class Analysis:
    spectral_radius: float
    slow_rate: float
    fast_amplitude: float  # the fast modes' amplitude, in units of the tolerance
    stiff: bool
    characteristic_times: float

    def as_dict(self) -> dict[str, float | bool]:
        return {
            "spectral_radius": self.spectral_radius,
            "slow_rate": self.slow_rate,
            "fast_mode_amplitude_over_tolerance": self.fast_amplitude,
            "stiff": self.stiff,
            "characteristic_times": self.characteristic_times,
        }


def jacobian(system: NumericSystem, t: float, y: np.ndarray, k: np.ndarray) -> np.ndarray:
    """dF/dy by central differences (step ~ eps^(1/3) |y_j|)."""
    m = y.size
    J = np.empty((m, m))
    for j in range(m):
        h = 6e-6 * max(1.0, abs(y[j]))
        up, down = y.copy(), y.copy()
        up[j] += h
        down[j] -= h
        J[:, j] = (system.f(t, up, k) - system.f(t, down, k)) / (2 * h)
    return J


def analyse(
    system: NumericSystem, k: np.ndarray, y0: np.ndarray, t_end: float, rtol: float, atol: np.ndarray
) -> Analysis:
    try:
        J = jacobian(system, 0.0, y0, k)
        F = system.f(0.0, y0, k)
        lam, V = np.linalg.eig(J)
    except (ArithmeticError, ValueError, np.linalg.LinAlgError):
        return Analysis(math.nan, math.nan, math.inf, False, 0.0)
    if not (np.all(np.isfinite(lam)) and np.all(np.isfinite(F))):
        return Analysis(math.nan, math.nan, math.inf, False, 0.0)
    size = np.abs(lam)
    rho = float(size.max())
    fast = size >= rho / 10.0
    slow_rate = max(float(size[~fast].max()) if np.any(~fast) else 0.0, 1.0 / t_end)
    # amplitudes of the fast modes: F(y0) = V c, mode i moves by |c_i / lambda_i| |v_i|
    scale = atol + rtol * np.abs(y0)
    if rho > 0 and np.linalg.cond(V) < 1e10:
        c = np.linalg.solve(V, F.astype(complex))
        amplitude = np.abs(V[:, fast]) @ (np.abs(c[fast]) / size[fast])
        fast_amplitude = float(np.max(amplitude / scale))
    else:
        fast_amplitude = math.inf
    stiff = rho > STIFF_RATIO * slow_rate and fast_amplitude <= 1.0
    return Analysis(rho, slow_rate, fast_amplitude, stiff, rho * t_end / (2 * math.pi))


def choose(system: NumericSystem, analysis: Analysis) -> tuple[str, str]:
    """The method ``auto`` runs, and the reason in one sentence."""
    a = analysis
    if a.stiff:
        return "Radau", (
            f"stiff: the fastest rate at the start, |λ| = {a.spectral_radius:.3g}/s, is "
            f"{a.spectral_radius / a.slow_rate:.2g} times the slow rate and its mode is not excited "
            f"(amplitude {a.fast_amplitude:.2g} of the tolerance), so the implicit Radau method steps over it"
        )
    if system.energy_name is not None and a.characteristic_times >= LONG_RUN:
        name = "Yoshida4" if system.separable else "Gauss-Legendre"
        why = "H separates into T(p) + U(q)" if system.separable else "H(q, p) does not separate"
        return name, (
            f"long run of a conservative system (about {a.characteristic_times:.3g} characteristic times, and the engine "
            f"says {system.energy_name} is conserved): a symplectic method keeps the energy error bounded; {why}"
        )
    excited = ""
    if a.spectral_radius > STIFF_RATIO * a.slow_rate:
        excited = f" (the fast mode, |λ| = {a.spectral_radius:.3g}/s, is excited, so it must be resolved)"
    return "DOP853-compiled", (
        f"non-stiff{excited}: the explicit 8th-order DOP853 with a compiled step loop is the cheapest per digit"
    )
