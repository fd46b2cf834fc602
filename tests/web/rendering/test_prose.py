"""A symbol's subscript in a sentence is set as <sub>, never typed as an underscore (issue 40, prof-e 2 / prof-f 14, 21, 35).

The rule's home is app/web/rendering/prose.py; static/js/prose.js sets the sentences the browser composes the same way
(tests/browser/test_prose_words.py reads every scene page as the browser shows it).
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest

from app.web.rendering.prose import prose_html

CASES = {
    "a step_size is no symbol": "a step_size is no symbol",
    "U_eff of the remaining coordinate": "U<sub>eff</sub> of the remaining coordinate",
    "its square is U_eff''/m_eff": "its square is U<sub>eff</sub>″/m<sub>eff</sub>",
    "p_x₁ + p_x₂ is conserved": "p<sub>x₁</sub> + p<sub>x₂</sub> is conserved",
    "so dp_X/dt = ∂L/∂X = 0": "so dp<sub>X</sub>/dt = ∂L/∂X = 0",
    "its force on body i is λ ∂𝒞/∂r_i": "its force on body i is λ ∂𝒞/∂r<sub>i</sub>",
    "U_eff′ = m g sin α": "U<sub>eff</sub>′ = m g sin α",
    "Q_θ = −b θ̇ <b>&": "Q<sub>θ</sub> = −b θ̇ &lt;b&gt;&amp;",
    "the bob's angle": "the bob&#39;s angle",
}
JS = Path(__file__).resolve().parents[3] / "static" / "js" / "prose.js"


@pytest.mark.parametrize(("text", "html"), CASES.items())
def test_a_subscript_is_set_and_the_rest_escaped(text, html):
    assert str(prose_html(text)) == html


def test_the_browser_sets_the_same_subscripts():
    # one rule in two languages: the browser's sentences (readouts, legends) read as the server's
    script = (
        f"import('{JS.as_uri()}').then(({{ proseHTML }}) => "
        f"console.log(JSON.stringify({json.dumps(list(CASES))}.map(proseHTML))))"
    )
    out = subprocess.run(["node", "--input-type=module", "-e", script], capture_output=True, text=True, check=True)
    assert json.loads(out.stdout) == list(CASES.values())


def test_a_scene_page_prints_no_underscore_in_its_sentences(client):
    html = client.get("/scenes/tabletop-spring").text
    text = re.sub(r"<math.*?</math>|<script.*?</script>|<code.*?</code>|<[^>]+>", " ", html, flags=re.S)
    found = re.search(r"[A-Za-zΑ-Ωα-ω]_[A-Za-z0-9θφ]", text)
    assert not found, text[found.start() - 300 : found.end() + 50]
    assert "U<sub>eff</sub>" in html and "p<sub>θ</sub>" in html


def test_a_statement_keeps_a_formulas_sign_with_its_term(client):
    # prof-k 12: on a phone the pulley's statement broke after the sign, "Y = −" | "(y₁ + y₂)/2 − c"; the sign is
    # joined to its term by a word joiner and to the "=" before it by a no-break space, a spaced minus still breaks
    html = client.get("/scenes/pulley").text
    statement = re.search(r'<p class="statement">(.*?)</p>', html, flags=re.S).group(1)
    assert "Y =\u00a0−\u2060(y₁ + y₂)/2 − c" in statement
    assert re.search(r"[=<>≈≤≥] −|−[^\s\u2060]", statement) is None, statement


def test_a_verdicts_formulas_are_cut_out_of_its_words_whole():
    # student-l 6, 7: the formulas a verdict lists (longest first) are set as formulas where they stand, never
    # inside a word or a possessive (T's), the rest left as words with their subscripts
    words = "I = M l² in place of a rod's I about its end, M l²/3; T's units (I about the pivot)"
    formulas = [
        {"text": "I = M l²", "latex": "I = M l^{2}"},
        {"text": "M l²/3", "latex": "M l^{2}/3"},
        {"text": "I", "latex": "I"},
        {"text": "T", "latex": "T"},
    ]
    script = (
        f"import('{JS.as_uri()}').then(({{ proseParts }}) => "
        f"console.log(JSON.stringify(proseParts({json.dumps(words)}, {json.dumps(formulas)}))))"
    )
    out = subprocess.run(["node", "--input-type=module", "-e", script], capture_output=True, text=True, check=True)
    assert json.loads(out.stdout) == [
        {"latex": "I = M l^{2}", "text": "I = M l²"},
        {"text": " in place of a rod's "},
        {"latex": "I", "text": "I"},
        {"text": " about its end, "},
        {"latex": "M l^{2}/3", "text": "M l²/3"},
        {"text": "; T's units "},
        # the parenthesis opened against a formula set with it: no line ends on "("
        {"latex": "(I", "text": "(I"},
        {"text": " about the pivot)"},
    ]
