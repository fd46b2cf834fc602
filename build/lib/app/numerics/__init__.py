"""Numerics: turn the engine's equations into fast, bounded, error-estimated trajectories.

Layers (each imports only from the left): codegen (SymPy to source) -> jit
(source to numba functions) -> system (a Derivation as numeric functions) ->
kernels (compiled integration loops) -> methods (one class per integrator,
rules in the base class) -> choose ("auto") -> estimate (global error) ->
simulate (the whole run with its budget) -> observables (energy, h, conserved
quantities and constraint forces along the trajectory).
"""
