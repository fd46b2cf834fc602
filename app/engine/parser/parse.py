"""Turn expression text into SymPy without ever calling ``eval``.

``sympify`` and ``parse_expr`` evaluate Python code, so they are never used on
text.  The text goes through three gates, each refusing with a message that
names the offending part and where it starts:

1. characters: ASCII letters, digits, ``_ . + - * / ( ) ,`` and spaces only,
   and at most ``MAX_LENGTH`` of them (quotes, brackets, colons and the like
   are the raw material of code, strings, lambdas and f-strings);
2. structure (pure Python, no SymPy): Python's ``ast`` tree walked against an
   allowlist of numbers, declared names, ``+ - * / **``, unary signs and calls
   of a fixed set of functions (``FUNCTIONS``, one argument each but
   ``atan2(y, x)``); limits on nesting depth, node
   count, literal size, exponents and nested calls; constant sub-expressions
   folded exactly (``fractions.Fraction``, with caps on digits and on the index
   of a root SymPy would extract) or in floating point, so that
   ``exp(exp(exp(3)))``, ``12**(1 - 1/3**40)`` or ``asin(2)`` are refused
   instead of sending SymPy's automatic evaluation into a hang or a non-real
   value; towers of exponents refused even behind signs; ``exp(c*log(u))``
   bounded as the power ``u**c`` SymPy turns it into; the degree of powers
   once combined bounded; and an upper bound on the number of terms a full
   expansion can produce, of the whole and of every function's argument;
3. construction: the checked tree is built into SymPy, and a result that is
   undefined or not real (``1/(x - x)``, ``sqrt(-x**2)``, ``asin(2 + x - x)``)
   is refused.

``check_expression`` runs gates 1 and 2 only, so a web process can refuse
hostile text without touching SymPy; ``parse_expression`` runs all three.
``read`` (gates 1 and 2) keeps what it read as a picklable ``Parsed`` and
``build`` (gate 3) makes SymPy of it, so that text read in one process is built
in another without being read again (docs/parsing.md).

Before gate 1, gate 0 (``parse_typed``) writes text as students type it (``x^2``, ``2x``, ``m g l``,
``θ'``, ``θ̇``, ``sin θ``) in the grammar of gate 2, keeping the columns of what was typed, and refuses
what could be read two ways (``2^x^2``, ``1/2m``) with both readings.

The parser lives in six modules, one idea each: ``parse_typed`` (gate 0), ``parse_rules`` (the limits, the function allowlist, the
names a user may declare, ``ExpressionError``), ``parse_help`` (what a refused character or a missing ``*``
should have been), ``parse_checker`` (gate 2's walk), ``parse_read`` (gates 1 and 2: ``read`` and
``Parsed``) and ``parse_build`` (gate 3: ``build``).  This module is their one door: import from here.
"""

from __future__ import annotations

from app.engine.parser.build import build, parse_expression, typed_terms
from app.engine.parser.read import Node, Parsed, Size, check_expression, expression_size, narrowed, read
from app.engine.parser.rules import (
    ALLOWED,
    ALLOWED_CHARACTERS,
    ARITY,
    CONSTANTS,
    FUNCTIONS,
    MAX_CALLS,
    MAX_CONSTANT,
    MAX_DEGREE,
    MAX_DEPTH,
    MAX_DIGITS,
    MAX_EXPONENT,
    MAX_LENGTH,
    MAX_LITERAL,
    MAX_NODES,
    MAX_ROOT,
    MAX_TERMS,
    NAME_PATTERN,
    RESERVED,
    Allowed,
    ExpressionError,
    check_name,
)
from app.engine.parser.typed import Typed, typed

__all__ = [
    "ALLOWED",
    "ALLOWED_CHARACTERS",
    "ARITY",
    "CONSTANTS",
    "FUNCTIONS",
    "MAX_CALLS",
    "MAX_CONSTANT",
    "MAX_DEGREE",
    "MAX_DEPTH",
    "MAX_DIGITS",
    "MAX_EXPONENT",
    "MAX_LENGTH",
    "MAX_LITERAL",
    "MAX_NODES",
    "MAX_ROOT",
    "MAX_TERMS",
    "NAME_PATTERN",
    "RESERVED",
    "Allowed",
    "ExpressionError",
    "Node",
    "Parsed",
    "Size",
    "Typed",
    "build",
    "check_expression",
    "check_name",
    "expression_size",
    "narrowed",
    "parse_expression",
    "read",
    "typed",
    "typed_terms",
]
