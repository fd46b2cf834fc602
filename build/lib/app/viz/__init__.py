"""Figure data for the pages: SVG diagrams, animation specs, expression trees.

Nothing here runs SymPy: the viz layer turns the engine's output (the
derivation JSON and the scene declarations) into data the browser draws.
"""
