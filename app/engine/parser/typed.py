"""Gate 0 of the parser (app/engine/parser/parse.py): text as students type it, written in the grammar gate 2 reads.

Students write ``m g l (1 - cos θ)``, ``1/2 m θ'^2`` and ``ẋ²``; gate 2 reads Python's expression syntax over
ASCII names.  ``typed`` rewrites the first into the second, in pure Python, and keeps for every character
it writes the columns of the characters it came from, so every refusal further on points at what the
student typed.  It never evaluates anything and never makes a name the allowlist would not see: what it
writes is read by the same gates as text typed in Python syntax.

The rules (docs/parsing.md, "As students type it"):

* ``^`` is a power, as ``**`` is; superscript digits (``x²``, ``x⁻¹``) too;
* Greek letters are their names (``θ`` is ``theta``, ``λ`` is ``lamda``, ``π`` is ``pi``); a Greek letter
  is one name by itself, so ``ωt`` is ``omega t``; subscript digits and ``_1`` belong to the name
  (``θ₁``, ``θ_1`` and ``theta1`` are one name);
* a prime or a dot over a name is a time derivative: ``θ'``, ``θ̇``, ``thetadot`` and ``theta_dot`` are
  ``theta_dot``; two of them, ``theta_ddot``;
* factors side by side multiply (``2x``, ``m g l``, ``2 sin(θ)``, ``(a + b)(a - b)``); letters written
  together are one name, never split (``theta1``, ``l0`` and ``mgl`` are names); a name directly followed
  by ``(`` is a call, as ``sin(θ)`` is, so a product needs a space: ``m (a + b)``;
* a function applies to one name without parentheses (``sin θ cos θ``), and ``sin^2(θ)`` is ``sin(θ)^2``;
* a quotient is a coefficient where a physicist means one thing: a fraction of two numbers before a spaced
  factor (``1/2 m R^2`` is ½ m R², ``3/4 m l^2``), a quotient by one name before a spaced factor (``-g/R θ``
  is −(g/R) θ, ``k/m x``, as Python reads them), any quotient before spaced function calls (``g/l sin θ`` is
  (g/l) sin θ, ``-g/R sin(θ)``), and nothing else;
* what a reader could take two ways is refused with both readings: a power of a power (``2^x^2``), a
  factor glued to an exponent (``x^2y``), any other factor after a quotient (``1/2m`` and ``g/Rθ`` written
  together, ``p^2/2 m``, where 2m is the textbook's denominator), a function of a factor that is not a name
  (``sin 2θ``, ``cos θ^2``).
"""

from __future__ import annotations

import keyword
import re
import unicodedata
from dataclasses import dataclass, field

from app.engine.parser.hints import character_error, characters_error
from app.engine.parser.rules import ALLOWED_CHARACTERS, FUNCTIONS, TYPED_FUNCTIONS, ExpressionError

# a number as Python writes one (1, 2.5, .5, 1_000, 1e-3: 2e1 is twenty; 2 times a name e1 is 2 e1)
_NUMBER = re.compile(
    r"(?:[0-9](?:_?[0-9])*(?:\.(?:[0-9](?:_?[0-9])*)?)?|\.[0-9](?:_?[0-9])*)(?:[eE][+-]?[0-9](?:_?[0-9])*)?"
)
_SPACES = {9: " ", 10: " ", 13: " "}
_DIGITS = frozenset("0123456789")
_PRIMES = {"'": 1, "\u2032": 1, "\u2019": 1, "\u2033": 2}  # ' ′ ’ (a phone's apostrophe) ″
# combining dot above, combining diaeresis (two dots), and their spacing forms a phone or a copied note may give
# after the letter (θ˙, θ¨)
_DOTS = {"\u0307": 1, "\u0308": 2, "\u02d9": 1, "\u00a8": 2}
_TIMES = {"\u00b7": "*", "\u22c5": "*", "\u2219": "*", "\u00d7": "*", "\u2212": "-", "\u2013": "-", "\u00f7": "/"}
_SUBSCRIPTS = {chr(0x2080 + d): str(d) for d in range(10)}
_SUPERSCRIPTS = {"\u00b9": "1", "\u00b2": "2", "\u00b3": "3", "\u207b": "-"} | {
    chr(0x2070 + d): str(d) for d in (0, 4, 5, 6, 7, 8, 9)
}
_GREEK_EXTRA = {
    "\u03d1": "theta",
    "\u03d5": "phi",
    "\u03f5": "epsilon",
    "\u03d6": "pi",
    "\u00b5": "mu",
    "\u03c2": "sigma",
}
# a name ending in dot or ddot is a velocity or an acceleration (names may not end so: app/engine/parser/rules.py)
_DOTTED = re.compile(r"(?P<base>[A-Za-z][A-Za-z0-9_]*?)_?(?P<dots>d?dot)\Z")
_VELOCITY = re.compile(r"d?dot(?![A-Za-z0-9])")  # θdot: a Greek name's velocity
_SUBSCRIPTED = re.compile(r"(?<=[A-Za-z])_(?=\d+(?:_|\Z))")


def greek(ch: str) -> str | None:
    """The name of a Greek letter (θ: theta, Δ: Delta, λ: lamda, which is not Python's keyword), else None."""
    if ch in _GREEK_EXTRA:
        return _GREEK_EXTRA[ch]
    if not "\u0391" <= ch <= "\u03c9":
        return None
    words = unicodedata.name(ch, "").split()
    if len(words) != 4 or words[:1] != ["GREEK"] or words[2] != "LETTER":
        return None
    name = words[3].lower()
    return name.capitalize() if words[1] == "CAPITAL" else name


@dataclass
class Token:
    """One piece of the text: ``kind`` (num, name, func, word, lp, rp, pow, op, comma, sup, other), what it
    is in the grammar of gate 2, its columns in the text as typed, and whether spaces stand before it."""

    kind: str
    text: str
    start: int
    end: int
    spaced: bool = False
    star: bool = field(default=False)  # a * is put before it (factors side by side)


@dataclass(frozen=True)
class Typed:
    """Text as typed, written in gate 2's grammar: ``text`` (ASCII, no surrounding spaces), and for each of
    its characters the columns ``[start, end)`` of what it came from in the text as typed."""

    given: str
    text: str
    starts: tuple[int, ...]
    ends: tuple[int, ...]

    def span(self, start: int, end: int | None) -> tuple[int, int]:
        """The columns in the text as typed of the characters ``[start, end)`` of ``text``."""
        if not self.text:
            return 0, 0
        start = min(max(start, 0), len(self.text) - 1)
        last = min(max((len(self.text) if end is None else end) - 1, start), len(self.text) - 1)
        return self.starts[start], max(self.ends[last], self.starts[start])


_RAISED = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
_DIGIT_POWER = re.compile(r"\*\*(\d+)")


def prose_powers(text: str) -> str:
    """A reading in prose: a power typed the Python way written as a reader writes it (R**2: R², x**(1/2): x^(1/2))."""
    return _DIGIT_POWER.sub(lambda m: m.group(1).translate(_RAISED), text).replace("**", "^")


def _refuse(
    given: str, start: int, end: int, why: str, readings: tuple[str, ...] = (), advice: str = ""
) -> ExpressionError:
    part = given[start:end]
    shown = part if len(part) <= 60 else part[:57] + "..."
    if readings:
        # a tutor's words: the two readings, and the brackets that choose one (the page marks the part); the
        # readings are prose, so a power typed the Python way is written as a reader writes it (R**2: R²)
        first, second = (prose_powers(r) for r in readings[:2])
        message = f"{why}: {shown!r} could be read as {first} or as {second}; "
        message += advice or "write the one you mean, with its brackets"
        return ExpressionError(message, shown, start, end, readings)
    return ExpressionError(f"{why}: {shown!r} at column {start + 1}", shown, start, end)


def _name(given: str, start: int, end: int, letters: str, dots: int) -> str:
    """A name as gate 2 spells it: thetadot and theta_dot are theta_dot, theta_1 is theta1, plus ``dots``
    time derivatives (primes or dots over it)."""
    letters = _SUBSCRIPTED.sub("", letters)
    found = _DOTTED.match(letters)
    if found and found.group("base"):
        letters = found.group("base")
        dots += 2 if found.group("dots") == "ddot" else 1
    if dots > 2:
        raise _refuse(given, start, end, "a third time derivative never appears in mechanics")
    return letters + ("", "_dot", "_ddot")[dots]


def _word(given: str, i: int) -> tuple[list[Token], int]:
    """The names of a run of letters, digits, underscores, subscripts and dots from column ``i``, with the
    primes after it: a Greek letter starts a name of its own, and so does a Latin letter after a Greek one
    (``ωt``: omega, t) unless an underscore joins them (``p_θ``, ``θ_dot``) or it spells the Greek name's
    velocity (``θdot``)."""
    parts: list[dict] = []  # letters, start, end, dots, and whether a Latin letter would start a new name
    j = i
    while j < len(given):
        ch = given[j]
        decomposed = unicodedata.normalize("NFD", ch) if not ch.isascii() else ch
        dots = 0
        if len(decomposed) > 1 and decomposed[0].isascii() and decomposed[0].isalpha():
            if not all(c in _DOTS for c in decomposed[1:]):
                break
            ch, dots = decomposed[0], sum(_DOTS[c] for c in decomposed[1:])  # ẋ is x with a dot above
        last = parts[-1] if parts else None
        name = greek(ch)
        if ch in _DOTS:
            if last is None:
                break
            last["end"], last["dots"], last["apart"] = j + 1, last["dots"] + _DOTS[ch], True
        elif name is not None:
            if last is not None and last["letters"].endswith("_"):
                last["letters"] += name
                last["end"], last["apart"] = j + 1, True
            else:
                parts.append({"letters": name, "start": j, "end": j + 1, "dots": 0, "apart": True})
        elif ch in _SUBSCRIPTS or (ch.isascii() and (ch.isalnum() or ch == "_")):
            velocity = _VELOCITY.match(given, j)
            if velocity and last is not None and last["apart"] and not last["dots"]:
                # θdot, θddot: the Greek name's velocity or acceleration
                last["letters"] += velocity.group()
                last["end"] = j + len(velocity.group())
                j += len(velocity.group())
                continue
            if last is None or (ch.isalpha() and last["apart"]):
                parts.append(
                    {"letters": _SUBSCRIPTS.get(ch, ch), "start": j, "end": j + 1, "dots": dots, "apart": dots > 0}
                )
            else:
                last["letters"] += _SUBSCRIPTS.get(ch, ch)
                last["end"], last["dots"] = j + 1, last["dots"] + dots
                last["apart"] = (last["apart"] and ch != "_") or dots > 0
        else:
            break
        j += 1
    # primes right after the run belong to its last name
    while j < len(given) and given[j] in _PRIMES and parts:
        parts[-1]["end"], parts[-1]["dots"] = j + 1, parts[-1]["dots"] + _PRIMES[given[j]]
        j += 1
    tokens = []
    for part in parts:
        start, end = part["start"], part["end"]
        if part["letters"][0].isdigit():  # a subscript with nothing to belong to
            raise _refuse(given, start, end, "a subscript belongs to a name")
        name = _name(given, start, end, part["letters"], part["dots"])
        # a function typed as Python spells it (abs) is the allowlist's own (Abs)
        name = TYPED_FUNCTIONS.get(name, name)
        kind = "func" if name in FUNCTIONS else "word" if keyword.iskeyword(name) else "name"
        tokens.append(Token(kind, name, start, end))
    return tokens, j


def fraction(ch: str) -> str:
    """A vulgar fraction written with the keyboard's digits, in brackets (½: (1/2)); "" for any other character."""
    if not unicodedata.decomposition(ch).startswith("<fraction>"):
        return ""
    top, _, bottom = unicodedata.normalize("NFKC", ch).partition("\u2044")
    return f"({top or 1}/{bottom})" if top.isdigit() and bottom.isdigit() else ""


def readable(ch: str) -> bool:
    """Whether a character can stand somewhere in a formula as typed (where it stands is the lexer's to judge)."""
    if ch in ALLOWED_CHARACTERS or ch in "^" or greek(ch) or fraction(ch):
        return True
    if ch in _PRIMES or ch in _DOTS or ch in _TIMES or ch in _SUBSCRIPTS or ch in _SUPERSCRIPTS:
        return True
    # a Latin letter with dots over it (ẋ)
    decomposed = unicodedata.normalize("NFD", ch)
    return (
        len(decomposed) > 1
        and decomposed[0].isascii()
        and decomposed[0].isalpha()
        and all(c in _DOTS for c in decomposed[1:])
    )


def lex(given: str) -> list[Token]:
    """The text's tokens, or a refusal of a character that has no place in an expression (every such character
    at once, so that a phone's user corrects them in one go)."""
    unknown = [i for i, ch in enumerate(given) if not readable(ch)]
    if unknown:
        raise characters_error(given, unknown)
    tokens: list[Token] = []
    i, spaced = 0, False
    while i < len(given):
        ch = given[i]
        if ch == " ":
            i, spaced = i + 1, True
            continue
        number = _NUMBER.match(given, i) if ch in _DIGITS or (ch == "." and given[i + 1 : i + 2] in _DIGITS) else None
        if number:
            found = [Token("num", number.group(), i, number.end())]
            i = number.end()
        elif ch.isalpha() or ch == "_" or ch in _SUBSCRIPTS or (not ch.isascii() and greek(ch)):
            found, i = _word(given, i)
            if not found:
                raise character_error(given, i)
        elif ch in _PRIMES:
            if tokens and not spaced and tokens[-1].kind in ("rp", "num"):
                raise _refuse(given, i, i + 1, "a prime marks the velocity of a name (θ' or x')")
            raise character_error(given, i)
        elif ch in _SUPERSCRIPTS:
            j = i
            while j < len(given) and given[j] in _SUPERSCRIPTS:
                j += 1
            power = "".join(_SUPERSCRIPTS[c] for c in given[i:j])
            if not re.fullmatch(r"-?\d+", power):
                raise _refuse(given, i, j, "a superscript power is a whole number (x² or x⁻¹)")
            found, i = [Token("sup", "**" + power, i, j)], j
        elif given.startswith("**", i) or ch == "^":
            width = 2 if ch == "*" else 1
            found, i = [Token("pow", "**", i, i + width)], i + width
        elif fraction(ch):
            # a vulgar fraction (½ from a phone's keyboard) is the quotient of its digits, in brackets: ½ m is (1/2) m
            found, i = [Token("num", fraction(ch), i, i + 1)], i + 1
        elif ch in _TIMES or ch in "+-*/":
            found, i = [Token("op", _TIMES.get(ch, ch), i, i + 1)], i + 1
        elif ch in "()":
            found, i = [Token("lp" if ch == "(" else "rp", ch, i, i + 1)], i + 1
        elif ch == ",":
            found, i = [Token("comma", ch, i, i + 1)], i + 1
        elif ch in ALLOWED_CHARACTERS:
            found, i = [Token("other", ch, i, i + 1)], i + 1
        else:
            raise character_error(given, i)
        found[0].spaced = spaced
        tokens.extend(found)
        spaced = False
    return tokens


ENDS = ("num", "name", "rp", "sup")  # what a factor can end with
STARTS = ("num", "name", "func", "lp")  # what a factor can start with


def _closing(tokens: list[Token], i: int) -> int:
    """The index of the ")" that closes the "(" at ``i`` (or len(tokens) when none does)."""
    depth = 0
    for j in range(i, len(tokens)):
        depth += {"lp": 1, "rp": -1}.get(tokens[j].kind, 0)
        if depth == 0:
            return j
    return len(tokens)


def _atom(tokens: list[Token], i: int) -> int:
    """The index just past the factor starting at ``i`` (signs, then a number, a name, a call or a bracket),
    without the powers after it."""
    while i < len(tokens) and tokens[i].kind == "op" and tokens[i].text in "+-":
        i += 1
    if i >= len(tokens):
        return i
    if tokens[i].kind == "lp":
        return _closing(tokens, i) + 1
    if tokens[i].kind == "func" and i + 1 < len(tokens) and tokens[i + 1].kind == "lp":
        return _closing(tokens, i + 1) + 1
    return i + 1


def _powered(tokens: list[Token], i: int) -> int:
    """The index just past the factor at ``i`` with its powers (x^2, x², f(x)^(1/2))."""
    j = _atom(tokens, i)
    while j < len(tokens) and tokens[j].kind in ("pow", "sup"):
        j = _atom(tokens, j + 1) if tokens[j].kind == "pow" else j + 1
    return j


def _side_by_side(tokens: list[Token], j: int) -> bool:
    """Whether the tokens at ``j - 1`` and ``j`` are two factors written side by side."""
    if not 0 < j < len(tokens):
        return False
    a, b = tokens[j - 1], tokens[j]
    call = a.kind in ("name", "func") and b.kind == "lp" and not b.spaced
    return a.kind in ENDS and b.kind in STARTS and not call


class _Reader:
    def __init__(self, given: str, tokens: list[Token]):
        self.given, self.tokens = given, tokens

    def typed(self, i: int, j: int) -> str:
        """The text as typed of tokens ``[i, j)`` (a bracket never closed ends at the last token: 1/2( )."""
        j = min(j, len(self.tokens))
        if i >= j:
            return ""
        return self.given[self.tokens[i].start : self.tokens[j - 1].end]

    def ambiguous(self, i: int, j: int, why: str, first: str, second: str, advice: str = "") -> ExpressionError:
        j = min(j, len(self.tokens))
        return _refuse(self.given, self.tokens[i].start, self.tokens[j - 1].end, why, (first, second), advice)

    def functions(self) -> None:
        """``sin θ`` is sin(θ) and ``sin^2(θ)`` is sin(θ)^2; a function followed by more than one name without
        a bracket is refused with both readings (``sin 2θ``: sin(2) θ or sin(2θ)?)."""
        tokens, out, i = self.tokens, [], 0
        while i < len(tokens):
            t = tokens[i]
            if t.kind != "func" or (i + 1 < len(tokens) and tokens[i + 1].kind == "lp"):
                out.append(t)
                i += 1
                continue
            power, k = self._function_power(i)
            if k < len(tokens) and tokens[k].kind == "lp":
                close = _closing(tokens, k)
                out += [t, *tokens[k : close + 1], *power]
                i = close + 1
                continue
            if k >= len(tokens) or tokens[k].kind not in STARTS:
                # nothing it applies to: gate 2 says "sin is a function: write sin(...)"
                out += [t, *power]
                i = k
                continue
            # the factors that follow it: sin θ (one name) is sin(θ); anything more could be read two ways
            end = _powered(tokens, k)
            while _side_by_side(tokens, end) and not tokens[end].spaced:
                end = _powered(tokens, end)
            one = tokens[k].kind == "name" and end == k + 1
            if not one:
                f, head = t.text, self.typed(k, k + 1)
                rest = self.typed(k + 1, end)
                first = (
                    f"{f}({head}){rest}" if rest.startswith(("^", "*", "\u00b2", "\u00b3")) else f"{f}({head}) {rest}"
                )
                if end == k + 1:
                    raise _refuse(
                        self.given, t.start, tokens[k].end, f"a function's argument is written in brackets: {f}({head})"
                    )
                raise self.ambiguous(
                    i, end, "a function without brackets is ambiguous", first, f"{f}({self.typed(k, end)})"
                )
            name = tokens[k]
            out += [
                t,
                Token("lp", "(", name.start, name.start, spaced=name.spaced),
                name,
                Token("rp", ")", name.end, name.end),
                *power,
            ]
            i = k + 1
        self.tokens = out

    def _function_power(self, i: int) -> tuple[list[Token], int]:
        """The power written right after the function at ``i`` (sin^2, sin²) and the index after it."""
        tokens = self.tokens
        if i + 1 < len(tokens) and tokens[i + 1].kind == "sup":
            return [tokens[i + 1]], i + 2
        if i + 1 < len(tokens) and tokens[i + 1].kind == "pow":
            end = _atom(tokens, i + 2)
            exponent = self.typed(i + 2, end)
            if not re.fullmatch(r"[0-9]+", exponent):
                f = tokens[i].text
                inverse = f"; the inverse is a{f}(x)" if f in ("sin", "cos", "tan") else ""
                last = tokens[end - 1].end if end > i + 2 else tokens[i + 1].end
                raise _refuse(
                    self.given,
                    tokens[i].start,
                    last,
                    f"a power of a function is a whole number, written {f}^2(x) or {f}(x)^2{inverse}",
                )
            return tokens[i + 1 : end], end
        return [], i + 1

    def towers(self) -> None:
        """A power of a power written with ^ is refused with both readings: 2^x^2 is (2^x)^2 or 2^(x^2)."""
        tokens = self.tokens
        for i, t in enumerate(tokens):
            if t.kind != "pow":
                continue
            end = _atom(tokens, i + 1)
            if (
                end < len(tokens)
                and tokens[end].kind == "pow"
                and "^" in self.given[t.start : t.end] + self.given[tokens[end].start : tokens[end].end]
            ):
                base = self._base(i)
                last = _atom(tokens, end + 1)
                b, e1, e2 = self.typed(base, i), self.typed(i + 1, end), self.typed(end + 1, last)
                raise self.ambiguous(
                    base, last, "a power of a power is ambiguous", f"({b}^{e1})^{e2}", f"{b}^({e1}^{e2})"
                )
            if end < len(tokens) and _side_by_side(tokens, end) and not tokens[end].spaced:
                base = self._base(i)
                factor = _powered(tokens, end)
                b, e, f = self.typed(base, i), self.typed(i + 1, end), self.typed(end, factor)
                raise self.ambiguous(
                    base, factor, "a factor written against an exponent is ambiguous", f"{b}^{e} {f}", f"{b}^({e} {f})"
                )

    def _base(self, i: int) -> int:
        """The index of the first token of the factor a power at ``i`` raises."""
        j = i - 1
        if j >= 0 and self.tokens[j].kind == "rp":
            depth = 0
            while j >= 0:
                depth += {"rp": 1, "lp": -1}.get(self.tokens[j].kind, 0)
                if depth == 0:
                    break
                j -= 1
            if j > 0 and self.tokens[j - 1].kind in ("func", "name") and not self.tokens[j].spaced:
                j -= 1
        return max(j, 0)

    def quotients(self) -> None:
        """A factor written after a quotient is refused with both readings (1/2m is (1/2) m or 1/(2 m)), unless
        the quotient is a coefficient as a physicist writes one: a fraction of two numbers before a spaced
        factor (1/2 m R^2 is (1/2) m R²), a quotient by one name before a spaced factor (g/R θ is (g/R) θ), or
        any quotient before spaced function calls (g/l sin θ is (g/l) sin θ). A number's denominator after
        another numerator stays refused: p^2/2 m is the textbook's p²/2m as often as (p²/2) m."""
        tokens = self.tokens
        for i, t in enumerate(tokens):
            if t.kind != "op" or t.text != "/":
                continue
            end = _powered(tokens, i + 1)
            if not _side_by_side(tokens, end):
                continue
            factors, last = [], end
            while _side_by_side(tokens, last):
                factors.append(last)
                last = _powered(tokens, last)
            if last > len(tokens):
                continue  # a bracket never closed: gate 2 says so, rather than two readings of half a formula
            first = self._term(i)
            numbers = self._numbers(first, i, end)
            # a coefficient as a textbook prints one, ended by a space: ½ m R², (g/R) θ, (k/m) x, (g/l) sin θ
            coefficient = numbers or self._named(i, end) or all(tokens[k].kind == "func" for k in factors)
            if tokens[end].spaced and coefficient:
                continue
            n, d, f = self.typed(first, i), self.typed(i + 1, end), self.typed(end, last)
            # a coefficient glued to a factor (1/2m, g/Rθ): say how the textbook's ½ m or (g/R) θ is typed
            advice = f"for the first, put a space after {n}/{d}" if numbers or self._named(i, end) else ""
            why = "a factor after a quotient is ambiguous"
            raise self.ambiguous(first, last, why, f"({n}/{d}) {f}", f"{n}/({d} {f})", advice)

    def _numbers(self, first: int, i: int, end: int) -> bool:
        """Whether tokens ``[first, end)`` with the "/" at ``i`` are a fraction of two plain numbers (-3/4)."""
        tokens, k = self.tokens, first
        # the numerator: signs, then one number
        while k < i and tokens[k].kind == "op" and tokens[k].text in "+-":
            k += 1
        return k == i - 1 and tokens[k].kind == "num" and end == i + 2 and tokens[i + 1].kind == "num"

    def _named(self, i: int, end: int) -> bool:
        """Whether the denominator of the "/" at ``i`` (tokens up to ``end``) is one name, perhaps raised to a
        power (g/R, k/m, g/R^2): a space after it ends the quotient, as in Python and in a textbook's (g/R) θ."""
        tokens = self.tokens
        return tokens[i + 1].kind == "name" and all(tokens[k].kind in ("pow", "sup", "num") for k in range(i + 2, end))

    def _term(self, i: int) -> int:
        """The index of the first token of the product a "/" at ``i`` divides."""
        depth, j = 0, i - 1
        while j >= 0:
            t = self.tokens[j]
            depth += {"rp": 1, "lp": -1}.get(t.kind, 0)
            if depth < 0 or (depth == 0 and t.kind == "comma"):
                return j + 1
            if depth == 0 and t.kind == "op" and t.text in "+-" and j > 0 and self.tokens[j - 1].kind in ENDS:
                return j + 1
            j -= 1
        return 0

    def stars(self) -> None:
        """A * between factors written side by side; two numbers side by side are refused."""
        tokens = self.tokens
        for j in range(1, len(tokens)):
            if _side_by_side(tokens, j):
                if tokens[j - 1].kind == "num" and tokens[j].kind == "num":
                    a, b = tokens[j - 1].text, tokens[j].text
                    if b.startswith("("):  # 2½: two and a half, or twice a half?
                        raise _refuse(
                            self.given,
                            tokens[j - 1].start,
                            tokens[j].end,
                            f"a number before a fraction: write {a} + {b[1:-1]} for the sum or {a}*{b} for a product",
                        )
                    raise _refuse(
                        self.given,
                        tokens[j - 1].start,
                        tokens[j].end,
                        f"two numbers side by side: write {a}*{b} for a product or {a}{b} for one number",
                    )
                tokens[j].star = True


def typed(given: str) -> Typed:
    """``given`` in gate 2's grammar, with the columns of each character (tabs and line breaks count as
    spaces, one for one)."""
    given = given.translate(_SPACES)
    reader = _Reader(given, lex(given))
    reader.functions()
    reader.towers()
    reader.quotients()
    reader.stars()
    text: list[str] = []
    starts: list[int] = []
    ends: list[int] = []

    def put(chars: str, start: int, end: int) -> None:
        text.append(chars)
        starts.extend([start] * len(chars))
        ends.extend([end] * len(chars))

    for k, t in enumerate(reader.tokens):
        if t.star:
            put("*", t.start, t.start)
        elif t.spaced and k:
            put(" ", t.start, t.start)
        put(t.text, t.start, t.end)
    return Typed(given, "".join(text), tuple(starts), tuple(ends))
