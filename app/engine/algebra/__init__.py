"""SymPy work within bounds: the measure of work, the bounds, simplification, the fast algebra."""
