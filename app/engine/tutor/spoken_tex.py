"""A formula the tutor's words quote, typeset as it is printed there.

The words of a verdict print a formula in Unicode, in the order the student wrote it ("your term
−m g cos(α) sin(α)/(M + m cos²(α))", "I = M l² in place of …", "ω² = U_eff″/m_eff").  A page sets those words in
a sans-serif face, where a capital I and a small l look the same and U_eff reads as code.  ``latex`` turns such a
quoted formula into LaTeX token by token, keeping its order, its slashes and its parentheses exactly: the page
typesets it (KaTeX, in math italic) where the words quote it.  A text it cannot read as a formula (a word in it,
a sign it does not know) gives None, and the page keeps the words as they are.

``formulas`` lists, for a verdict's words, each formula they quote with its LaTeX: the one home of that list.
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable

from app.engine.display.names import GREEK

# each Greek letter's command (φ as \varphi, as every formula of the book prints it)
_GREEK_TEX = {u: rf"\{'varphi' if n == 'phi' else n}" for n, u in GREEK.items()} | {"ϑ": r"\vartheta", "ϕ": r"\phi"}
_FUNCTIONS = ("arcsin", "arccos", "arctan", "sinh", "cosh", "tanh", "sin", "cos", "tan", "exp", "log", "sqrt", "Abs")
_MARKS = {"\u0307": r"\dot", "\u0308": r"\ddot", "\u0302": r"\hat"}
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_SUBSCRIPTS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
_SIGNS = {"−": "-", "-": "-", "+": "+", "=": "=", "/": "/", "×": r"\times ", "·": r"\cdot ", "≈": r"\approx ",
          "<": "<", ">": ">", "≤": r"\le ", "≥": r"\ge ", "∂": r"\partial ", "½": r"\tfrac{1}{2}", ",": ",\\,"}  # fmt: skip
_PRIMES = {"″": "''", "′": "'", "'": "'"}

_LETTER = r"[A-Za-zΑ-Ωα-ωϑϕ]"
_TOKEN = re.compile(
    rf"(?P<function>(?:{'|'.join(_FUNCTIONS)})(?![A-Za-z]))(?P<fpower>[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+)?"
    # a symbol: one letter, its dot or hat, its subscript (digits, or _ and a word or digits), its primes
    r"|(?P<pi>pi)(?![A-Za-z])"
    rf"|(?P<letter>{_LETTER})(?P<mark>[\u0307\u0308\u0302]?)(?P<sub>[₀-₉]+|_[A-Za-z0-9Α-Ωα-ω]+)?(?P<prime>''|[″′'])?"
    r"|(?P<number>\d+(?:\.\d+)?)"
    r"|(?P<power>[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+)"
    r"|(?P<caret>\^(?:\((?P<cgroup>[^()]+)\)|(?P<cone>[0-9A-Za-z]+)))"
    r"|(?P<open>\()|(?P<close>\))"
    rf"|(?P<sign>[{re.escape(''.join(_SIGNS))}])"
    r"|(?P<space>\s+)"
)


def latex(text: str) -> str | None:
    """The LaTeX of a formula printed in Unicode, in its own order (−m g cos(α)/R → -m g \\cos(\\alpha)/R), or None
    where the text is not one formula (a word of prose in it, or a character no formula prints)."""
    # a dotted letter printed as one character (ẏ, Ẋ) read as the letter and its dot
    text = unicodedata.normalize("NFD", text)
    out: list[str] = []
    closers: list[str] = []  # what each open parenthesis closes with: ")" or "}" (a square root's argument)
    at = 0
    while at < len(text):
        m = _TOKEN.match(text, at)
        if m is None or m.end() == at:
            return None
        at = m.end()
        kind = m.lastgroup if m.group("function") is None else "function"
        if kind == "function":
            name = m.group("function")
            if name in ("sqrt", "Abs"):
                # √(…) and |…| take their argument whole: the parenthesis that follows must open it
                if not text.startswith("(", at):
                    return None
                at += 1
                out.append(r"\sqrt{" if name == "sqrt" else r"\left|")
                closers.append("}" if name == "sqrt" else r"\right|")
                continue
            out.append(rf"\{name}" if name in ("sin", "cos", "tan", "sinh", "cosh", "tanh", "exp", "log") else
                       rf"\operatorname{{{name}}}")  # fmt: skip
            if m.group("fpower"):
                out.append(f"^{{{m.group('fpower').translate(_SUPERSCRIPTS)}}}")
            out.append(" ")
        elif m.group("letter") is not None:
            if _is_word(text, m):
                return None
            base = _GREEK_TEX.get(m.group("letter"), m.group("letter"))
            mark = m.group("mark")
            symbol = f"{_MARKS[mark]}{{{base}}}" if mark else base
            sub = m.group("sub")
            if sub:
                sub = sub[1:] if sub.startswith("_") else sub.translate(_SUBSCRIPTS)
                # a word as a subscript is upright (U_eff: "eff" names, it is no product e f f)
                shown = rf"\text{{{sub}}}" if len(sub) > 1 and sub.isalpha() and sub.isascii() else _greek(sub)
                symbol += f"_{{{shown}}}"
            if m.group("prime"):
                symbol += _PRIMES[m.group("prime")]
            out.append(symbol + " ")
        elif kind == "pi":
            out.append(r"\pi ")
        elif kind == "number":
            out.append(m.group("number"))
        elif kind == "power":
            out.append(f"^{{{m.group('power').translate(_SUPERSCRIPTS)}}}")
        elif kind == "caret":
            out.append(f"^{{{m.group('cgroup') or m.group('cone')}}}")
        elif kind == "open":
            out.append("(")
            closers.append(")")
        elif kind == "close":
            if not closers:
                return None
            out.append(closers.pop())
        elif kind == "sign":
            out.append(_SIGNS[m.group("sign")])
        else:  # a space: a product, which a formula sets by juxtaposition
            out.append(" ")
    if closers:
        return None
    return re.sub(r" +", " ", "".join(out)).strip()


def _greek(sub: str) -> str:
    return "".join(_GREEK_TEX.get(c, c) for c in sub)


def _is_word(text: str, m: re.Match[str]) -> bool:
    """Whether a letter is the start of a word of prose (two Latin letters run together: "in", "at"), which no
    formula the words print has: its symbols stand apart (m g R, never mgR)."""
    after = text[m.end() : m.end() + 1]
    return bool(after) and after.isascii() and after.isalpha() and m.group("sub") is None


# what makes a run of symbols a formula worth setting as one (a sign, a power, an index, a dot, a Greek letter, a
# function of something), where a lone letter of the words (the x of the bob, your T) is a symbol all the same
_MATHS = re.compile(r"[⁰¹²³⁴⁵⁶⁷⁸⁹₀-₉\u0300-\u036fΑ-Ωα-ω=/½_″′+−×·∂]|\b(?:sin|cos|tan|exp|log|sqrt)\(")
_ENDS = ".,;:!?"
# a unit, printed upright by its own rule, is no formula of symbols: m/s², 1/s², J·s
_UNIT = re.compile(r"^[(]?[0-9./·⁰¹²³⁴⁵⁶⁷⁸⁹⁻ ]*(?:(?:kg|[msJNW])[0-9./·⁰¹²³⁴⁵⁶⁷⁸⁹⁻ ]*)*[)]?$")


def spans(words: str) -> list[str]:
    """The formulas a sentence prints, each as it stands there: runs of whole space-separated pieces that read as
    one formula ("I = M l²", "(x₁ − x₂) κ", "ω² = U_eff″/m_eff") and a lone symbol (the T of "your T"); a piece
    glued to a word (rod's, kg·m/s², z-component) is words, and so is the article a."""
    out: list[str] = []
    run: list[str] = []

    def close() -> None:
        text = " ".join(run)
        # a parenthesis the run does not close belongs to the words around it ("(at θ = 0)")
        while text and (text.count("(") > text.count(")") and text[0] == "(" or text[-1:] in "+−=/×·" + _ENDS):
            text = text[1:] if text[0] == "(" and text.count("(") > text.count(")") else text[:-1].rstrip()
        while text.endswith(")") and text.count(")") > text.count("("):
            text = text[:-1]
        run.clear()
        if text and not (_UNIT.match(text) and "s" in text) and (len(text) == 1 and text.isalpha() or " " in text or _MATHS.search(
                unicodedata.normalize("NFD", text))) and latex(text) is not None:  # fmt: skip
            out.append(text)

    for piece in words.split():
        core = piece.rstrip(_ENDS)
        bare = core.replace("(", "").replace(")", "")
        # (a possessive, your T's, is words: T′s is no formula)
        # (and the article a is a word, never a symbol glued to the formula before it: "m g R a product")
        if bare and bare not in ("a", "A") and "'s" not in bare and latex(bare) is not None:
            run.append(core)
            if core != piece:  # a full stop or a comma ends the formula
                close()
        else:
            close()
    close()
    return out


def formulas(words: Iterable[str | None]) -> list[dict[str, str]]:
    """Each formula the ``words`` of a verdict print, once, with its LaTeX (the longest first, so that a page sets
    "I = M l²" whole before the "M" it also holds)."""
    found = {t for w in words if w for t in spans(w)}
    return [{"text": t, "latex": latex(t) or ""} for t in sorted(found, key=lambda t: (-len(t), t))]
