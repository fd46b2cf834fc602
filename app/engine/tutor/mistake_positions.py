"""The mistakes of a positions step: one Cartesian component of one body, in the generalised coordinates.

Where students go wrong first (a student's review of practice mode): sine and cosine swapped, a component
or one of its terms with the wrong sign, the point that carries a body left out of its position (the
wedge's X in the block's x), a point halfway along moving as far as its ends (the pulley's middle mass),
another coordinate in one term (θ₁ for θ₂), another component typed in this one's box.  Each is built from
the derivation's own positions, bounded by counts (a component has a handful of terms), never by time.
"""

from __future__ import annotations

from collections.abc import Iterator

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.display.names import unicode
from app.engine.display.spoken import spoken
from app.engine.document.notation import practice_axes
from app.engine.equations.constraints import AXES, cartesian_symbols
from app.engine.tutor.mistake_families import Mistake

MAX_TERMS = 8  # terms of one component tried one at a time

# how the figure draws each axis
# what each axis means, by index, in the step's letter for it (x or ξ, y or η, z or ζ: notation.practice_axes)
_AXIS_WORDS = (
    "{0} is measured across, to the right, as the figure draws it",
    "{0} is measured along the figure's third axis (into the page for a flat figure)",
    "{0} is measured upward, as the figure draws it: a point below the origin has {0} < 0",
)


def points(d: Derivation) -> tuple[tuple[sp.Expr, ...], ...]:
    """The position of every point a positions step asks about: each particle's, then the centre of each declared
    rigid body that moves (the cylinder's on the wedge, where the wedge's motion enters its velocity); a wheel
    turning on a fixed axle has no centre that moves."""
    centres = tuple(b.centre for b in d.mechanics.bodies if b.translation != 0)
    return (*d.mechanics.positions, *centres)


def _moving(d: Derivation, i: int, a: int) -> sp.Expr:
    """The part of body i's component a that moves (its constant lengths dropped: the origin's choice)."""
    return sp.Add(*_moving_terms(points(d)[i][a], (*d.table.q, d.table.t)))


def component_keys(d: Derivation) -> list[tuple[str, int, int]]:
    """(key, body, axis) of every component that moves: x, y, z for one body; x1, z2, … for several (the
    constraints' names, ``app.engine.equations.constraints.cartesian_symbols``). A component that is a constant (a
    planar figure's y = 0, a fixed pulley's x) has nothing to derive and is left out; so is a carrier's component
    that is a coordinate itself (the wedge's x = X), which the carried body's own component holds (its x is
    X + …): that one is asked, where the carrier's motion enters."""
    found = d.mechanics.positions and points(d)
    moving = (*d.table.q, d.table.t)
    out = []
    for i, triple in enumerate(cartesian_symbols(len(found))):
        for a, symbol in enumerate(triple):
            if found[i][a].has(*moving) and not _carrier_coordinate(d, i, a):
                out.append((symbol.name, i, a))
    return out


def _carrier_coordinate(d: Derivation, i: int, a: int) -> bool:
    """Whether body i's component a is a coordinate alone that another body's same component holds as a term."""
    own = _moving(d, i, a)
    if own not in d.table.q:
        return False
    moving = (*d.table.q, d.table.t)
    return any(j != i and own in _moving_terms(r[a], moving) for j, r in enumerate(points(d)))


def body_name(d: Derivation, i: int) -> str:
    """The body as the page names it: the block, the upper bob, the cylinder's centre; else particle 2."""
    particles = d.system.particles
    if i >= len(particles):
        moving = [b for b in d.mechanics.bodies if b.translation != 0]
        b = moving[i - len(particles)]
        return f"the {b.body.label or b.body.kind}'s centre"
    label = particles[i].label
    return f"the {label}" if label else f"particle {i + 1}"


def position_label(d: Derivation, i: int, a: int) -> str:
    """The step's label: 'x of the block' (ζ where a coordinate is named z: ``notation.practice_axes``)."""
    return f"{unicode(practice_axes(d)[a])} of {body_name(d, i)}"


def _swap(expr: sp.Expr) -> sp.Expr:
    """sin ↔ cos in every sine and cosine."""
    return expr.replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)),
        lambda e: sp.cos(e.args[0]) if isinstance(e, sp.sin) else sp.sin(e.args[0]),
    )


def _swap_of(expr: sp.Expr, x: sp.Expr) -> sp.Expr:
    """sin ↔ cos of the argument x only."""
    return expr.replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)) and e.args[0] == x,
        lambda e: sp.cos(e.args[0]) if isinstance(e, sp.sin) else sp.sin(e.args[0]),
    )


def _moving_terms(expr: sp.Expr, moving: tuple[sp.Symbol, ...]) -> list[sp.Expr]:
    return [t for t in sp.Add.make_args(sp.expand(expr)) if t.has(*moving)]


def position_mistakes(d: Derivation, i: int, a: int) -> Iterator[Mistake]:
    """The plausible wrong answers for body i's component a, most specific first."""
    positions, table = points(d), d.table
    axes = tuple(unicode(n) for n in practice_axes(d))
    axis, body = axes[a], body_name(d, i)
    moving = (*table.q, table.t)
    terms = _moving_terms(positions[i][a], moving)[:MAX_TERMS]
    # the moving part only: a position is judged up to a constant (its origin), so the figure's constant lengths
    # (the pulley's c, set by its string) are no part of what is asked
    truth = sp.Add(*terms)
    base = f"position.{cartesian_symbols(len(positions))[i][a].name}"

    # the point that carries this body left out: a part of this component that is another body's whole
    # moving component (the wedge's X in the block's x, the upper bob's l₁ sin θ₁ in the lower bob's)
    for j, other in enumerate(positions):
        carried = _moving_terms(other[a], moving)
        if j == i or not carried or len(carried) >= len(terms) or any(t not in terms for t in carried):
            continue
        carrier = body_name(d, j)
        yield Mistake(
            f"{base}.carried.{j + 1}",
            "position_carried",
            f"{carrier}'s {axis} left out",
            None,
            f"{body} moves with {carrier}, which carries it along, so its {axis} is {carrier}'s {axis} plus its own "
            f"part measured from {carrier}",
            truth - sum(carried),
        )

    # the whole component: a point halfway along moving as far as its ends (the pulley's middle mass), or twice
    # as far; its sign; sine and cosine swapped throughout
    varying = sum(terms)
    halves = all(t.as_coeff_Mul()[0] in (sp.Rational(1, 2), sp.Rational(-1, 2)) for t in terms)
    if halves:
        where = (
            f"{body} sits halfway between the points that carry it (their average), so it moves half as far as they do"
        )
    else:
        where = f"check each length in your {axis} against the figure"
    yield Mistake(f"{base}.doubled", "doubled", f"twice the correct motion: {body} moving as far as the points that "
                  "carry it" if halves else "a component twice the size it should be", None, where, truth + varying)  # fmt: skip
    yield Mistake(f"{base}.halved", "halved", "half the correct motion", None, where, truth - varying / 2)
    yield Mistake(
        f"{base}.sign", "position_sign", "the wrong sign", None, _AXIS_WORDS[a].format(axis), truth - 2 * varying
    )
    if truth.has(sp.sin, sp.cos):
        yield Mistake(f"{base}.sin_cos", "sin_cos", "sin and cos swapped", None, _SWAP_WHY, _swap(truth))
        # one angle's sine and cosine swapped, the others' right (the spherical pendulum's θ in R sin θ cos φ)
        angles = sorted({f.args[0] for f in truth.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
        for x in angles if len(angles) > 1 else ():
            yield Mistake(f"{base}.sin_cos.{_key(x)}", "sin_cos", f"sin and cos of {spoken(x)} swapped", None,
                          _SWAP_WHY, _swap_of(truth, x))  # fmt: skip

    # another component of this body typed in this one's box
    for b, whole in enumerate(positions[i]):
        other = sp.Add(*_moving_terms(whole, moving))
        if b != a and other != 0:
            yield Mistake(
                f"{base}.other_component.{AXES[b]}",
                "position_other",
                f"{body}'s {axes[b]}, not its {axis}",
                None,
                _AXIS_WORDS[a].format(axis),
                other,
            )

    # one term at a time: left out, its sign, sine and cosine swapped in it, another coordinate in it
    if len(terms) > 1:
        for t in terms:
            rates = [q for q in table.q if t.has(q)]
            what = " and ".join(unicode(q.name) for q in rates) or "t"
            yield Mistake(f"{base}.left_out.{_key(t)}", "left_out", f"the part that moves with {what} left out", None,
                          f"{body}'s {axis} changes with {what} through this part too", truth - t)  # fmt: skip
            yield Mistake(f"{base}.term_sign.{_key(t)}", "term_sign", f"the sign of your term {spoken(-t)}", -t,
                          _AXIS_WORDS[a].format(axis), truth - 2 * t)  # fmt: skip
            if t.has(sp.sin, sp.cos):
                swapped = _swap(t)
                yield Mistake(f"{base}.sin_cos.{_key(t)}", "sin_cos", f"sin and cos swapped in your term {spoken(swapped)}",
                              swapped, _SWAP_WHY, truth - t + swapped)  # fmt: skip
    for t in terms:
        for q in table.q:
            if not t.has(q):
                continue
            for other_q in table.q:
                if other_q == q or t.has(other_q):
                    continue
                wrong = t.xreplace({q: other_q})
                yield Mistake(
                    f"{base}.coordinate.{q.name}.{other_q.name}",
                    "position_coordinate",
                    f"{unicode(other_q.name)} where {unicode(q.name)} belongs, in your term {spoken(wrong)}",
                    wrong,
                    f"each part of a position moves with its own coordinate: this part changes with "
                    f"{unicode(q.name)}, not with {unicode(other_q.name)}",
                    truth - t + wrong,
                )


_SWAP_WHY = (
    "the part along the line an angle is measured from takes its cosine, the part across that line its sine: "
    "check which line the figure measures the angle from"
)


def _key(t: sp.Expr) -> str:
    """A term's part of a stable key: its symbols, sorted."""
    return "_".join(sorted(s.name for s in t.free_symbols)) or "constant"
