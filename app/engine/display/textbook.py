"""Textbook forms for display: the same expressions, printed in the order a reader writes them.

Display only: the SymPy strings of the contract are untouched; only the LaTeX changes.

* In a product, numbers come first, then parameters in a reader's order (masses, then g,
  then stiffnesses and drags, then the rest alphabetically), then constants of the motion,
  then coordinates, velocities and accelerations, then functions, then bracketed sums:
  ``½ m R² θ̇²``, ``m g R (1 − cos θ)``.
* A product of parameters over parameters is a fraction in front: ``(g/R) sin θ``.
* In a sum, higher derivatives come first (``θ̈ + … ``, kinetic before potential terms) and,
  within a bracket, positive terms before negative ones: ``(1 − cos θ)``, ``(x₂ − x₁ − l₀)``.
* A fraction inside a fraction is written with a slash, so nothing shrinks to script size.
* ``equation`` divides an Euler–Lagrange residual by its acceleration's coefficient when the
  mass matrix is diagonal and that coefficient is a single term (``θ̈ + (g/R) sin θ = 0``), keeps
  an inertia that adds masses as 𝓜 q̈ = f (``(m₁ + m₂ + M/2) z̈ = (m₁ − m₂) g``), and divides by its
  parameter factor otherwise.

Bounded and deterministic: an expression of more than ``NODE_BUDGET`` nodes is printed by
SymPy's own ``latex``; every ordering ends on SymPy's canonical sort key.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy as sp
from sympy.printing.latex import LatexPrinter
from sympy.printing.str import StrPrinter

from app.engine.algebra.budget import memoized
from app.engine.algebra.simplify import larger_than, pythagoras
from app.engine.display.names import MASS_NAME, tex_greek, unicode

NODE_BUDGET = 600

# A reader's order of parameter names: masses (MASS_NAME), then gravity, then stiffnesses and drags.
_FIRST = {"g": 1, "k": 2, "kappa": 2, "b": 2}


def _level(symbol: sp.Symbol) -> int:
    """0 for a coordinate (or anything else), 1 for a velocity, 2 for an acceleration."""
    return 2 if symbol.name.endswith("_ddot") else 1 if symbol.name.endswith("_dot") else 0


def _acceleration(f: sp.Expr) -> bool:
    """An acceleration (θ̈), or a power of one."""
    base = f.base if f.is_Pow else f
    return bool(base.is_Symbol and _level(base) == 2)


def _rate(f: sp.Expr) -> bool:
    """A velocity or an acceleration (θ̇, θ̈), or a power of one."""
    base = f.base if f.is_Pow else f
    return bool(base.is_Symbol and _level(base) >= 1)


def _parameter_rank(name: str) -> tuple[int, str, str]:
    rank = 0 if MASS_NAME.fullmatch(name) else _FIRST.get(name, 3)
    return rank, name.lower(), name


class _Printer(LatexPrinter):
    def __init__(self, names: dict[sp.Symbol, str], moving: set[sp.Symbol], first: sp.Symbol | None = None):
        # arccos, not acos: inverse trigonometric functions as a textbook names them
        super().__init__({"symbol_names": names, "fold_func_brackets": True, "inv_trig_style": "full"})
        self.moving = moving  # coordinates, velocities, accelerations and time
        self.first = first  # the term holding this symbol leads a top-level sum (an equation's own acceleration)
        self.depth = 0  # fractions open around what is being printed

    def _print_Symbol(self, expr: sp.Symbol, style: str = "plain") -> str:
        # a name missing from the table is still written as app/engine/display/names.py writes it (φ, not ϕ)
        if expr in self._settings["symbol_names"]:
            return self._settings["symbol_names"][expr]  # the caller's table is kept as given
        return tex_greek(super()._print_Symbol(expr, style))

    # --- classification -------------------------------------------------------
    def place(self, expr: sp.Expr) -> int:
        """The place of the first declared coordinate ``expr`` holds (-1: none)."""
        coordinates = [s for s in self._settings["symbol_names"] if s in self.moving and _level(s) == 0]
        return min((coordinates.index(s) for s in expr.free_symbols if s in coordinates), default=-1)

    def momenta(self, term: sp.Expr) -> list[int]:
        """The places (in the order of the coordinates) of the canonical momenta p_q that ``term`` holds."""
        order = [s.name for s in self._settings["symbol_names"] if not s.name.endswith(("_dot", "_ddot"))]
        return [order.index(s.name[2:]) for s in term.free_symbols if s.name.startswith("p_") and s.name[2:] in order]

    def constant(self, expr: sp.Expr) -> bool:
        return not (expr.free_symbols & self.moving)

    def level(self, expr: sp.Expr) -> int:
        return max((_level(s) for s in expr.free_symbols & self.moving), default=-1)

    def _factor_key(self, f: sp.Expr) -> tuple:
        if f.is_Number:
            return (-2,)
        base = f.base if f.is_Pow else f
        if isinstance(base, sp.Add) and self.constant(base):
            # (m₁ + m₂) g l₁: a constant sum goes in front; among sums, one holding a mass first, a power after
            # (m₁ + m₂)(l₁ + l₂), (m₁ + m₂)(l₁ − l₂)²
            lead = min(_parameter_rank(s.name) for s in base.free_symbols) if base.free_symbols else (9, "", "")
            return (-1, lead[0], f.is_Pow, sp.default_sort_key(f))
        if base.is_Symbol and base not in self.moving and MASS_NAME.fullmatch(base.name):
            # a mass before a bracket of other parameters, as a textbook writes it: m(1 + α²R²) ż, ½ m(1 + 4α²ρ²) ρ̇²
            # (a bracket holding a mass still leads: (m₁ + m₂) g l₁)
            return (-1, 0.5, f.is_Pow, *_parameter_rank(base.name))
        if base.is_Symbol and base not in self.moving:
            # a parameter, or a constant of the motion (p_φ, E_r) after the parameters
            momentum = base.name.startswith("p_") or base.name.startswith("E_")
            return (1 if momentum else 0, *_parameter_rank(base.name))
        if base.is_Symbol:
            # coordinates, velocities, then accelerations, all before the functions: m l θ̈ cos θ, m l θ̇² sin θ
            return (2, _level(base), sp.default_sort_key(base))
        if isinstance(base, sp.Add):
            return (4, 0, sp.default_sort_key(f))
        # functions in the order of the coordinates they hold, as declared: R sin θ cos φ, R sin θ sin φ
        return (3, self.place(base), sp.default_sort_key(f))

    def _term_key(self, signed: tuple[bool, sp.Expr], top: bool) -> tuple:
        negative, term = signed
        if top:
            own = self.first is not None and term.has(self.first)
            held = self.momenta(term)
            if held and not negative:
                # a positive term holding a canonical momentum is kinetic (a Hamiltonian's p_r²/(2m)): first, in
                # the order of the coordinates
                return (not own, -1.5, negative, min(held), sp.default_sort_key(term))
            # the term holding ``first`` leads whatever its level (U_eff's centrifugal piece before −mgD sin α)
            return (not own, -self.level(term), negative, sp.default_sort_key(term))
        # a parameter times a whole number ranks as the parameter: 3M + m + 2m sin² α, as a textbook writes a
        # determinant (a fraction of one, an added inertia M/2, stays after the masses: m₁ + m₂ + M/2)
        coeff, alone = term.as_coeff_Mul()
        named = alone if alone.is_Symbol and alone not in self.moving and coeff.is_Integer else None
        rank = _parameter_rank(named.name) if named is not None else (9, "", "")
        if getattr(self, "_constants_first", False):
            return (negative, not self.constant(term), rank, sp.default_sort_key(term))
        return (self.constant(term) and not term.is_Number, negative, rank, sp.default_sort_key(term))

    def split_sign(self, expr: sp.Expr) -> tuple[bool, sp.Expr]:
        """(negative, |expr|): a bracket of negative terms only is written positive, −(m₁ + m₂)."""
        if not isinstance(expr, sp.Mul):
            return (True, -expr) if expr.could_extract_minus_sign() else (False, expr)
        coeff, rest = expr.as_coeff_Mul()
        negative = bool(coeff < 0) if coeff.is_Number else False
        factors = []
        for f in sp.Mul.make_args(rest):
            if isinstance(f, sp.Add) and all(a.could_extract_minus_sign() for a in f.args):
                negative, f = not negative, -f
            factors.append(f)
        magnitude = abs(coeff) if coeff.is_Number else coeff
        return negative, sp.Mul(magnitude, *factors, evaluate=False) if magnitude != 1 else sp.Mul(
            *factors, evaluate=False
        )

    # --- sums ------------------------------------------------------------------
    def ordered_terms(self, expr: sp.Add, top: bool) -> list[tuple[bool, sp.Expr]]:
        """The terms of a sum as (negative, |term|) in the order the page prints them (the running text's too)."""
        signed = [self.split_sign(t) for t in expr.args]
        # a sum of constants alone (a mass matrix's entry, m_eff) is ordered as in a bracket, masses first:
        # m₁ + m₂ + M/2, not M/2 + m₁ + m₂
        top = top and not all(self.constant(t) for _, t in signed)
        # a bracket whose moving terms are all negative starts with its constants: (2m₁ + m₂ − m₂ cos 2Δ); so
        # does a bracket below a fraction bar, as a textbook writes a determinant: l(M + m sin² φ)
        below = getattr(self, "below", False) and any(not self.constant(t) for _, t in signed)
        self._constants_first = not top and (below or all(neg for neg, t in signed if not self.constant(t)))
        return sorted(signed, key=lambda st: self._term_key(st, top))

    def _print_Add(self, expr: sp.Add, order: Any = None) -> str:
        top = getattr(self, "_top", False)
        self._top = False
        terms = self.ordered_terms(expr, top)
        out = ""
        for i, (negative, term) in enumerate(terms):
            if negative:
                text = "- " + self._print(term)
            else:
                text = ("+ " if i else "") + self._print(term)
            out += (" " if i else "") + text
        return out

    # --- products --------------------------------------------------------------
    def _wrap(self, f: sp.Expr) -> str:
        if not isinstance(f, sp.Add):
            return self._print(f)
        outer, self.bracket = getattr(self, "bracket", False), True
        try:
            return rf"\left({self._print(f)}\right)"
        finally:
            self.bracket = outer

    def ordered_factors(self, factors: Sequence[sp.Expr]) -> list[sp.Expr]:
        """The factors of a product in the order the page prints them (the running text's too): m g R sin θ."""
        ordered = sorted(factors, key=self._factor_key)
        brackets = [f for f in ordered if isinstance(f, sp.Add) and not self.constant(f)]
        if brackets:
            # an acceleration after a coefficient that moves, as a textbook writes it: (1 + 4α²ρ²) ρ̈; and a
            # velocity after one that holds positions only, an inertia that varies, m(1 + 4α²ρ²) ρ̇, as
            # ½ m(1 + 4α²ρ²) ρ̇² (a bracket holding a rate keeps its place after it: ρ(ω² − 4α²ρ̇²))
            last = _rate if all(self.level(f) == 0 for f in brackets) else _acceleration
            ordered = [f for f in ordered if not last(f)] + [f for f in ordered if last(f)]
        if (
            len(ordered) == 2 and isinstance(ordered[0], sp.Add) and self.constant(ordered[0])
            and ordered[1].is_Symbol and ordered[1] not in self.moving and MASS_NAME.fullmatch(ordered[1].name)
        ):  # fmt: skip
            # a mass times a sum of parameters, alone, as a textbook writes it: M(m₁ + m₂), m(1 + α²R²)
            ordered.reverse()
        return ordered

    def _product(self, factors: Sequence[sp.Expr], bare: bool = False) -> str:
        if bare and len(factors) == 1:
            return self._print(factors[0])  # a sum alone over a fraction bar needs no brackets
        return " ".join(self._wrap(f) for f in self.ordered_factors(factors))

    def under(self, bottom: Sequence[sp.Expr], bare: bool = True) -> str:
        """The factors below a fraction bar, each bracket's constants first: l(M + m sin² φ)."""
        outer, self.below = getattr(self, "below", False), True
        try:
            return self._product(bottom, bare=bare)
        finally:
            self.below = outer

    def _print_Function(self, expr: sp.Expr, exp: str | None = None) -> str:
        # an angle below a fraction bar keeps its own order: cos(2θ + 2α), as in the numerator
        outer, self.below = getattr(self, "below", False), False
        try:
            return super()._print_Function(expr, exp)
        finally:
            self.below = outer

    def _frac(self, num: str, den: str) -> str:
        return rf"\frac{{{num}}}{{{den}}}"

    def _print_Mul(self, expr: sp.Expr) -> str:
        negative, expr = self.split_sign(expr)
        if negative:
            return "- " + self._print_Mul(expr)
        coeff, rest = expr.as_coeff_Mul()
        factors = sp.Mul.make_args(rest)
        num: list[sp.Expr] = []
        den: list[sp.Expr] = []
        for f in factors:
            if f.is_Pow and f.exp.is_Rational and f.exp.is_negative:
                den.append(f.base ** (-f.exp))
            else:
                num.append(f)
        p, q = sp.fraction(sp.Rational(coeff)) if coeff.is_Rational else (coeff, sp.Integer(1))
        if not den and q == 1:
            lead = "" if p == 1 else self._print(p) + " "
            return (lead + self._product(num)).strip() or "1"
        if self.depth > 0:
            return self._slashed(p, q, num, den)
        if getattr(self, "bracket", False) and p == 1 and q == 2 and not den and len(num) == 1 and self.constant(num[0]):
            # half of one parameter's power within a bracket as a textbook writes it: m(gα − ½ω²)ρ²
            base = num[0].base if num[0].is_Pow else num[0]
            if base.is_Symbol and not MASS_NAME.fullmatch(base.name):
                return rf"\tfrac{{1}}{{2}} {self._print(num[0])}"
        const_num = [f for f in num if self.constant(f)]
        const_den = [f for f in den if self.constant(f)]
        moving_den = [f for f in den if not self.constant(f)]
        self.depth += 1
        try:
            # one fraction when the denominator moves, when nothing moves, or when only 1 stands over the
            # constants: (F cos ωt − b ẋ − k x)/m rather than (1/m)(…)
            bare = p == 1 and not const_num
            if moving_den or not [f for f in num if not self.constant(f)] or (bare and const_den):
                # one fraction over everything: (p_φ² cos θ)/(m² R⁴ sin³ θ), or g/R alone
                top = ([p] if p != 1 else []) + num
                bottom = ([q] if q != 1 else []) + den
                return self._frac(self._product(top, bare=True) if top else "1", self.under(bottom))
            moving_num = [f for f in num if not self.constant(f)]
            if const_den:
                top = ([p] if p != 1 else []) + const_num
                lead = self._frac(
                    self._product(top, bare=True) if top else "1",
                    self._product(([q] if q != 1 else []) + const_den, bare=True),
                )
                return lead + " " + self._product(moving_num)
            lead = self._frac(self._print(p), self._print(q))
        finally:
            self.depth -= 1
        return lead + " " + self._product(num)

    def _slashed(self, p: sp.Expr, q: sp.Expr, num: list[sp.Expr], den: list[sp.Expr]) -> str:
        """Inside a fraction: a/b on one line, so that nothing is set at script size."""
        top = ([p] if p != 1 else []) + num
        bottom = ([q] if q != 1 else []) + den
        b = self.under(bottom, bare=False)
        if len(bottom) > 1:
            b = rf"\left({b}\right)"
        return f"{self._product(top) if top else '1'} / {b}"

    def _print_Pow(self, expr: sp.Pow) -> str:
        if expr.exp.is_Rational and expr.exp.is_negative:
            return self._print_Mul(expr)
        return super()._print_Pow(expr)

    def doprint(self, expr: Any) -> str:
        self._top = isinstance(expr, sp.Add)
        return super().doprint(expr)


def _moving(names: dict[sp.Symbol, str], expr: Any) -> set[sp.Symbol]:
    """The symbols of ``expr`` that change along a motion: coordinates (those with a velocity), rates and t."""
    known = {s.name for s in names}
    rates = {n for n in known if n.endswith("_dot")}
    stems = {n[: -len("_ddot")] if n.endswith("_ddot") else n[: -len("_dot")] for n in rates}
    free: set[Any] = getattr(expr, "free_symbols", set())
    return {s for s in free if s.name == "t" or s.name in stems or s.name.endswith(("_dot", "_ddot"))}


def latex(expr: Any, names: dict[sp.Symbol, str], first: sp.Symbol | None = None) -> str:
    """``expr`` as LaTeX in textbook order (SymPy's ``latex`` beyond the node budget).

    ``first``: in a sum, the term holding this symbol comes first (an equation's own acceleration).
    """
    if isinstance(expr, sp.MatrixBase):
        # a mutable matrix is no sp.Basic: each entry in textbook order all the same (m R², not R² m)
        return _Printer(names, _moving(names, sp.ImmutableMatrix(expr)), first).doprint(expr)
    if not isinstance(expr, sp.Basic) or larger_than(expr, NODE_BUDGET):
        return tex_greek(sp.latex(expr, symbol_names=names, inv_trig_style="full"))
    # a document prints most expressions several times (the steps and the results box; a double pendulum's
    # 161 printings are of 62 expressions): each once per document and set of names
    key = (expr, tuple(names.items()), first)
    return memoized("latex", key, lambda: _Printer(names, _moving(names, expr), first).doprint(expr))


def _simplest(const: sp.Expr) -> sp.Expr:
    """The shortest of a constant coefficient's forms: as it is, common factors out, or cancelled."""
    # a product is worth rewriting only when a sum sits in it ((1 + 1/tan²a)/(1 + 1/tan²a)², not m g)
    mixed = isinstance(const, (sp.Mul, sp.Pow)) and any(
        isinstance(f.as_base_exp()[0], sp.Add) for f in sp.Mul.make_args(const)
    )
    if not (isinstance(const, sp.Add) or mixed) or larger_than(const, NODE_BUDGET // 4):
        return const
    if sp.denom(const).could_extract_minus_sign():
        # a denominator's sign in front, as a textbook writes it: −1/(1 + c²), not 1/(−c² − 1)
        const = sp.factor_terms(const)
    forms = [const, sp.factor_terms(const), sp.cancel(const)]
    if const.has(sp.tan, sp.cot):
        # tan and cot as quotients of sin and cos, cancelled, then sin² + cos² = 1: a bead on a cone's
        # (1 + 1/tan²a)/(1 + 1/tan²a)² is sin²a, and g/((1 + 1/tan²a) tan a) is g sin a cos a
        quotients = const.replace(sp.tan, lambda x: sp.sin(x) / sp.cos(x)).replace(sp.cot, lambda x: sp.cos(x) / sp.sin(x))
        cancelled = sp.cancel(quotients)
        angles = {f.args[0] for f in cancelled.atoms(sp.sin, sp.cos)}
        forms.append(cancelled.xreplace({sp.sin(x) ** 2 + sp.cos(x) ** 2: sp.Integer(1) for x in angles}))
        forms.append(sp.factor_terms(pythagoras(cancelled)))
    return min(forms, key=lambda e: (sp.count_ops(e), forms.index(e)))


def _content(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """The constant monomial factor common to every term (a number, parameters and their powers)."""
    common = sp.factor_terms(expr)
    if not isinstance(common, sp.Mul):
        return sp.Integer(1)
    return sp.Mul(*(f for f in common.args if not isinstance(f, sp.Add) and not (f.free_symbols & moving)))


def masses_summed(coefficient: sp.Expr) -> bool:
    """Whether an acceleration's coefficient is an inertia that adds masses: m₁ + m₂ + M/2, l²(m₁ + m₂); not a
    single term (M l²/3) nor a sum with anything but masses in it (m(1 + c²))."""
    sums = [f for f in sp.Mul.make_args(sp.factor_terms(coefficient)) if isinstance(f, sp.Add)]
    return bool(sums) and all(
        isinstance(t.as_coeff_Mul()[1], sp.Symbol)
        and t.as_coeff_Mul()[0].is_Rational
        and MASS_NAME.fullmatch(t.as_coeff_Mul()[1].name) is not None
        for f in sums
        for t in f.args
    )


def normalised(
    residual: sp.Expr, coefficient: sp.Expr, diagonal: bool, names: dict[sp.Symbol, str], own: sp.Symbol | None = None
) -> sp.Expr:
    """An Euler–Lagrange residual scaled for display (``scaled``'s first part)."""
    return scaled(residual, coefficient, diagonal, names, own)[0]


def scaled(
    residual: sp.Expr, coefficient: sp.Expr, diagonal: bool, names: dict[sp.Symbol, str], own: sp.Symbol | None = None
) -> tuple[sp.Expr, sp.Expr]:
    """An Euler–Lagrange residual scaled for display (the equation residual = 0 is unchanged), and the factor s
    it was scaled by: residual = s × (the form returned).

    Divided by its acceleration's coefficient when the mass matrix is diagonal and that
    coefficient is a product (θ̈ + (g/R) sin θ), else by the constant factor common to its
    terms; terms with the same acceleration collected ((1 + 4α²ρ²) ρ̈), like terms added
    ((2gα − ω²) ρ), a common parameter factor of the rest taken out ((k/m₁)(x₁ − x₂ + l₀)).
    """
    if larger_than(residual, NODE_BUDGET):
        return residual, sp.Integer(1)
    # sin²α + cos²α = 1 of one argument never survives into an equation (a particle on a cone: r̈, not
    # r̈/(sin²α + cos²α)): collapsed in the residual and in the coefficient it is divided by
    residual, coefficient = pythagoras(residual), pythagoras(coefficient)
    moving = _moving(names, residual) | _moving(names, coefficient)
    expanded = sp.expand(residual)
    scaled_by = sp.factor_terms(coefficient)
    product = not any(isinstance(f, sp.Add) and f.free_symbols & moving for f in sp.Mul.make_args(scaled_by))
    # an inertia that is a single term is divided out, θ̈ + (3g/2l) sin θ = 0; one that is a sum of masses is kept
    # in sight, 𝓜 q̈ = f as the Euler–Lagrange equation gives it: (m₁ + m₂ + M/2) z̈ = (m₁ − m₂) g
    if diagonal and masses_summed(coefficient):
        scale = sp.Integer(1)
    else:
        scale = scaled_by if diagonal and product else _content(expanded, moving)
    if scale == 0:
        return residual, sp.Integer(1)
    accelerations: dict[sp.Expr, sp.Expr] = {}
    groups: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(expanded):
        t = term / scale
        acc = sorted((s for s in t.free_symbols & moving if _level(s) == 2), key=sp.default_sort_key)
        if len(acc) == 1 and t.is_polynomial(acc[0]) and sp.degree(t, acc[0]) == 1:
            accelerations[acc[0]] = accelerations.get(acc[0], sp.Integer(0)) + t / acc[0]
            continue
        # the term split into its constant factors and its moving ones, each taken as it stands: dividing t by
        # its constant would leave −1/(1 + c²), which SymPy keeps as 1/(−1 − c²), half in the moving part
        const = sp.Mul(*(f for f in sp.Mul.make_args(t) if not (f.free_symbols & moving)))
        part = sp.Mul(*(f for f in sp.Mul.make_args(t) if f.free_symbols & moving))
        groups[part] = groups.get(part, sp.Integer(0)) + const
    # each acceleration with its coefficient; constants of like terms added
    leading = [sp.Mul(_simplest(c), a) for a, c in accelerations.items()]
    rest: list[sp.Expr] = []
    for part, const in groups.items():
        if part == 1:
            # terms free of the coordinates stay separate terms; a single one is written in its simplest form
            rest += _over_one_sum(const) if isinstance(const, sp.Add) else [_simplest(const)]
        else:
            rest.append(sp.Mul(_simplest(const), part))
    if len(rest) > 1:
        # a parameter factor common to the rest, such as k/m₁, goes in front of one bracket
        common, inner = sp.factor_terms(sp.Add(*rest)).as_independent(*moving, as_Add=False)
        if isinstance(inner, sp.Add) and not sp.numer(common).is_Number:
            rest = [sp.Mul(common, inner, evaluate=False)]
    leading.sort(key=lambda e: own is None or not e.has(own))
    out = leading + rest
    if leading and leading[0].could_extract_minus_sign():
        out, scale = [-e for e in out], -scale
    return (sp.Add(*out, evaluate=False) if len(out) > 1 else out[0]), scale


def inertia_sides(shown: sp.Expr, names: dict[sp.Symbol, str]) -> tuple[sp.Expr, sp.Expr]:
    """An equation kept undivided (its inertia a sum of masses) as 𝓜 q̈ = f: the acceleration's term on the left,
    the rest moved to the right with a common factor taken out, (m₁ + m₂ + M/2) z̈ = (m₁ − m₂) g."""
    moving = _moving(names, shown)
    left = [t for t in sp.Add.make_args(shown) if any(_level(s) == 2 for s in t.free_symbols & moving)]
    right = [-t for t in sp.Add.make_args(shown) if t not in left]
    force = sp.factor_terms(sp.Add(*right)) if right else sp.Integer(0)
    return sp.Add(*left, evaluate=False) if len(left) > 1 else left[0], force


def _over_one_sum(const: sp.Expr) -> list[sp.Expr]:
    """The constant terms of an equation: separate terms, unless all stand over one sum, which a textbook writes
    once: ÿ − (m₁ − m₂) g/(m₁ + m₂ + M/2), not ÿ + m₂ g/(m₁ + m₂ + M/2) − m₁ g/(m₁ + m₂ + M/2); a numerator
    led by a minus written with its sign in front of the fraction."""
    denominators = {sp.denom(t) for t in const.args}
    (den,) = denominators if len(denominators) == 1 else (None,)
    if not isinstance(den, sp.Add):
        return list(const.args)
    # each term times the one denominator is its numerator: the numerators added, their common factor out
    top = sp.factor_terms(sp.Add(*(t * den for t in const.args)))
    held = [f for f in sp.Mul.make_args(top) if isinstance(f, sp.Add)]
    if len(held) == 1 and held[0].could_extract_minus_sign():
        # (m₂ − m₁) g is −(m₁ − m₂) g: the bracket as the acceleration prints it, the sign in front
        rest = [-f if f is held[0] else f for f in sp.Mul.make_args(top)]
        return [sp.Mul(-1, *rest, 1 / den, evaluate=False)]
    return [sp.Mul(top, 1 / den, evaluate=False)]


_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
# SymPy's names of the inverse functions, and a textbook's
TEXTBOOK_FUNCTIONS = {"acos": "arccos", "asin": "arcsin", "atan": "arctan"}


class _Unicode(StrPrinter):
    """One line of Unicode a reader writes in running text: −mgR, 1/(mR²), (g/R) sin θ, never ** or *."""

    def __init__(self, order: _Printer):
        super().__init__({"order": None})
        self.tex = order  # the textbook printer, for its order of factors (masses, g, then the rest)

    def _print_Symbol(self, expr: sp.Symbol) -> str:
        return unicode(expr.name)

    def _print_Rational(self, expr: sp.Rational) -> str:
        return f"{expr.p}/{expr.q}" if expr.q != 1 else str(expr.p)

    def _print_Pi(self, expr: sp.Expr) -> str:
        return "π"

    def _print_Abs(self, expr: sp.Abs) -> str:
        return f"|{self._print(expr.args[0])}|"

    def _print_Function(self, expr: sp.Function) -> str:
        (arg,) = expr.args if len(expr.args) == 1 else (None,)
        # arccos, not acos: an inverse function as a textbook names it
        name = TEXTBOOK_FUNCTIONS.get(expr.func.__name__, expr.func.__name__)
        if arg is not None and (arg.is_Symbol or arg.is_Number):
            return f"{name} {self._print(arg)}"
        return f"{name}({', '.join(self._argument(a) for a in expr.args)})"

    def _argument(self, arg: sp.Expr) -> str:
        """A function's argument, in its own order below a fraction bar too (cos(2θ + 2α)), as the LaTeX."""
        outer, self.tex.below = getattr(self.tex, "below", False), False
        try:
            return self._print(arg)
        finally:
            self.tex.below = outer

    def _factor(self, f: sp.Expr) -> str:
        text = self._print(f)
        return f"({text})" if isinstance(f, sp.Add) else text

    def _print_Pow(self, expr: sp.Pow, rational: bool = False) -> str:
        base, exp = expr.as_base_exp()
        root = {sp.Rational(1, 2): "√", sp.Rational(1, 3): "∛", sp.Rational(1, 4): "∜"}.get(exp)
        if root:
            # √(g/R), ∜m: the roots the LaTeX beside it writes \sqrt, \sqrt[3], \sqrt[4]
            return f"{root}({self._print(base)})" if isinstance(base, (sp.Add, sp.Mul)) else f"{root}{self._print(base)}"
        if exp.is_Integer and exp > 0 and base.is_Function and len(base.args) == 1:
            # sin² θ, cos²(θ₁ − θ₂)
            arg = self._argument(base.args[0])
            simple = base.args[0].is_Symbol or base.args[0].is_Number
            return f"{base.func.__name__}{str(exp).translate(_SUPERSCRIPT)}" + (f" {arg}" if simple else f"({arg})")
        if exp.is_Integer and exp > 0:
            inner = self._print(base)
            wrapped = f"({inner})" if isinstance(base, (sp.Add, sp.Mul, sp.Pow)) or base.is_Function else inner
            return wrapped + str(exp).translate(_SUPERSCRIPT)
        if exp.is_Integer and exp < 0:
            return self._print_Mul(expr)
        return f"{self._factor(base)}^({self._print(exp)})"

    def _product(self, factors: Sequence[sp.Expr]) -> str:
        out, previous_function = "", False
        # the factors in the order the LaTeX of the same page prints them: m(1 + α²R²), 2gα − ω², ρ cos(ωt)
        for f in self.tex.ordered_factors(factors):
            text = self._factor(f)
            # names are written side by side (mgR); a function, or its power, is set apart by a space (m g sin θ ->
            # mg sin θ, m sin²θ: never msin²θ)
            function = f.is_Function or (f.is_Pow and f.base.is_Function)
            out += (" " if out and (function or previous_function) else "") + text
            previous_function = function
        return out

    def _print_Mul(self, expr: sp.Expr) -> str:
        # a bracket of negative terms written positive, as the LaTeX writes it: −(m₁ + m₂)g, not (−m₁ − m₂)g
        negative, expr = self.tex.split_sign(expr)
        if negative:
            return "−" + self._print_Mul(expr)
        coeff, rest = expr.as_coeff_Mul()
        sign = "−" if coeff < 0 else ""
        coeff = abs(coeff)
        num: list[sp.Expr] = []
        den: list[sp.Expr] = []
        for f in sp.Mul.make_args(rest):
            base, exp = f.as_base_exp()
            (den if exp.is_Number and exp < 0 else num).append(base ** (-exp) if exp.is_Number and exp < 0 else f)
        p, q = (coeff.p, coeff.q) if coeff.is_Rational else (coeff, 1)
        top = ("" if p == 1 and num else self._print(sp.Integer(p) if coeff.is_Rational else p)) + self._product(num)
        bottom = [*([sp.Integer(q)] if q != 1 else []), *den]
        if not bottom:
            return sign + top
        # below the bar each bracket's constants first, as the LaTeX writes it: l(M + m sin² φ)
        outer, self.tex.below = getattr(self.tex, "below", False), True
        try:
            below = self._product(bottom)
        finally:
            self.tex.below = outer
        if len(bottom) > 1 or isinstance(bottom[0], sp.Add):
            below = f"({below})" if not below.startswith("(") or len(bottom) > 1 else below
        top = f"({top})" if isinstance(rest, sp.Add) and not num else top
        return f"{sign}{top or '1'}/{below}"

    def _print_Add(self, expr: sp.Add, order: Any = None) -> str:
        top = getattr(self, "_top", False)
        self._top = False
        out = ""
        # the terms in the order the LaTeX of the same page prints them: (1 + α²R²), (x₂ − x₁ − l₀)
        for i, (negative, term) in enumerate(self.tex.ordered_terms(expr, top)):
            text = self._print(term)
            if negative:
                out += (" − " if i else "−") + text
            else:
                out += (" + " if i else "") + text
        return out

    def doprint(self, expr: Any) -> str:
        self._top = isinstance(expr, sp.Add)
        return super().doprint(expr)


def unicode_text(expr: Any, names: dict[sp.Symbol, str] | None = None) -> str:
    """An expression as one line of Unicode for prose (messages, reasons, captions): −mgR, 1/(mR²)."""
    expr = sp.sympify(expr)
    names = names or {}
    return _Unicode(_Printer(names, _moving(names, expr))).doprint(expr)
