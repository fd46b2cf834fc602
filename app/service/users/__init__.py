"""Systems users type in: checked, derived and simulated in the worker pool."""
