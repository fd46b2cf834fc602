"""LaTeX to presentation MathML on the server, so a derivation reads as mathematics without JavaScript.

Chromium, Firefox and Safari render MathML Core natively.  With JavaScript on,
KaTeX (static/js/derivation.js) typesets the same TeX, kept in ``data-tex``, over
it.  A formula the converter cannot read stays as its TeX source.

The markup is sanitised before the ``mathml`` filter marks it safe.  latex2mathml
builds an element tree, serialises it and then *unescapes* the result, so a
``\\text{<img src=x onerror=...>}`` came out as a live ``<img>`` element, and
``\\href{javascript:...}`` or ``\\style{...}`` as attributes.  So the tree is taken
from the converter (``convert_to_element``) and rebuilt here: only MathML
elements of the allowlist below, only allowlisted presentation attributes whose
values are plain words, numbers or lengths; any other element becomes an
``<mtext>`` of its text, any other attribute is dropped.  Text is serialised
escaped; only the numeric character references the converter writes for symbols
(``&#x003B8;``) are turned back into references.
"""

from __future__ import annotations

import re
from functools import lru_cache
from xml.etree.ElementTree import Element, SubElement, tostring

from latex2mathml.converter import convert_to_element
from markupsafe import Markup, escape

MATHML_NS = "http://www.w3.org/1998/Math/MathML"
# MathML Core's presentation elements (and the few the converter writes beyond them: menclose, mstyle)
ELEMENTS = frozenset(
    "math mrow mi mn mo ms mtext mspace msub msup msubsup munder mover munderover mfrac msqrt mroot "
    "mtable mtr mtd mstyle mpadded mphantom menclose merror mmultiscripts mprescripts none semantics annotation".split()
)
# presentation attributes; never href, style, class, id or an event handler
ATTRIBUTES = frozenset(
    "display mathvariant mathcolor mathbackground mathsize displaystyle scriptlevel stretchy fence separator "
    "lspace rspace minsize maxsize largeop movablelimits symmetric accent accentunder form linethickness "
    "columnalign rowalign columnspacing rowspacing columnlines rowlines frame framespacing notation width "
    "height depth voffset rowspan columnspan align equalrows equalcolumns side linebreak".split()
)
# an attribute's value: words, numbers, lengths, #colours and lists of them (no quotes, colons, brackets)
_VALUE = re.compile(r"[\w\s.%#+-]{0,80}")
# the character references the converter writes into text (``&#x003B8;``), escaped once by the serialiser
_REFERENCE = re.compile(r"&amp;(#x[0-9A-Fa-f]{1,6};|#[0-9]{1,7};)")


def _clean(source: Element, parent: Element | None) -> Element:
    """A copy of ``source`` holding only allowlisted elements and attributes (under ``parent`` if given)."""
    tag = source.tag if isinstance(source.tag, str) else ""
    if tag not in ELEMENTS:
        # not MathML we allow: its text, shown as text
        text = "".join(source.itertext())
        copy = Element("mtext") if parent is None else SubElement(parent, "mtext")
        copy.text = text
        copy.tail = source.tail
        return copy
    attributes = {"xmlns": MATHML_NS} if tag == "math" else {}
    attributes |= {k: v for k, v in source.attrib.items() if k in ATTRIBUTES and _VALUE.fullmatch(v)}
    copy = Element(tag, attributes) if parent is None else SubElement(parent, tag, attributes)
    copy.text = source.text
    copy.tail = source.tail
    for child in source:
        _clean(child, copy)
    return copy


def sanitised(tree: Element) -> str:
    """The markup of a converter's tree, through the allowlist, with its text escaped."""
    markup = tostring(_clean(tree, None), encoding="unicode")
    return _REFERENCE.sub(r"&\1", markup)


# latex2mathml reads ``aligned`` as plain text (each & shown, each \\ a line break browsers ignore) but ``split``,
# the same rows aligned at & (right, then left), as a table: the MathML is made from the latter
_ALIGNED = re.compile(r"\\(begin|end)\{aligned\}")


@lru_cache(maxsize=4096)
def _convert(tex: str, display: bool) -> str | None:
    try:
        tree = convert_to_element(_ALIGNED.sub(r"\\\1{split}", tex), display="block" if display else "inline")
    except Exception:  # noqa: BLE001 -- any failure of the converter leaves the TeX source readable
        return None
    return sanitised(tree)


def mathml(tex: str, display: bool = False) -> Markup:
    """The sanitised MathML of ``tex`` (escaped TeX when it cannot be converted)."""
    text = str(tex)
    converted = _convert(text, bool(display))
    return Markup(converted) if converted is not None else escape(text)
