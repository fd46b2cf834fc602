"""The step checker against a corpus of student answers, and its refusals."""

from __future__ import annotations

import os
import re

import pytest
import sympy as sp

from app.engine.derivation.derive import Derivation, derive
from app.engine.derivation.dimensions import dimension, system_dimensions
from app.engine.display.spoken import spoken
from app.engine.document.notation import MASS_INERTIA, Inertia
from app.engine.parser.parse import parse_expression
from app.engine.tutor.check import STEPS, CheckError, check_answer, exercises, judge, name_kinds, problem
from app.engine.tutor.exercises import exercise_json
from app.engine.tutor.mistake_families import sum_words
from app.engine.tutor.mistakes import (
    CONSTANT_FACTOR_HINT,
    MISSING_FACTOR_HINT,
    OMEGA_HINT,
    POINTERS,
    RULES,
    pointer,
    without_springs,
)
from app.scenes import SCENES
from app.scenes.types import Parameter, System
from tests.engine.check_corpus import CORPUS, TYPICAL, USER_SYSTEMS
from tests.engine.declared import derivation, family_steps, problem_of

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

HINTS = {rule.mistake: rule.hint for rule in RULES}


def expected_hint(step: str, hint: str | None, frequency: str = "ω", inertia: Inertia = MASS_INERTIA) -> str | None:
    if hint is None:
        return None
    kind, _, factor = hint.partition(":")
    if kind == "key":
        return None  # a generated mistake: checked by its key
    if kind == "units":
        return "units"
    if kind == "pointer":
        return pointer(step, frequency, inertia)
    if kind == "omega":
        # the reduced coordinate's inertia by its letter: I_eff for an angle (prof-n 5)
        return OMEGA_HINT.format(w=frequency, i=inertia.unicode)
    if kind == "missing_factor":
        return MISSING_FACTOR_HINT.format(factor=factor)
    if kind == "constant_factor":
        return CONSTANT_FACTOR_HINT.format(factor=factor)
    return HINTS[kind]


@pytest.mark.parametrize(
    ("system", "step", "coordinate", "answer", "verdict", "difference", "hint"),
    CORPUS,
    ids=[f"{c[0]}-{c[1]}-{c[2] or ''}-{i}" for i, c in enumerate(CORPUS)],
)
def test_corpus(system, step, coordinate, answer, verdict, difference, hint):
    d = derivation(system)
    pb = problem_of(system, step, coordinate)
    result = judge(pb, answer)
    assert result["verdict"] == verdict, result
    # a system with no spring is told nothing about springs (mistakes.without_springs)
    fitted = (lambda text: text) if pb.springs else without_springs
    if hint is not None and hint.startswith("key:"):
        assert result["mistake"]["key"] == hint.removeprefix("key:"), result
        assert result["hint"] not in {pointer(s, pb.frequency, pb.inertia) for s in POINTERS}
        # the piece kept for the reveal says what it is, or is not kept where the difference says it all; under
        # the name, nothing of the correct answer
        tex = result["reveal"]["piece"]
        assert tex == "" or tex.startswith(r"\text{"), tex
        assert result["mistake"]["latex"] == "", result["mistake"]
    elif hint in HINTS:
        # a rule's hint, with the system's own reason added where it has one (h ≠ E)
        assert result["hint"].startswith(fitted(HINTS[hint])) and result["mistake"]["key"] == hint, result
    elif hint == "units":
        # terms whose units disagree (θ̈ is 1/s², g sin θ an acceleration) are named as such
        assert result["hint"].startswith("Check the units") and result["mistake"]["key"] == "units.mismatch", result
    else:
        assert result["hint"] == fitted(expected_hint(step, hint, pb.frequency, pb.inertia))
    if difference is None:
        assert result["reveal"] is None
    else:
        # the difference is kept for the step's reveal, never in the verdict's words
        shown = result["reveal"]["difference"]
        names = {**d.table.namespace(), **{s.name: s for s in d.table.qdd}}
        got = parse_expression(shown["sympy"], names)
        want = parse_expression(difference, names)
        assert sp.simplify(got - want) == 0, (shown, difference)
        assert shown["latex"]
    if verdict == "equivalent":
        message = result["message"]
        assert message.startswith("Equivalent:") and ("multiplied by" in message or "plus" in message)
    if verdict == "correct" and step == "equation":
        assert result["message"].startswith("Correct:")


def test_the_corpus_covers_every_scene_both_systems_and_every_common_mistake():
    assert len(CORPUS) >= 40
    assert {c[0] for c in CORPUS} == set(SCENES) | set(USER_SYSTEMS)
    hints = {c[6].partition(":")[0] for c in CORPUS if c[6]} | {"key"}
    common = {
        "missing_half",
        "speed_not_squared",
        "sign_of_u",
        "t_plus_u",
        "force_counted_twice",
        "missing_factor",
        "omega",
        "key",
    }
    assert common <= hints
    assert {c[4] for c in CORPUS} == {"correct", "equivalent", "incorrect"}
    assert {c[1] for c in CORPUS} == set(STEPS)


def test_equivalent_messages_say_how():
    d = derivation("simple-pendulum")
    potential = judge(problem(d, "potential"), "-m*g*R*cos(theta)")
    assert "plus the constant −mgR" in potential["message"] and "zero of height" in potential["message"]
    # the page's own form, the engine's equation divided through by m R², is right, and says so
    equation = judge(problem(d, "equation", "theta"), "theta_ddot + g*sin(theta)/R")
    # (student-e, 5): plainly correct, never "multiplied by 1/(mR²)" as though it were not the equation
    assert equation["verdict"] == "correct" and equation["message"] == "Correct: this is the equation of motion for θ."
    wrong = judge(problem(d, "equation", "theta"), "theta_ddot - g*sin(theta)/R")
    assert "scaling" not in wrong["message"] and "mR²" not in wrong["message"], wrong["message"]
    spherical = judge(
        problem_of("spherical-pendulum", "equation", "phi"),
        "sin(theta)*phi_ddot + 2*cos(theta)*theta_dot*phi_dot",
    )
    assert "depends on the coordinates" in spherical["message"] and "sin θ" in spherical["message"]


def test_an_incorrect_equation_is_compared_at_the_students_scale():
    result = judge(problem_of("simple-pendulum", "equation", "theta"), "theta_ddot - g*sin(theta)/R")
    # compared at the student's scale (the difference shown is theirs), the scale 1/(mR²) never said
    assert "mR²" not in result["message"] and "R" not in result["reveal"]["difference"]["sympy"].split("/")[0]


@pytest.mark.parametrize(
    ("answer", "part"),
    [
        ("m*(R*theta_dot**2/2", "m*(R*theta_d"),  # syntax
        ("m*v**2/2", "v"),  # an unknown name
        ("m*R^2^2*theta_dot**2/2", "R^2^2"),  # read two ways
        ("__import__('os').system('touch /tmp/lagrange-check-ran')", "'"),
        ("theta_dot.__class__", "theta_dot.__class__"),
        ("(lambda x: x)(1)", ":"),
        ("sin.__globals__", "sin.__globals__"),
        ("Symbol(1)", "Symbol"),
        ("9**9**9**9", "9**9**9"),
        ("exp(exp(exp(3)))", "exp(exp(exp(3)))"),
        ("m*R**2*theta_dot**2/2 + t*1e999", "1e999"),
        ("theta_ddot", "theta_ddot"),  # no acceleration in T
    ],
)
def test_refusals_name_the_answer_and_the_offending_part_and_run_nothing(answer, part):
    d = derivation("simple-pendulum")
    with pytest.raises(CheckError) as refused:
        judge(problem(d, "kinetic"), answer)
    assert refused.value.field == "answer"
    assert str(refused.value).startswith("answer: ")
    assert refused.value.part == part
    assert answer[refused.value.start : refused.value.end] == part
    assert not os.path.exists("/tmp/lagrange-check-ran")


def test_refusals_in_pure_python_name_the_steps_rules():
    kinds = name_kinds(("theta",), ("m", "g", "R"), ())
    with pytest.raises(CheckError, match="U depends on positions only") as velocity:
        check_answer("m*g*R*theta_dot", "potential", kinds)
    assert (velocity.value.start, velocity.value.end) == (6, 15)
    with pytest.raises(CheckError, match="what you solve for"):
        check_answer("-g*sin(theta)/R + 0*theta_ddot", "acceleration", kinds)
    # an ω² with θ still in it is read (and judged: not evaluated at the equilibrium); a velocity or t is refused
    check_answer("g*cos(theta)/R", "omega_squared", kinds)
    for typed in ("g/R + 0*theta_dot", "g/R + 0*t"):
        with pytest.raises(CheckError, match="constant"):
            check_answer(typed, "omega_squared", kinds)
    with pytest.raises(CheckError, match="allowed here: R, g, m, t, theta, theta_dot"):
        check_answer("m*x_dot", "kinetic", kinds)


def test_an_unknown_or_inapplicable_step_or_coordinate_lists_the_allowed_ones():
    damped = derivation("damped-pendulum")
    with pytest.raises(
        CheckError, match="the steps are: position, kinetic, potential, lagrangian, momentum, equation"
    ) as e:
        problem(damped, "omega_squared")
    assert e.value.field == "step"
    with pytest.raises(CheckError, match="unknown step 'jerk'"):
        problem(damped, "jerk")
    with pytest.raises(CheckError, match="give one of: theta") as e:
        problem(damped, "momentum")
    assert e.value.field == "coordinate"
    with pytest.raises(CheckError, match="'x' is not a coordinate of this system; the coordinates are: theta"):
        problem(damped, "equation", "x")
    with pytest.raises(CheckError, match="given by its Lagrangian alone"):
        problem_of("spring-rod", "kinetic")
    # a position names its component: the moving ones are listed (a flat figure's y is not)
    with pytest.raises(CheckError, match=r"'y' is not one of this system's moving position components: x, z \(") as e:
        problem(damped, "position", "y")
    assert e.value.field == "coordinate"
    with pytest.raises(CheckError, match="given by its energies, not by its bodies' positions"):
        problem_of("spring-rod", "position", "x")


def test_exercises_follow_the_chapter_and_carry_the_engines_answers():
    d = derivation("spherical-pendulum")
    assert exercises(d) == [
        ("position", "x"),
        ("position", "y"),
        ("position", "z"),
        ("kinetic", None),
        ("potential", None),
        ("lagrangian", None),
        ("momentum", "theta"),
        ("momentum", "phi"),
        ("equation", "theta"),
        ("equation", "phi"),
        ("acceleration", "theta"),
        ("acceleration", "phi"),
        ("hamiltonian", None),
    ]
    doc = exercise_json(derivation("tabletop-spring"))
    last = doc["exercises"][-1]
    assert last["step"] == "omega_squared" and r"\omega^2 = \frac{4 k}{m}" in last["answer"]["latex"]
    assert "p_theta" in last["names"] and doc["symbols"]["theta_dot"] == r"\dot{\theta}"
    for item in doc["exercises"]:
        # the engine's own answer passes its own checker
        assert (
            judge(problem_of("tabletop-spring", item["step"], item["coordinate"]), item["answer"]["sympy"])["verdict"]
            == "correct"
        )


@pytest.mark.parametrize(
    ("system", "step", "coordinate", "answer", "key"),
    TYPICAL,
    ids=[f"{c[0]}-{c[1]}-{c[2] or ''}-{c[4]}" for c in TYPICAL],
)
def test_typical_mistakes_get_their_specific_diagnosis(system, step, coordinate, answer, key):
    result = judge(problem_of(system, step, coordinate), answer)
    assert result["verdict"] == "incorrect", result
    assert result["mistake"] is not None and result["mistake"]["key"] == key, result
    # never only the step's general rule: the hint names this mistake, and a piece typeset says what it is
    assert result["hint"] not in {pointer(s) for s in POINTERS} and result["mistake"]["name"]
    assert result["mistake"]["latex"] == "" or result["mistake"]["latex"].startswith(r"\text{"), result["mistake"]
    assert "**" not in result["hint"] and "*" not in result["mistake"]["name"]


def test_every_scene_and_both_systems_have_three_typical_mistakes():
    counts = {name: sum(c[0] == name for c in TYPICAL) for name in (*SCENES, *USER_SYSTEMS)}
    assert min(counts.values()) >= 3, counts


def test_the_half_lost_in_differentiating_the_square_is_not_a_force_counted_twice():
    result = judge(problem_of("simple-pendulum", "equation", "theta"), "m*R**2*theta_ddot/2 + m*g*R*sin(theta)")
    assert "counted twice" not in result["hint"] and "differentiating the square" in result["hint"]


def student_text(expr: sp.Expr, step: str, d=None) -> str:
    """A mistaken expression as a student would type it: collected, in the API's syntax, at their own scale
    (an equation with the opposite sign, U with its zero moved by a constant energy: a term of U with every
    coordinate at 1, never a bare number, which has no unit)."""
    shown = sp.factor_terms(sp.collect(sp.expand(expr), sorted(expr.free_symbols, key=lambda s: s.name)))
    if step == "equation":
        shown = -shown
    text = sp.sstr(shown)
    if step != "potential" or d is None:
        return text
    known = system_dimensions(d)
    for term in sp.Add.make_args(sp.expand(d.mechanics.U)):
        # a coordinate set to 1 keeps the term's units only where the coordinate is an angle
        constant = term.xreplace({q: sp.Integer(1) for q in d.table.q})
        if constant.free_symbols and dimension(constant, known) == dimension(term, known) is not None:
            return f"{text} + 3*({sp.sstr(constant)})"
    return text


# a term a hint quotes: "swapped in the term X:", "the sign of the term X is wrong" (the catalogue's), "the sign of
# the X term is wrong" (as typed); "one of the terms" where no term of the answer is it alone
QUOTED = re.compile(
    r"(?P<kind>swapped in|the sign of) (?:one of the terms|the term (?P<term>.+?)|the (?P<unsigned>.+?) term)"
    r"(?= is wrong|:)"
    # an angle's sign inside a function, quoted as typed: "has θ₁ + θ₂: the sign of θ₂"
    r"|has (?P<inner>.+?): the sign of "
)
# a stretch's term of the wrong sign, quoted as the student multiplied it out: "has the term +κ x₂, which should be
# −κ x₂ (a stretch is …)", where the catalogue says "has x₁ + x₂ where x₁ − x₂ belongs: the sign of x₂ (a stretch …"
SIGNED = re.compile(r"has the term (?P<signed>[+−].+?), which should be [+−].+? (?=\()")


def typed_terms(typed: str, d: Derivation, kind: str) -> set[str]:
    """Each term of a typed answer, multiplied out, as a hint prints it (a sign's slip quotes it unsigned)."""
    names = {**d.table.namespace(), **{s.name: s for s in d.table.qdd}}
    terms = sp.Add.make_args(sp.expand(parse_expression(typed, names)))
    return {spoken(t) for t in terms} | ({spoken(-t) for t in terms} if kind == "the sign of" else set())


def typed_arguments(typed: str, d: Derivation) -> set[str]:
    """Every function's argument in a typed answer, as a hint prints it (θ₁ + θ₂ of cos(θ₁ + θ₂)), and every sum
    it holds, as a stretch is quoted (x₁ + x₂ + l₀ of k (l₀ + x₁ + x₂))."""
    names = {**d.table.namespace(), **{s.name: s for s in d.table.qdd}}
    found = list(sp.preorder_traversal(parse_expression(typed, names)))
    sums = {sum_words(a, d.table.q) for a in found if isinstance(a, sp.Add)}
    return {spoken(a) for f in found if isinstance(f, sp.Function) for a in f.args} | sums


FAMILY_STEPS = [
    (name, step, coordinate) for name in (*SCENES, *USER_SYSTEMS) for step, coordinate in family_steps(name)
]


@pytest.mark.slow
@pytest.mark.parametrize("name", [*SCENES, *USER_SYSTEMS])
def test_the_family_steps_listed_from_the_declaration_are_the_tutors_exercises(name):
    assert family_steps(name) == [
        e for e in exercises(derivation(name)) if e[0] in ("kinetic", "potential", "equation")
    ]


@pytest.mark.slow
@pytest.mark.parametrize(
    ("system", "step", "coordinate"), FAMILY_STEPS, ids=["-".join(filter(None, c)) for c in FAMILY_STEPS]
)
def test_every_generated_mistake_typed_back_is_named(system, step, coordinate):
    pb = problem_of(system, step, coordinate)
    generated = [(m, hint) for m, hint, _ in pb.mistakes if "." in m.key]
    assert generated or step == "potential"
    for mistake, hint in generated:
        typed = student_text(mistake.expr, step, derivation(system))
        result = judge(pb, typed)
        assert result["verdict"] == "incorrect", (mistake.key, result)
        # the catalogue's own mistake is named, by the catalogue's words
        assert result["mistake"] and result["mistake"]["key"] == mistake.key, (mistake.key, result)
        want = hint if pb.springs else without_springs(hint)
        signed = SIGNED.search(result["hint"])
        if result["hint"] != want and signed and QUOTED.search(want) and QUOTED.search(want)["inner"]:
            theirs = QUOTED.search(want)
            # the same opening and the same reason; the term quoted is one of the student's, with its sign
            assert result["hint"][: signed.start()] == want[: theirs.start()], (result["hint"], want)
            assert result["hint"][signed.end() :] == want[want.index(" (", theirs.end()) + 1 :], (result["hint"], want)
            quoted = signed["signed"][1:]
            assert quoted in typed_terms(typed, derivation(system), "the sign of"), (typed, quoted)
        elif result["hint"] != want:
            # a term is quoted as the student typed it, where the catalogue quotes the engine's piece: the rest of
            # the hint is the catalogue's, and the quoted term is one the student finds in their own answer
            mine, theirs = QUOTED.search(result["hint"]), QUOTED.search(want)
            assert mine and theirs and mine["kind"] == theirs["kind"], (mistake.key, result["hint"], want)
            assert result["hint"][: mine.start()] == want[: theirs.start()], (result["hint"], want)
            assert result["hint"][mine.end() :] == want[theirs.end() :], (result["hint"], want)
            if mine["inner"]:
                # the argument quoted is one the student's answer holds
                assert mine["inner"] in typed_arguments(typed, derivation(system)), (typed, mine["inner"])
            quoted = mine["term"] or mine["unsigned"]
            if quoted:
                assert quoted in typed_terms(typed, derivation(system), mine["kind"]), (typed, quoted)
        if mistake.family in ("other_coordinate", "limit", "bodies_lumped"):
            # another question's right answer, or the whole answer recast (the bodies taken as one): nothing else in
            # it is "right"
            assert result["partial"] is None, (mistake.key, result["partial"])
        elif len(sp.Add.make_args(sp.expand(mistake.expr))) > 1:
            # "everything else is right" only where there is something else
            assert result["partial"]["message"]


def test_the_double_pendulums_missing_velocity_squared_term_is_the_whole_difference():
    d = derivation("double-pendulum")
    # the θ̇₂² term of the θ₁ equation left out, the rest typed as a textbook has it (cos(θ₁ − θ₂))
    result = judge(
        problem(d, "equation", "theta1"),
        "(m1 + m2)*l1**2*theta1_ddot + m2*l1*l2*cos(theta1 - theta2)*theta2_ddot + (m1 + m2)*g*l1*sin(theta1)",
    )
    names = {**d.table.namespace(), **{s.name: s for s in d.table.qdd}}
    shown = parse_expression(result["reveal"]["difference"]["sympy"], names)
    missing = parse_expression("m2*l1*l2*sin(theta1 - theta2)*theta2_dot**2", names)
    # the whole difference is that term (up to scale), nothing about the accelerations
    assert not shown.has(*d.table.qdd) and "ddot" not in result["reveal"]["difference"]["latex"]
    assert sp.simplify(shown / missing).is_number
    assert len(sp.Add.make_args(shown)) == 1
    # and the θ̇₁² term of the θ₂ equation
    result = judge(
        problem(d, "equation", "theta2"),
        "m2*l2**2*theta2_ddot + m2*l1*l2*cos(theta1 - theta2)*theta1_ddot + m2*g*l2*sin(theta2)",
    )
    shown = parse_expression(result["reveal"]["difference"]["sympy"], names)
    assert sp.simplify(shown / parse_expression("l1*l2*m2*sin(theta1 - theta2)*theta1_dot**2", names)).is_number


def test_names_of_pieces_read_as_mathematics_not_code():
    from app.engine.display.spoken import spoken

    names = {**derivation("double-pendulum").table.namespace()}
    expr = parse_expression(
        "m2*l1*l2*sin(theta1 - theta2)*theta2_dot**2 + R**2*sin(theta1)**2", {**names, "R": sp.Symbol("R")}
    )
    text = spoken(expr)
    assert "*" not in text and "theta" not in text and "sin²(θ₁)" in text and "θ̇₂²" in text and "θ₁ − θ₂" in text


def test_an_unmatched_answer_is_compared_part_by_part():
    result = judge(
        problem_of("double-pendulum", "kinetic"), "(m1 + m2)*l1**2*theta1_dot**2/2 + 7*m2*l2**2*theta2_dot**2"
    )
    assert result["mistake"] is None
    assert result["partial"]["differ"] and "the θ̇₁ θ̇₂ terms" in result["partial"]["differ"]
    # two groups that differ are joined as a reader lists them, never run together with a comma
    (agree,), (one, other) = result["partial"]["agree"], result["partial"]["differ"]
    assert (
        result["partial"]["message"] == f"Part by part: {agree} agree with the correct ones; {one} and {other} do not."
    )


def test_a_constant_difference_is_said_with_its_unit_and_what_it_changes():
    # issue 41, item 4: "plus the constant 1" said no unit; where none was declared the sentence says whose
    # units the number is in, and that a constant added to U or L changes nothing in the motion
    from app.engine.tutor.check import _with_unit

    spring = derive(
        System(
            coordinates=("x",),
            parameters=(Parameter("m", 1.0, min=0.0), Parameter("k", 1.0, min=0.0)),
            kinetic="m*x_dot**2/2",
            potential="k*x**2/2",
        )
    )
    potential = judge(problem(spring, "potential"), "k x^2/2 + 1")
    assert potential["verdict"] == "equivalent"
    assert "plus the constant 1 (in the units of U): " in potential["message"]
    assert "a constant added to U changes no force and nothing in the motion" in potential["message"]
    lagrangian = judge(problem(spring, "lagrangian"), "m x'^2/2 - k x^2/2 - 2")
    assert "plus the constant −2 (in the units of L): a constant added to L" in lagrangian["message"]
    assert "changes nothing in the motion" in lagrangian["message"]
    # where the units are declared, a number is written with the step's own: J for U, m for a position
    d = derivation("simple-pendulum")
    assert _with_unit(problem(d, "potential"), sp.Integer(1)) == "1 J"
    assert _with_unit(problem(d, "position", "z"), sp.Rational(1, 2)) == "1/2 m"
    assert _with_unit(problem(d, "potential"), sp.Symbol("m") * sp.Symbol("g") * sp.Symbol("R")) == "mgR"
