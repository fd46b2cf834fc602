"""A warning as a reader sees it: a sentence, with a capital letter and a full stop.

The numerics word their warnings as clauses (so that they can be joined and quoted); every warning the
API serves passes through ``as_sentence`` once, here.
"""

from __future__ import annotations


def as_sentence(text: str) -> str:
    """``the error in θ₁ is about 450 times …`` → ``The error in θ₁ is about 450 times ….``"""
    text = text.strip()
    if not text:
        return text
    return text[0].upper() + text[1:] + ("" if text.endswith((".", "!", "?")) else ".")
