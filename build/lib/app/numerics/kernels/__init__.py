"""Compiled integration loops (numba), one module per family of methods.

Every kernel takes the right-hand side as a first-class function of one fixed
type (``RHS``), so each kernel is compiled once, cached on disk, and reused for
every system; only the small generated right-hand side is compiled per system.
Kernels are resumable: they run at most ``chunk`` steps per call and keep their
state in arrays, so the caller checks the wall clock between chunks.
"""
