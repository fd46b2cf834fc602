"""Plain-text (Unicode) labels for symbol names, for SVG text and plot axes.

The names themselves live in ``app.engine.display.names`` (one home for LaTeX, Unicode and
plain forms); this module keeps the short name the viz code uses.
"""

from __future__ import annotations

from app.engine.display.names import unicode as label

__all__ = ["label"]
