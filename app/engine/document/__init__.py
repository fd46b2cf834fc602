"""The derivation printed: its steps, its notation and the JSON document the API serves."""
