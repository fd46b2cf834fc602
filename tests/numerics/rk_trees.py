"""Butcher's rooted trees and the order conditions of a Runge-Kutta tableau, for the tableau tests."""

import numpy as np


def grow(tree: tuple) -> set[tuple]:
    """Every tree with one more node: a leaf added to the root or, recursively, inside one of its subtrees."""
    out = {tuple(sorted((*tree, ())))}
    for i, child in enumerate(tree):
        for bigger in grow(child):
            out.add(tuple(sorted((*tree[:i], bigger, *tree[i + 1 :]))))
    return out


def trees(order: int) -> list[tuple]:
    """The rooted trees with ``order`` nodes, a tree being the sorted tuple of its subtrees (() is a node)."""
    level = {()}
    for _ in range(order - 1):
        level = set().union(*(grow(t) for t in level))
    return sorted(level)


def size(tree: tuple) -> int:
    return 1 + sum(size(c) for c in tree)


def density(tree: tuple) -> int:
    # gamma(t) = |t| prod gamma(t_k)
    return size(tree) * int(np.prod([density(c) for c in tree]))


def stage_weights(tree: tuple, A: np.ndarray) -> np.ndarray:
    # g(t) = prod_k A g(t_k), componentwise; the elementary weight is b . g(t)
    g = np.ones(A.shape[0])
    for child in tree:
        g = g * (A @ stage_weights(child, A))
    return g


def round_off(w: np.ndarray, g: np.ndarray, ulps: float = 50) -> float:
    # what summing w . g in doubles may lose: a few ulps of the largest terms
    return ulps * np.finfo(float).eps * float(np.abs(w) @ np.abs(g))
