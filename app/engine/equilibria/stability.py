"""Linear stability of an equilibrium from its full linearization M e'' + G e' + K e = 0 (numbers).

G collects every term linear in the velocities at rest: its antisymmetric part
is gyroscopic (Coriolis forces in a rotating frame, magnetic forces), its
symmetric part damping.  With e = v exp(s t) the exponents s are the eigenvalues
of the first-order system

    d/dt (e, e') = A (e, e'),   A = [[0, I], [-M^-1 K, -M^-1 G]].

Re s > 0 for some s: unstable (that direction grows like exp(Re s t)); every
Re s < 0: asymptotically stable (damped); every Re s = 0: stable to first order
(oscillations at the frequencies Im s), neutral when some s = 0 (a free drift).
When G = 0 this is the familiar test on omega^2 = -s^2, the eigenvalues of K
relative to M; with G != 0 an equilibrium where K alone has a negative omega^2
can still have every Re s = 0: gyroscopic stabilization (a spinning top, a
Penning trap, the Lagrange points L4 and L5).

Every decision is relative, so none depends on the units: M is equilibrated by
its diagonal (D^-1 M D^-1 with D = sqrt|diag M|) before it is called singular,
and an exponent counts as zero or as growing relative to the largest exponent.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app import late

SINGULAR = 1e-10  # smallest |eigenvalue| of the equilibrated M, relative to its largest, below which M is singular
ZERO = 1e-7  # |s| or Re s, relative to the largest |s|, below which it counts as zero

STABLE, NEUTRAL, UNSTABLE = "stable", "neutral", "unstable"


@dataclass(frozen=True)
class Linear:
    """The verdict on M e'' + G e' + K e = 0 at one equilibrium."""

    kind: str  # stable, neutral or unstable
    exponents: tuple[complex, ...]  # the eigenvalues s of the first-order system
    omega_squared: tuple[float, ...]  # eigenvalues of K relative to M (the undamped, ungyroscopic problem)
    shapes: tuple[tuple[float, ...], ...]  # their shapes, largest component 1
    gyroscopic: bool  # stable only thanks to G (K relative to M has a negative omega^2)
    damped: bool  # G has a symmetric (dissipative or anti-dissipative) part
    moving: bool  # G != 0 at all
    definite: int  # +1: M positive definite, -1: negative definite (L = U - T), 0: indefinite
    # with G != 0: each oscillating exponent (Im s > 0) and the coordinates' part of its eigenvector,
    # largest component 1 (amplitudes |a|, phases arg a): the complex modes
    complex_modes: tuple[tuple[complex, tuple[complex, ...]], ...] = ()

    @property
    def frequencies(self) -> tuple[float, ...]:
        """Im s > 0 of each oscillating pair (radians per unit time)."""
        return tuple(sorted(float(s.imag) for s in self.exponents if s.imag > 0))


def _diagonal_scale(M: np.ndarray) -> np.ndarray:
    d = np.sqrt(np.abs(np.diag(M)))
    # a zero diagonal entry (M singular or indefinite there): that row's largest entry instead
    rows = np.sqrt(np.abs(M).max(axis=1))
    d = np.where(d > 0, d, rows)
    return np.where(d > 0, d, 1.0)


def singular(M: np.ndarray) -> bool:
    """M is singular once equilibrated by its diagonal (so masses of 1e6 and 1e-6 are not singular)."""
    if not np.all(np.isfinite(M)):
        return True
    d = _diagonal_scale(M)
    E = M / np.outer(d, d)
    sizes = np.abs(np.linalg.eigvals((E + E.T) / 2))
    return bool(sizes.max() == 0 or sizes.min() <= SINGULAR * sizes.max())


def _shape(vector: np.ndarray) -> tuple[float, ...]:
    """Scaled so that the largest component is +1."""
    v = np.real_if_close(vector)
    v = np.real(v).astype(float) if np.iscomplexobj(v) else v.astype(float)
    big = v[int(np.argmax(np.abs(v)))]
    return tuple(float(x) for x in v / big) if big != 0 else tuple(float(x) for x in v)


def linearize(M: np.ndarray, K: np.ndarray, G: np.ndarray) -> Linear | None:
    """The verdict, or None when M is singular (scale-free) or not finite."""
    if singular(M) or not (np.all(np.isfinite(K)) and np.all(np.isfinite(G))):
        return None
    n = M.shape[0]
    d = _diagonal_scale(M)
    # D^-1 M D^-1, D^-1 K D^-1, D^-1 G D^-1: the same problem in scaled coordinates e = D^-1 u
    Ms, Ks, Gs = M / np.outer(d, d), K / np.outer(d, d), G / np.outer(d, d)
    symmetric_m = np.linalg.eigvalsh((Ms + Ms.T) / 2)
    definite = 1 if symmetric_m.min() > 0 else (-1 if symmetric_m.max() < 0 else 0)
    linalg = late.module("scipy.linalg")
    if definite != 0 and np.allclose(Ks, Ks.T, rtol=1e-10, atol=1e-12 * max(np.abs(Ks).max(), 1e-300)):
        # symmetric K, definite M: real omega^2, M-orthogonal shapes (a negative M flips both signs)
        w2, vectors = linalg.eigh(definite * (Ks + Ks.T) / 2, definite * (Ms + Ms.T) / 2)
    else:
        w2c, vectors = linalg.eig(Ks, Ms)
        order = np.argsort(w2c.real)
        w2, vectors = w2c.real[order], vectors[:, order]
    shapes = tuple(_shape(vectors[:, i] / d) for i in range(n))
    # the first-order system's matrix, in the scaled coordinates (same eigenvalues)
    Minv = np.linalg.inv(Ms)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ Ks, -Minv @ Gs]])
    s, vectors_a = np.linalg.eig(A)
    size = max(float(np.abs(s).max()), 1e-300)
    grows = any(x.real > ZERO * size for x in s)
    still = any(abs(x) <= ZERO * size for x in s)
    kind = UNSTABLE if grows else (NEUTRAL if still else STABLE)
    w_size = max(float(np.abs(w2).max()), 1e-300)
    # an omega^2 that is zero to rounding (a free translation) is shown as 0
    w2 = np.where(np.abs(w2) <= ZERO * w_size, 0.0, w2)
    negative = any(w < -ZERO * w_size for w in w2)
    moving = bool(np.abs(Gs).max() > 0)
    sym = (Gs + Gs.T) / 2
    damped = bool(np.abs(sym).max() > 1e-12 * max(np.abs(Gs).max(), 1e-300))
    exponents = tuple(sorted((complex(x) for x in s), key=lambda z: (round(z.imag, 12), z.real)))
    complex_modes = []
    if moving:
        for j in np.argsort(s.imag):
            if s[j].imag <= ZERO * size:
                continue
            # back from the scaled coordinates, e = D^-1 u
            a = vectors_a[:n, j] / d
            a = a / a[int(np.argmax(np.abs(a)))]
            complex_modes.append((complex(s[j]), tuple(complex(x) for x in a)))
    return Linear(
        kind,
        exponents,
        tuple(float(w) for w in w2),
        shapes,
        gyroscopic=moving and negative and kind != UNSTABLE,
        damped=damped,
        moving=moving,
        definite=definite,
        complex_modes=tuple(complex_modes),
    )
