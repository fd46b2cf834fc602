"""The QR code of a link, drawn here as SVG (segno), so that a lecture slide needs no outside service."""

from __future__ import annotations

import io

import segno


def qr_svg(link: str, title: str) -> bytes:
    """``link`` as a QR code in SVG: black modules on white, the standard quiet zone of four modules, whole
    pixels per module. Error correction is at least M (segno raises it when the symbol has room), so a
    code projected and read from the back of a hall survives some glare. ``title`` is its accessible name."""
    code = segno.make(link, error="m", micro=False)
    out = io.BytesIO()
    code.save(out, kind="svg", scale=8, border=4, dark="#000", light="#fff", title=title, xmldecl=False, svgclass="qr")
    return out.getvalue()
