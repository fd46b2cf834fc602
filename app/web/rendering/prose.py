"""How a symbol with a subscript is written in running text: U_eff -> U<sub>eff</sub>, p_θ -> p<sub>θ</sub>.

Sentences across the book (a step's reason, a panel's caption, the Symbols table, the errata) are plain
text that names symbols the way a reader types them, with an underscore before the subscript.  A reader
never sees the underscore: the ``prose`` filter escapes the text and sets each such subscript as HTML
``<sub>``, a prime pair '' as ″ and a single ' after a subscript as ′.  static/js/prose.js applies the same
rule to the sentences the browser composes (readouts, legends); tests/web/rendering/test_prose.py holds the two to
the same cases.
"""

from __future__ import annotations

import re

from markupsafe import Markup, escape

# a one-letter stem, not the end of a longer word (step_size is no symbol; the d of dp_X/dt may precede it), Latin or Greek, with a combining dot or hat) and its subscript: letters, Greek letters,
# digits or subscript digits (p_x₁), with its primes (U_eff'' is the second derivative)
_SUBSCRIPTED = re.compile(
    r"(?<![A-Za-z0-9_Α-Ωα-ω]{2})([A-Za-zΑ-Ωα-ω][\u0300-\u036f]?)_([A-Za-z0-9Α-Ωα-ω₀-₉\u0300-\u036f]+)(''|'|″|′)?"
)
_PRIMES = {"''": "″", "'": "′", "″": "″", "′": "′", None: ""}

# a formula's sign stays with what it signs (a phone broke "Y = −" | "(y₁ + y₂)/2 − c"): a minus sign
# written against its term (−(y₁ …), −c) is joined to it by a word joiner, U+2060, and to a relation before it
# ("= −", "< −") by a no-break space; a minus between spaced terms (a − b) breaks as a word would
_SIGNED = re.compile(r"(?:([=<>≈≤≥]) )?−(?=[^\s])")


def prose_html(text: object) -> Markup:
    """``text`` escaped, with every symbol's subscript set as ``<sub>``."""
    if isinstance(text, Markup):
        return text
    if text is None:
        return Markup("")

    # the pieces between subscripts are escaped; a prime is read before escaping would turn ' into &#39;
    text, out, at = str(text), [], 0
    for match in _SUBSCRIPTED.finditer(text):
        stem, sub, prime = match.groups()
        out.append(f"{escape(text[at : match.start()])}{escape(stem)}<sub>{escape(sub)}</sub>{_PRIMES[prime]}")
        at = match.end()
    out.append(str(escape(text[at:])))
    return Markup("".join(out))


def statement_html(text: object) -> Markup:
    """A problem statement as printed (the scene page's one place for it): ``prose_html``, with each formula's
    minus sign kept on the line of the term it signs and of the relation before it."""
    if text is None or isinstance(text, Markup):
        return prose_html(text)
    return prose_html(_SIGNED.sub(lambda m: (f"{m.group(1)}\u00a0" if m.group(1) else "") + "−\u2060", str(text)))
