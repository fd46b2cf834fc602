"""Simulations and what is measured from them: runs, their trust, Poincaré sections, modes, the action."""
