"""The QR code of a join link: a standard symbol, whole pixels, the quiet zone, an accessible name."""

import re

import segno

from app.viz.qr import qr_svg


def test_the_symbol_is_the_links_own_with_a_quiet_zone_of_four_modules():
    link = "http://lecture-hall.example.edu:8000/j/ACK3X7"
    svg = qr_svg(link, "QR code of the link").decode()
    symbol = segno.make(link, error="m", micro=False)
    modules = symbol.symbol_size(scale=1, border=0)[0]
    size = (modules + 2 * 4) * 8  # four white modules each side, eight pixels a module
    assert f'width="{size}" height="{size}"' in svg and symbol.error in ("M", "Q", "H")  # at least M
    assert "<title>QR code of the link</title>" in svg and 'fill="#fff"' in svg and 'stroke="#000"' in svg
    assert not re.search(r"https?://(?!www\.w3\.org)", svg.replace(link, ""))  # nothing fetched from elsewhere
