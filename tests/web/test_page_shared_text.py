"""What every scene page prints from the shared templates, pinned by the pages served (issue 40, part A)."""

from __future__ import annotations

import html
import re

import pytest

from app.scenes import SCENES

ALL = list(SCENES)


def page(client, scene: str) -> str:
    served = client.get(f"/scenes/{scene}")
    assert served.status_code == 200
    return served.text


def symbols_table(text: str) -> tuple[str, str]:
    """(the Symbols table's markup, the page without it)."""
    start = text.index('<table class="symbols">')
    end = text.index("</table>", start) + len("</table>")
    return text[start:end], text[:start] + text[end:]


def maths(text: str) -> list[str]:
    return re.findall(r"<math\b.*?</math>", text, flags=re.S)


def inner(math: str) -> str:
    """A formula's MathML inside its outer <math><mrow>."""
    body = re.sub(r"^<math[^>]*>|</math>$", "", math)
    return re.sub(r"^<mrow>(.*)</mrow>$", r"\1", body, flags=re.S)


def words(text: str) -> str:
    """The running text a reader sees: no scripts, styles, formulas or markup."""
    text = re.sub(r"<(script|style|math)\b.*?</\1>", " ", text, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", " ", text))


def in_words(letter: str, text: str) -> bool:
    """``letter`` stands alone in the running text; "a" and "A" count only as mathematics (beside an = sign)."""
    for m in re.finditer(re.escape(letter), text):
        before, after = text[max(0, m.start() - 3) : m.start()], text[m.end() : m.end() + 3]
        if re.match(r"[\w\u0300-\u036f]", after[:1] or " ") and not re.match(r"[₀-₉]", after[:1]):
            continue
        if re.search(r"[\w\u0300-\u036f]$", before):
            continue
        if letter in ("a", "A") and "=" not in before + after:
            continue
        return True
    return False


@pytest.mark.parametrize("scene", ALL)
def test_every_symbol_row_names_a_letter_the_page_prints(client, scene):
    table, rest = symbols_table(page(client, scene))
    notation = {r["latex"]: r["unicode"] for r in client.get(f"/api/scenes/{scene}/derivation").json()["notation"]}
    formulas = "".join(inner(m) for m in maths(rest))
    prose = words(rest)
    rows = re.findall(r'<tr><td><span class="math" data-tex="([^"]*)">(.*?)</span></td>', table, flags=re.S)
    assert rows
    missing = [
        tex
        for tex, math in rows
        if inner(math) not in formulas and not in_words(notation[html.unescape(tex)], prose)
    ]
    assert missing == [], f"{scene}: the Symbols table lists {missing}, which the page never prints"


def test_a_planar_pendulum_lists_no_beats_and_no_mode_shape(client):
    table, _ = symbols_table(page(client, "simple-pendulum"))
    assert "displacement the beats start from" not in table and "amplitudes of a normal mode" not in table
    coupled, _ = symbols_table(page(client, "coupled-oscillators"))
    assert "displacement the beats start from" in coupled


def steps_of(text: str) -> list[tuple[str, str, str]]:
    """(title, explanation, formula's LaTeX) of every step on a page, the folded ones too."""
    found = re.findall(
        r'<h3 class="step-title">(.*?)</h3>\s*<p class="explanation">(.*?)</p>.*?data-tex="([^"]*)"', text, flags=re.S
    )
    return [(html.unescape(a), html.unescape(b), html.unescape(c)) for a, b, c in found]


@pytest.mark.parametrize("scene", ALL)
def test_the_word_hamiltonian_names_only_h_of_the_momenta(client, scene):
    text = page(client, scene)
    shown = steps_of(text)
    assert len(shown) > 10
    for title, explanation, tex in shown:
        tex = tex.removeprefix(r"\begin{aligned}").replace("&", "")
        if tex.startswith(r"h = \sum_k p_k"):
            assert "Hamiltonian" not in title and title == "Energy function h"
            assert not explanation.startswith("The Hamiltonian")
        if "Hamiltonian" in title:
            assert tex.startswith("H =")
    prose = words(text)
    assert "the Hamiltonian is conserved" not in prose and "level sets of the Hamiltonian" not in prose
