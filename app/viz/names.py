"""Plain-text (Unicode) labels for symbol names, for SVG text and plot axes.

KaTeX typesets the derivation; Plotly and SVG get readable Unicode instead:
``theta`` -> θ, ``theta_dot`` -> θ̇, ``x1`` -> x₁, ``p_phi`` -> p_φ.
"""

from __future__ import annotations

import re

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ", "eta": "η",
    "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ",
    "rho": "ρ", "sigma": "σ", "tau": "τ", "phi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω",
    "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Sigma": "Σ", "Phi": "Φ",
    "Psi": "Ψ", "Omega": "Ω",
}  # fmt: skip
SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
DOT, DDOT = "\u0307", "\u0308"
_TRAILING_DIGITS = re.compile(r"([A-Za-z]+?)(\d+)")


def _base(name: str) -> str:
    match = _TRAILING_DIGITS.fullmatch(name)
    stem, digits = (match.group(1), match.group(2)) if match else (name, "")
    return GREEK.get(stem, stem) + digits.translate(SUBSCRIPT)


def label(name: str) -> str:
    """A readable label for a symbol name in the project's convention."""
    if name.endswith("_ddot"):
        return _base(name[: -len("_ddot")]) + DDOT
    if name.endswith("_dot"):
        return _base(name[: -len("_dot")]) + DOT
    if "_" in name:
        head, _, tail = name.partition("_")
        return _base(head) + "_" + _base(tail)
    return _base(name)
