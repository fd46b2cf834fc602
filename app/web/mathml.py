"""LaTeX to presentation MathML on the server, so a derivation reads as mathematics without JavaScript.

Chromium, Firefox and Safari render MathML Core natively.  With JavaScript on,
KaTeX (static/js/derivation.js) typesets the same TeX, kept in ``data-tex``, over
it.  A formula the converter cannot read stays as its TeX source.
"""

from __future__ import annotations

from functools import lru_cache

from latex2mathml.converter import convert
from markupsafe import Markup, escape


@lru_cache(maxsize=4096)
def _convert(tex: str, display: bool) -> str | None:
    try:
        return convert(tex, display="block" if display else "inline")
    except Exception:  # noqa: BLE001 -- any failure of the converter leaves the TeX source readable
        return None


def mathml(tex: str, display: bool = False) -> Markup:
    """The MathML of ``tex`` (escaped TeX when it cannot be converted)."""
    text = str(tex)
    converted = _convert(text, bool(display))
    return Markup(converted) if converted is not None else escape(text)
