"""Prose escaped for markdown and LaTeX: nothing typed becomes markup."""

import string

from app.service.export.text import latex_text, markdown_text


def test_markdown_escapes_every_ascii_punctuation_mark_and_keeps_one_line():
    text = "<script>alert(1)</script> [x](javascript:y) $a$ *b* `c`\n# heading | cell"
    escaped = markdown_text(text)
    assert "\n" not in escaped
    for i, char in enumerate(escaped):
        if char in string.punctuation and char != "\\":
            assert escaped[i - 1] == "\\", (char, escaped)
    assert markdown_text("θ̇ = ∂L/∂q") == "θ̇ \\= ∂L\\/∂q"


def test_latex_escapes_specials_and_writes_the_unicode_of_the_prose_as_math():
    assert latex_text("$\\input{/etc/passwd}$ 50% #1 a_b ~^&") == (
        r"\$\textbackslash{}input\{/etc/passwd\}\$ 50\% \#1 a\_b \~{}\^{}\&"
    )
    assert (
        latex_text("d/dt ∂L/∂q̇ − ∂L/∂q = Q") == r"d/dt $\partial$L/$\partial$$\dot{q}$ $-$ $\partial$L/$\partial$q = Q"
    )
    assert latex_text("θ̇ and x₁, sin² + cos² = 1") == r"$\dot{\theta}$ and x$_{1}$, sin$^{2}$ + cos$^{2}$ = 1"
    assert latex_text("Ω, Α, λ, é, 😀") == r"$\Omega$, $A$, $\lambda$, e, ?"
    assert latex_text("a\nb — c") == "a b --- c"
    # the prose's φ is the letter the equations print, \varphi; the closed ϕ stays \phi
    assert latex_text("φ̇ and ϕ") == r"$\dot{\varphi}$ and $\phi$"
