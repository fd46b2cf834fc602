"""Parameters several scene families share, declared once."""

from app.scenes.types import Parameter

GRAVITY = Parameter("g", 9.81, "m/s²", 0.1, 100.0, "gravitational acceleration")
