"""The derivation engine: SymPy from a scene's data to every step the chapter teaches."""

from app.engine.algebra import sympy_fixes  # noqa: F401  (a slow path inside SymPy stepped around, before any use)
