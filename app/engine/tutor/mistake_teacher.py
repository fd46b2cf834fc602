"""A named mistake as its teacher reads it: the same name, in the third person.

The tutor names a mistake to the student who made it ("sin and cos swapped in your term m g R sin θ",
"… it moves half as far as you have it"); a dashboard projected in a hall, and the answers file,
speak about the student's answer instead ("sin and cos swapped in the term m g R sin θ",
"… half as far as the answer has it").  The engine's names are the one home of what a mistake is
called; this module only changes who is spoken to, so the two never drift apart.
"""

from __future__ import annotations

import functools
import re

# (the second person, the third) in the order they are tried: the longer phrases before the words they hold
_PERSON = (
    (r"\bas far as you have it\b", "as far as the answer has it"),
    (r"\byou have it\b", "the answer has it"),
    (r"\bone of your terms\b", "one of the terms"),
    (r"\byour earlier step\b", "the earlier step"),
    (r"\byou differentiated\b", "the answer differentiates"),
    (r"\byours\b", "the answer's"),
    (r"\byour\b", "the"),
    (r"\byou\b", "the student"),
)
_RULES = tuple((re.compile(pattern, re.IGNORECASE), words) for pattern, words in _PERSON)


def _same_case(found: str, words: str) -> str:
    """The replacement with the capital the found words had ("Your" → "The")."""
    return words[:1].upper() + words[1:] if found[:1].isupper() else words


def for_teacher(name: str) -> str:
    """A mistake's name (or the tutor's sentence about it) with the student's "your"/"you" put in the third
    person; names already in the third person come back unchanged."""
    for pattern, words in _RULES:
        name = pattern.sub(functools.partial(_replaced, words), name)
    return name


def _replaced(words: str, found: re.Match[str]) -> str:
    return _same_case(found.group(0), words)
