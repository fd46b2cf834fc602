"""Rods for a drawing inferred from the particles: a fixed distance is something rigid.

A particle whose distance to the origin, or to another particle, stays the same
whatever the coordinates and time gets a rod to it (to the origin: a rod from a
drawn pivot).  The engine proves such distances on the positions
(``fixed_distances`` of the derivation document, app/engine/derivation/rods.py); a pair it
could not decide is tried numerically here: the squared distance
D = |r_j − r_i|² is evaluated at ``SAMPLES`` seeded random states (coordinates
in [−2, 2], t in [0, 10], parameters at their defaults) and counts as fixed
when every value agrees with the first to ``TOLERANCE`` relative.  Rods found
only this way carry ``check``: the browser confirms them along the run and
drops one whose length changes.  No SymPy runs here.
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from typing import Any

from app.engine.document.model import FixedDistance
from app.engine.document.trees import TreeError, of_text
from app.viz.exprtree import evaluate, leaves

SAMPLES = 12
TOLERANCE = 1e-9
Pair = tuple[int | None, int]  # (None for the origin or a particle's index, a particle's index)


def _position(pos: Sequence[str]) -> list[Any] | None:
    try:
        return [of_text(c) for c in pos]
    except TreeError:
        return None


def _moves(trees: Sequence[Any], moving: set[str]) -> bool:
    return any(leaves(t) & moving for t in trees)


def _numerically_fixed(a: Sequence[Any] | None, b: Sequence[Any], envs: Sequence[dict[str, float]]) -> bool:
    values = []
    for env in envs:
        try:
            ra = [evaluate(t, env) for t in a] if a is not None else [0.0, 0.0, 0.0]
            rb = [evaluate(t, env) for t in b]
        except (ArithmeticError, ValueError, KeyError, RecursionError):
            return False
        if not all(isinstance(v, float) for v in (*ra, *rb)):
            return False  # a complex power: not a real position here
        # D = |r_b - r_a|^2
        values.append(sum((x - y) ** 2 for x, y in zip(rb, ra, strict=True)))
    first = values[0]
    return first > 0 and all(abs(v - first) <= TOLERANCE * max(1.0, first) for v in values)


def rods(
    particles: Sequence[tuple[str, Sequence[str]]],
    coordinates: Sequence[str],
    defaults: Mapping[str, float],
    proven: Sequence[FixedDistance] = (),
) -> list[tuple[int | None, int, bool]]:
    """(from, to, checked numerically) for each rod: from None is the origin (a pivot), else a particle's index."""
    known = {(p.start, p.to) for p in proven}
    positions = [_position(pos) for _, pos in particles]
    moving = {*coordinates, "t"}
    rng = random.Random(20261123)
    envs = []
    for _ in range(SAMPLES):
        env = {name: float(value) for name, value in defaults.items()}
        env.update({q: rng.uniform(-2.0, 2.0) for q in coordinates})
        env["t"] = rng.uniform(0.0, 10.0)
        envs.append(env)
    out: list[tuple[int | None, int, bool]] = []
    for j, b in enumerate(positions):
        if b is None or not _moves(b, moving):
            continue
        for i in (None, *range(j)):
            a = None if i is None else positions[i]
            if i is not None and a is None:
                continue
            if (i, j) in known:
                out.append((i, j, False))
            elif _numerically_fixed(a, b, envs):
                out.append((i, j, True))
    return out


def _squares_of(tree: Any) -> set[str]:
    """Coordinates-or-names inside a base raised to the power 2 somewhere in a tree (a spring's (r - l)**2)."""
    found: set[str] = set()
    if isinstance(tree, list):
        op, *args = tree
        if op == "pow" and len(args) == 2 and args[1] == 2:
            found |= leaves(args[0])
        for a in args:
            found |= _squares_of(a)
    return found


def springs(
    particles: Sequence[tuple[str, Sequence[str]]],
    coordinates: Sequence[str],
    defaults: Mapping[str, float],
    potential: Any,
) -> list[tuple[int, str]]:
    """(particle, coordinate) for each particle whose distance from the origin is a coordinate r that U holds
    squared, as a spring's energy ½ k (r − l)² does: the particle hangs from a pivot at the origin on a spring.

    |r_j|² = r² is checked at the same seeded random states as the rods."""
    if potential is None:
        return []
    squared = _squares_of(potential) & set(coordinates)
    positions = [_position(pos) for _, pos in particles]
    rng = random.Random(20261124)
    envs = []
    for _ in range(SAMPLES):
        env = {name: float(value) for name, value in defaults.items()}
        env.update({q: rng.uniform(0.2, 2.0) for q in coordinates})
        env["t"] = rng.uniform(0.0, 10.0)
        envs.append(env)
    out = []
    for j, b in enumerate(positions):
        if b is None:
            continue
        for q in sorted(squared):
            try:
                same = all(
                    abs(sum(evaluate(t, env) ** 2 for t in b) - env[q] ** 2) <= TOLERANCE * max(1.0, env[q] ** 2)
                    for env in envs
                )
            except (ArithmeticError, ValueError, KeyError, RecursionError, TypeError):
                same = False
            if same:
                out.append((j, q))
                break
    return out
