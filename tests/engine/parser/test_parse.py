"""The expression parser: what it accepts, what it refuses, and where it points."""

import pytest
import sympy as sp

from app.engine.parser.parse import (
    MAX_DEPTH,
    MAX_LENGTH,
    MAX_NODES,
    ExpressionError,
    build,
    check_expression,
    check_name,
    expression_size,
    parse_expression,
    read,
)

NAMES = {n: sp.Symbol(n, real=True) for n in ("x", "x_dot", "y", "m", "g", "t")}
x, x_dot, y, m, g, t = NAMES.values()


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("m*x_dot**2/2 - m*g*x", m * x_dot**2 / 2 - m * g * x),
        ("sin(x)**2 + cos(x)**2", sp.sin(x) ** 2 + sp.cos(x) ** 2),
        ("0.5*m*x_dot**2", sp.Rational(1, 2) * m * x_dot**2),
        ("1e-20*x", x / 10**20),
        ("-(-x)", x),
        ("+x", x),
        ("x**0.5", sp.sqrt(x)),
        ("x**(1/3)", x ** sp.Rational(1, 3)),
        ("exp(-t/m)*Abs(y)", sp.exp(-t / m) * sp.Abs(y)),
        ("pi*x", sp.pi * x),
        ("  m *\n x\t", m * x),
        ("1_000*x", 1000 * x),
        ("((((x))))", x),
        ("sqrt(g/m)", sp.sqrt(g / m)),
        ("10**20*x", 10**20 * x),
        # as students type it (app/engine/parser/typed.py; the corpus is tests/engine/parser/test_parse_typed.py)
        ("x^2", x**2),
        ("(1/2) m x'^2", m * x_dot**2 / 2),
    ],
)
def test_accepts_and_builds_exactly(text, expected):
    assert parse_expression(text, NAMES) == expected


# (text, words the message must contain, the offending part it must name)
REFUSALS = [
    ("sin.__globals__", "attribute", "sin.__globals__"),
    ("x.__class__.__mro__", "attribute", "x.__class__.__mro__"),
    ("__import__", "unknown name", "__import__"),
    ("__import__('os').system('ls')", "quotes", "'"),
    ("(lambda: 0)()", "':'", ":"),
    ("f'{x}'", "not allowed", "{"),
    ('sin("x")', "quotes", '"'),
    ("x^2^3", "could be read as (x^2)^3 or as x^(2^3)", "x^2^3"),
    ("x // 2", "'//'", "x // 2"),
    ("x if y else m", "conditional", "x if y else m"),
    ("x and y", "'and'/'or'", "x and y"),
    ("not x", "signs", "not x"),
    ("x,y", "comma", "x,y"),
    ("sin(x, y)", "one argument", "sin(x, y)"),
    ("sin(*x)", "one argument", "sin(*x)"),
    ("print(x)", "only these functions", "print"),
    ("exp", "function", "exp"),
    ("9**9**9**9", "towers", "9**9**9"),
    ("2**10**10", "towers", "2**10**10"),
    ("x**100", "exponent larger than 64", "x**100"),
    ("x**y", "exponents must be numbers", "x**y"),
    ("1e999999999", "out of range", "1e999999999"),
    ("12345678901234567890*x", "15 digits", "12345678901234567890"),
    ("1e16*x", "out of range", "1e16"),
    ("1j*x", "unknown name", "j"),  # a number side by side with a name j, not Python's imaginary 1j
    ("sin(sin(3+exp(exp(exp(3)))))", "too large", "exp(exp(exp(3)))"),
    ("exp(1000)*x", "too large", "exp(1000)"),
    ("(10**15)**64", "too large", "(10**15)**64"),
    ("sqrt(-1)*x", "not real", "sqrt(-1)"),
    ("log(0)", "undefined", "log(0)"),
    ("asin(2)", "not real", "asin(2)"),
    ("x/0", "division by zero", "x/0"),
    ("x/(1-1)", "division by zero", "x/(1-1)"),
    ("0**-1", "division by zero", "0**-1"),
    ("1/(x-x)", "division by zero", "x-x"),
    ("sqrt(-x**2)", "not real", "sqrt(-x**2)"),
    ("tan(pi/2)*x", "undefined", "tan(pi/2)*x"),
    ("x_ddot", "accelerations", "x_ddot"),
    ("q", "unknown name", "q"),
    ("θ", "unknown name", "θ"),
    ("ｓｉｎ(x)", "you may type Greek letters (θ)", "ｓ"),
    ("x[0]", "not allowed", "["),
    ("x;y", "not allowed", ";"),
    ("x +", "ends with '+' at column 3", "x +"),
    ("", "empty", ""),
    ("(x+y+m+g)**64", "expand into more than", "(x+y+m+g)**64"),
    ("((x+1)**64)**64", "grow too large", "((x+1)**64)**64"),
    ("-" * 60 + "x", f"deeper than {MAX_DEPTH}", "-"),
    ("+".join(["x"] * (MAX_NODES + 1)), "parts", ""),
    ("x" * (MAX_LENGTH + 1), "characters long", ""),
]


@pytest.mark.parametrize(("text", "words", "part"), REFUSALS, ids=[r[0][:30] for r in REFUSALS])
def test_refuses_with_a_message_naming_the_part(text, words, part):
    with pytest.raises(ExpressionError) as caught:
        parse_expression(text, NAMES)
    error = caught.value
    assert words in str(error)
    assert error.part.startswith(part) or part.startswith(error.part.rstrip(".")), (error.part, part)
    if error.start is not None:
        # the span points into the text at the part it names
        assert text[error.start : error.end].startswith(error.part.rstrip(".")[:10])


def test_velocity_refused_where_only_positions_belong():
    positional = {k: v for k, v in NAMES.items() if not k.endswith("_dot")}
    with pytest.raises(ExpressionError, match="velocity is not allowed here"):
        parse_expression("m*x_dot", positional)


def test_check_expression_never_builds_sympy():
    # gate 2 alone runs no SymPy: a name that maps to nothing is fine there
    tree = check_expression("m*x_dot**2/2", {"m", "x_dot"})
    assert tree.body is not None


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("lambda", "keyword"),
        ("sin", "reserved"),
        ("E", "reserved"),
        ("I", "reserved"),
        ("pi", "reserved"),
        ("t", "time"),
        ("sign", "reserved"),
        ("Integral", "reserved"),
        ("xdot", "velocity"),
        ("thetaddot", "velocity"),
        ("x_1", "no underscores"),
        ("1x", "a letter followed by"),
        ("a" * 17, "up to 15"),
        ("θ", "ASCII"),
        ("", "a letter followed by"),
    ],
)
def test_names_are_strict(name, words):
    with pytest.raises(ExpressionError, match=words):
        check_name(name, "parameter")


@pytest.mark.parametrize("name", ["x", "theta", "m1", "omega", "gamma", "dot", "Lz", "k2b"])
def test_good_names_pass(name):
    assert check_name(name) == name


def test_error_survives_a_process_boundary():
    import pickle

    error = ExpressionError("msg", "part", 3, 7)
    copy = pickle.loads(pickle.dumps(error))
    assert (str(copy), copy.part, copy.start, copy.end) == ("msg", "part", 3, 7)


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("m(x+1)", "m is not a function: put a space (or *) between m and the bracket: m (x+1)"),
        ("½m(ẋ₁²+ẋ₂²)", "m is not a function: put a space (or *) between m and the bracket: m (ẋ₁²+ẋ₂²)"),
        ("mR", "letters written together are one name: for a product write m R"),
        ("m*x = 2", "write it as one expression equal to zero, e.g. a - (b) for a = b"),
    ],
)
def test_input_help_says_what_to_write(text, words):
    # factors side by side ("m R**2 theta_dot", "2(x+1)", "sin(x) cos(x)") multiply: tests/engine/parser/test_parse_typed.py
    with pytest.raises(ExpressionError) as e:
        check_expression(text, ["m", "R", "theta_dot", "x"])
    assert words in str(e.value)


def test_a_plain_syntax_error_gets_no_made_up_hint():
    with pytest.raises(ExpressionError) as e:
        check_expression("x +* 2", ["x"])
    assert "between factors" not in str(e.value)


@pytest.mark.parametrize("text", ["m*x_dot**2/2 - m*g*x", "  m *\n x\t", "exp(-t/m)*Abs(y)", "1e-20*x"])
def test_what_is_read_builds_after_pickling_as_parsing_does(text):
    import pickle

    parsed = pickle.loads(pickle.dumps(read(text, set(NAMES))))
    assert parsed.text == text and parsed.size == expression_size(text, set(NAMES))
    assert build(parsed, NAMES) == parse_expression(text, NAMES)


def test_what_is_read_builds_only_over_the_names_it_was_checked_against():
    parsed = read("m*x_dot", set(NAMES))
    positional = {k: v for k, v in NAMES.items() if not k.endswith("_dot")}
    with pytest.raises(ValueError, match="x_dot"):
        build(parsed, positional)


def test_building_refuses_what_only_sympy_finds_with_the_same_message():
    # 1/(x - x) passes gates 1 and 2; gate 3, run on what was read, refuses it as parse_expression does
    parsed = read(" 1/(x - x)", {"x"})
    with pytest.raises(ExpressionError) as built:
        build(parsed, NAMES)
    with pytest.raises(ExpressionError) as parsed_whole:
        parse_expression(" 1/(x - x)", NAMES)
    assert (str(built.value), built.value.start, built.value.end) == (
        str(parsed_whole.value),
        parsed_whole.value.start,
        parsed_whole.value.end,
    )
