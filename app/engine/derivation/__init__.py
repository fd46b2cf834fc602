"""The whole derivation of a system (``Derivation``), and what is read from it whole."""
