"""Class codes, secret keys and what the database keeps of them.

A code is what a student types from the projector: ``CODE_LENGTH`` characters
from an alphabet without look-alikes (no 0/O/Q/D, 1/I/L/J, 2/Z, 5/S, 8/B, 6/G,
U/V), so 18^6 ≈ 3.4 × 10^7 codes; a lower-case code, spaces or a dash typed
in the middle are forgiven.  A key is 32 random bytes (URL-safe base64, 43
characters); the database keeps only its SHA-256, so a copy of the database
opens no class.  A key of that strength needs no slow hash: nothing can be
guessed from the digest.

A recovery code is the instructor's way back into a class from another machine: ``RECOVERY_LENGTH``
characters of the same alphabet in groups of four (18^24 ≈ 1.3 × 10^30, about 100 bits), shown once when the
class is created.  The instructor's key of a class with a recovery code is derived from it (an HMAC of the
class code under the recovery code), so the code gives back the very key the first browser holds, while the
database keeps only the SHA-256 of each.

A student's recovery code is the same kind of code, ``STUDENT_RECOVERY_LENGTH`` characters in three groups (about
50 bits: short enough to copy from a phone, and a join's rate limits bound guessing it), shown once at joining;
with the pseudonym it gives the student's record a new key on another device.  The database keeps its SHA-256.
"""

from __future__ import annotations

import base64
import hashlib
import hmac
import secrets

ALPHABET = "ACEFHKMNPRTWXY3479"
CODE_LENGTH = 6
KEY_BYTES = 32
MAX_KEY_LENGTH = 100
# the digest compared when the code names no class: the same work as a real comparison
NO_CLASS_HASH = hashlib.sha256(b"no class has this code").hexdigest()
RECOVERY_LENGTH = 24
RECOVERY_GROUP = 4
STUDENT_RECOVERY_LENGTH = 12  # a student's code: three groups of four, 18^12 ≈ 1.2 × 10^15


def new_code() -> str:
    return "".join(secrets.choice(ALPHABET) for _ in range(CODE_LENGTH))


def normal_code(text: str) -> str | None:
    """The code as stored, from what was typed; None when it cannot be a code."""
    code = "".join(text.split()).replace("-", "").upper()
    if len(code) != CODE_LENGTH or any(c not in ALPHABET for c in code):
        return None
    return code


# the letters and digits a code leaves out, for they are easily confused with another when read off a board
LEFT_OUT = ", ".join(c for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789" if c not in ALPHABET)


def why_not_code(text: str) -> str:
    """Why a text typed as a class code is not one: its length, or the first character a code never holds."""
    code = "".join(text.split()).replace("-", "").upper()
    # one reason, in a student's words: the list of the characters a code leaves out helps nobody at the board
    if len(code) != CODE_LENGTH:
        return f"it has {len(code)} character{'' if len(code) == 1 else 's'}, and a class code has {CODE_LENGTH} letters and digits"
    bad = next((c for c in code if c not in ALPHABET), None)
    if bad is None:
        return "no class has this code"
    return f"“{bad}” is never in a class code, which leaves out the characters easily read as another"


def new_key() -> str:
    return secrets.token_urlsafe(KEY_BYTES)


def digest(key: str) -> str:
    """What the database keeps of a key."""
    return hashlib.sha256(key.encode("utf-8", "surrogatepass")).hexdigest()



def new_recovery_code(length: int = RECOVERY_LENGTH) -> str:
    """A recovery code as shown: groups of four characters joined by dashes (an instructor's six groups, a
    student's three)."""
    raw = "".join(secrets.choice(ALPHABET) for _ in range(length))
    return "-".join(raw[i : i + RECOVERY_GROUP] for i in range(0, length, RECOVERY_GROUP))


def normal_recovery(text: str, length: int = RECOVERY_LENGTH) -> str | None:
    """The recovery code without its dashes and spaces, upper case; None when it cannot be one."""
    code = "".join(text.split()).replace("-", "").upper()
    if len(code) != length or any(c not in ALPHABET for c in code):
        return None
    return code


def why_not_recovery(text: str, length: int = RECOVERY_LENGTH) -> str:
    """Why a text is not a recovery code: its length (a teacher link cut short), or a character no code holds."""
    code = "".join(text.split()).replace("-", "").upper()
    rule = (f"a recovery code has {length} letters and digits in groups of {RECOVERY_GROUP}, "
            f"without the ones easily confused (no {LEFT_OUT})")
    if len(code) < length:
        cut = " (a teacher link cut short, as some mail programs do, misses part of it)" if length == RECOVERY_LENGTH else ""
        return f"this recovery code is incomplete: it has {len(code)} of its {length} letters and digits{cut}; {rule}"
    if len(code) > length:
        return f"this recovery code has {len(code)} letters and digits, and {rule}"
    bad = next((c for c in code if c not in ALPHABET), "?")
    return f"“{bad}” is never in a recovery code: {rule}"


def teacher_key_from(recovery: str, class_code: str) -> str:
    """The instructor's key of a class, from its recovery code (normalised) and its code: HMAC-SHA256."""
    mac = hmac.new(recovery.encode(), b"lagrange teacher key " + class_code.encode(), hashlib.sha256).digest()
    return base64.urlsafe_b64encode(mac).decode().rstrip("=")
