"""Display names of symbols: the one home of how a name is written (LaTeX, Unicode, plain).

Every route that shows a symbol's name (derivation steps, controls, prose, plot axes,
diagrams, exports) reads it from here, so ``Omega`` is Ω everywhere:

    latex("theta_dot") -> \\dot{\\theta}    unicode("theta_dot") -> θ̇    plain("theta_dot") -> theta_dot
    latex("x1") -> x_{1}                   unicode("x1") -> x₁
    latex("p_phi") -> p_{\\varphi}          unicode("p_phi") -> p_φ
"""

from __future__ import annotations

import re
from collections.abc import Iterable

# The mass matrix is ℳ (a calligraphic M) on every page: a body's mass is often M (the pulley's, the wedge's, a total
# mass in an erratum), and one letter means one quantity throughout the book.  Its Unicode is U+2133, the plain
# script capital that KaTeX's \mathcal{M} draws, so the prose beside a formula shows the formula's glyph (not a bold one)
MASS_MATRIX = (r"\mathcal{M}", "ℳ")  # (LaTeX, Unicode)
# a mass's name (m, M, m₁, μ): masses come first in a product and a textbook takes them out of a sum first
MASS_NAME = re.compile(r"(m|M|mu)\d*")

# letters every page prints with a meaning of its own: a declared name spelled so would give one letter two
# meanings on the page (a charge q beside the coordinates q of S[q] and ℳ q̈ = f), so a user's system is refused
# with a name to use instead (app/service/users/user_checks.py)
PAGE_LETTERS: dict[str, tuple[str, str]] = {
    "q": (f"the generalized coordinates (S[q], {MASS_MATRIX[1]} q̈ = f)", "e"),
    "p": ("a generalized momentum (p_x, p_θ)", "P0"),
    "S": ("the action, S = ∫ L dt", "S0"),
    "T": ("the kinetic energy", "T0"),
    "U": ("the potential energy", "U0"),
    "L": ("the Lagrangian", "l"),
    "h": ("the energy function", "h0"),
    "H": ("the Hamiltonian", "H0"),
    "E": ("the energy, T + U", "E0"),
    "f": (f"the right-hand side of {MASS_MATRIX[1]} q̈ = f", "f0"),
    "Q": ("a generalized force", "Q0"),
}


def page_letter_clash(name: str, what: str) -> str | None:
    """Why a declared name cannot be used, when a page already prints that letter with another meaning; else None.
    A coordinate may be called q (it is then the q of S[q])."""
    if name not in PAGE_LETTERS or (name == "q" and what == "coordinate"):
        return None
    meaning, instead = PAGE_LETTERS[name]
    return (
        f"{what} {name!r} clashes with the page's own letter {name}, {meaning}: one letter would mean two things. "
        f"Choose another name, such as {instead}" + (f" (printed {unicode(instead)})" if unicode(instead) != instead else "")
    )


# The Greek letters LaTeX has a command for, by name, with their Unicode characters (the command is a
# backslash and the name; the capitals left out are written as Latin letters)
GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ", "eta": "η",
    "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ",
    "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "upsilon": "υ", "phi": "φ", "chi": "χ", "psi": "ψ",
    "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Pi": "Π", "Sigma": "Σ",
    "Upsilon": "Υ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
}  # fmt: skip
SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
DOT, DDOT = "\u0307", "\u0308"
_TRAILING_DIGITS = re.compile(r"([A-Za-z]+?)(\d+)")
HAT = "\u0302"
# accents written as a suffix of the name: a velocity's dots, and a unit vector's hat (r_hat -> r̂)
_DOTS = (("_ddot", "ddot", DDOT), ("_dot", "dot", DOT), ("_hat", "hat", HAT))
# LaTeX's \phi is the closed ϕ; the φ of running text (U+03C6) is LaTeX's \varphi: one glyph on a page
_TEX_GREEK = {"phi": "varphi"}


def tex_greek(tex: str) -> str:
    """LaTeX printed elsewhere (SymPy's printer) with each Greek command as this module writes it: \\phi -> \\varphi."""
    for stem, command in _TEX_GREEK.items():
        tex = re.sub(rf"\\{stem}(?![A-Za-z])", "\\\\" + command, tex)
    return tex


def _split(name: str) -> tuple[str, str]:
    match = _TRAILING_DIGITS.fullmatch(name)
    return (match.group(1), match.group(2)) if match else (name, "")


def _tex_base(name: str) -> tuple[str, str]:
    """(stem, subscript) in LaTeX: theta1 -> (\\theta, 1); a name of several letters that is no Greek letter's is
    one upright name, th -> \\mathrm{th} (never the product t h), so that a dot sits over the whole of it."""
    stem, digits = _split(name)
    if stem in GREEK:
        return "\\" + _TEX_GREEK.get(stem, stem), digits
    # a differential (dt, dr: d and one letter, as the errata's dt/dr writes) stays as a textbook prints it
    differential = len(stem) == 2 and stem[0] == "d"
    return (rf"\mathrm{{{stem}}}" if len(stem) > 1 and stem.isalpha() and not differential else stem), digits


# a rate of a name of several letters in running text: a spacing dot after the whole name (th˙), as a combining
# dot would sit on its last letter alone and read as t times ḣ
_SPACING = {DOT: "\u02d9", DDOT: "\u00a8", HAT: "\u02c6"}


def _uni_base(name: str, mark: str = "") -> str:
    # the dot sits on the letter, before any subscript digits: θ̇₁
    stem, digits = _split(name)
    if mark and len(stem) > 1 and stem not in GREEK:
        return stem + digits.translate(SUBSCRIPT) + _SPACING[mark]
    return GREEK.get(stem, stem) + mark + digits.translate(SUBSCRIPT)


def latex(name: str) -> str:
    """A symbol name as LaTeX; a velocity's dot sits on the stem, not on the subscript."""
    for suffix, accent, _ in _DOTS:
        if name.endswith(suffix):
            base = name[: -len(suffix)]
            if "_" in base:
                # a rate of a subscripted name: the dot on the letter, not over the subscript (p_theta_dot -> ṗ_θ,
                # \dot{p}_{\theta}, as a textbook prints Hamilton's ṗ_θ = −∂H/∂θ)
                head, _, tail = base.partition("_")
                return f"{latex(head + suffix)}_{{{_tex_subscript(tail)}}}"
            stem, sub = _tex_base(base)
            return rf"\{accent}{{{stem}}}" + (f"_{{{sub}}}" if sub else "")
    if "_" in name:
        head, _, tail = name.partition("_")
        return f"{latex(head)}_{{{_tex_subscript(tail)}}}"
    stem, sub = _tex_base(name)
    return stem + (f"_{{{sub}}}" if sub else "")


def _tex_subscript(tail: str) -> str:
    """What follows a name's ``_`` as its LaTeX subscript; a word is upright text: U_eff -> U_{\\text{eff}}."""
    word = tail.isalpha() and len(tail) > 1 and tail not in GREEK
    return r"\text{" + tail + "}" if word else latex(tail)


def unicode(name: str) -> str:
    """A symbol name as a reader writes it in running text and on plots: theta_dot -> θ̇, x1 -> x₁; a conserved
    sum's name term by term (p_x1 + p_x2 -> p_x₁ + p_x₂)."""
    if " + " in name:
        return " + ".join(unicode(part) for part in name.split(" + "))
    for suffix, _, mark in _DOTS:
        if name.endswith(suffix):
            base = name[: -len(suffix)]
            if "_" in base:
                # the dot on the letter before the subscript: p_theta_dot -> ṗ_θ
                head, _, tail = base.partition("_")
                return unicode(f"{head}{suffix}") + "_" + unicode(tail)
            return _uni_base(base, mark)
    if "_" in name:
        head, _, tail = name.partition("_")
        return _uni_base(head) + "_" + _uni_base(tail)
    return _uni_base(name)


def said_all(names: list[str]) -> list[str]:
    """Names as ``said`` says them, each coordinate followed by its velocity, then its acceleration (θ, θ̇, θ̈)."""

    def order(name: str) -> tuple[str, int]:
        for rank, suffix in ((2, "_ddot"), (1, "_dot")):
            if name.endswith(suffix):
                return name[: -len(suffix)], rank
        return name, 0

    return [said(n) for n in sorted(names, key=order)]


def said(name: str) -> str:
    """A name in a sentence a student reads: as a textbook prints it, then once how it is typed where the two
    differ (theta_ddot -> θ̈ (type theta_ddot), m1 -> m₁ (type m1), R -> R)."""
    shown = unicode(name)
    return shown if shown == name else f"{shown} (type {name})"


def plain(name: str) -> str:
    """The name as typed in expressions (the project's symbol convention)."""
    return name


# A symbol name inside running text: a short stem with digits (m1, x2, l0) or a name with a subscript (theta_0).
_IN_PROSE = re.compile(r"\b(?:[A-Za-z]{1,2}\d+|[A-Za-z]+_(?:\d+|[A-Za-z]+\d*))\b")


def prose(text: str) -> str:
    """Running text with the symbol names in it written as a reader writes them: m1 -> m₁, theta_0 -> θ₀."""

    def one(match: re.Match[str]) -> str:
        name = match.group(0)
        head, _, tail = name.partition("_")
        # theta_0 is θ₀ (a subscript), p_phi is p_φ
        return unicode(head + tail) if tail.isdigit() else unicode(name)

    return _IN_PROSE.sub(one, text)


def display_names(names: Iterable[str]) -> dict[str, dict[str, str]]:
    """Each name with its three written forms, for the derivation document."""
    return {n: {"latex": latex(n), "unicode": unicode(n), "plain": plain(n)} for n in names}
