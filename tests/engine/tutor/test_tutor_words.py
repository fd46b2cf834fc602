"""What a student reads names no code (issue 41, item 3): every prompt, names hint, rule, refusal and verdict of
the simple and the double pendulum's steps names a velocity θ̇ and an acceleration θ̈ as a textbook prints them,
and a function as a student types it (abs, never SymPy's Abs); the typed spelling follows once, as "(type …)"."""

from __future__ import annotations

import re
from functools import cache

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.derivation.dimensions import system_dimensions
from app.engine.tutor.answer_sides import read_answer
from app.engine.tutor.check import CheckError, judge, problem
from app.engine.tutor.diagnose import sentence
from app.engine.tutor.exercises import exercise_json
from app.engine.tutor.mistake_families import kinetic_mistakes, potential_mistakes
from app.engine.tutor.mistake_pieces import travelled
from app.scenes import SCENES

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

SCENE_IDS = ("simple-pendulum", "double-pendulum")
# code a student should never read: a name's Python spelling, SymPy's function, Python's power
CODE = re.compile(r"_d?dot|Abs|\*\*")
# the one place a typed spelling may follow a printed name: "θ̈ (type theta_ddot)"
TYPED = re.compile(r"\(type [^()]*\)")

# text a student may type in any box, refused: an unknown name, an unknown function, a bar, ambiguous text, an
# acceleration where none may stand, an acceleration with a wrong left side, a velocity in U
BAD = ("v", "foo(θ)", "|θ|", "ab(θ)", "1/2m", "2^θ^2", "sin 2θ", "θ̈", "R θ̈ = 1", "d/dt(θ')", "θ'", "T - U", "θ(t)")


@cache
def _derivation(scene: str):
    return derive(SCENES[scene].system)


def _page_words(scene: str) -> list[str]:
    """Every sentence the practice page prints from the exercises: titles, notes, names hints, rules."""
    page = exercise_json(_derivation(scene))
    words = list(page["rules"].values())
    for e in page["exercises"]:
        words += [e["title"], e.get("note") or "", ", ".join(e["names_said"]), *e["answer"].get("notes", [])]
        words.append(e.get("acceleration") or "")
    return words


def _refusals(scene: str) -> list[str]:
    out = []
    for e in exercise_json(_derivation(scene))["exercises"]:
        pb = problem(_derivation(scene), e["step"], e["coordinate"], mistakes=False)
        for text in BAD:
            try:
                read_answer(text, e["step"], e["coordinate"], pb.kinds)
            except CheckError as refused:
                out.append(str(refused))
    return out


def _readable(text: str) -> str:
    return TYPED.sub("", text)


@pytest.mark.parametrize("scene", SCENE_IDS)
def test_the_practice_pages_words_name_no_code(scene):
    words = [w for w in _page_words(scene) if w]
    assert words and [w for w in words if CODE.search(_readable(w))] == []
    # the names hint prints θ̇ and says once how it is typed
    assert any("θ̇" in w and "(type theta" in w for w in words)


@pytest.mark.parametrize("scene", SCENE_IDS)
def test_the_refusals_name_no_code(scene):
    said = _refusals(scene)
    assert len(said) > 50  # every box refuses most of the bad inputs
    assert [s for s in said if CODE.search(_readable(s))] == []


def test_the_functions_are_named_as_typed_and_abs_is_read():
    kinds = problem(_derivation("simple-pendulum"), "potential", None, mistakes=False).kinds
    with pytest.raises(CheckError) as refused:
        read_answer("foo(θ)", "potential", None, kinds)
    assert "the functions are abs, acos," in str(refused.value)
    read_answer("m g R abs(cos θ)", "potential", None, kinds)  # abs as a student types it is read
    with pytest.raises(CheckError) as refused:
        read_answer("m g R |cos θ|", "potential", None, kinds)
    assert str(refused.value).endswith("is not allowed: an absolute value |x| is typed abs(x)")


@pytest.mark.parametrize(
    ("step", "coordinate", "answer"),
    [
        ("kinetic", None, "m R^2 θ'^2"),
        ("potential", None, "m g R cos θ"),
        ("lagrangian", None, "1/2 m R^2 θ'^2 - m g R cos θ"),
        ("momentum", "theta", "m R θ'"),
        ("equation", "theta", "θ'' + g/R θ"),
        ("equation", "theta", "θ'' - g/R sin θ"),
        ("acceleration", "theta", "-g/R θ"),
        ("hamiltonian", None, "m R^2 θ'^2 - m g R cos θ"),
        ("position", "x", "R cos θ"),
    ],
)
def test_the_verdicts_name_no_code(step, coordinate, answer):
    pb = problem(_derivation("simple-pendulum"), step, coordinate)
    result = judge(pb, answer)
    assert result["verdict"] == "incorrect", result
    mistake = result.get("mistake") or {}
    said = [result["message"], result.get("hint") or "", mistake.get("name", ""), mistake.get("where", "")]
    said += [(result.get("partial") or {}).get("message", ""), (result.get("follow_up") or {}).get("question", "")]
    assert [s for s in said if CODE.search(_readable(s))] == [], said


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_a_composed_sentence_says_left_out_once(scene):
    # issue 41, 3: "a U that leaves out the ½ of ½ k × stretch² left out of your term k x₂²": the clause composed
    # around a slip of T or U (carried into an equation) and each hint's opening say "left out" once at most
    d = _derivation(scene)
    carried = list(travelled(d, "equation", 0, sp.Integer(0), system_dimensions(d), []))
    own = [*kinetic_mistakes(d), *potential_mistakes(d)]
    said = [sentence(m, "equation") for m in carried] + [sentence(m, "T") for m in own]
    assert carried and said
    assert [s for s in said if len(re.findall(r"left out|leaves out", s)) > 1] == []
    # a slip of U said inside a clause names the term of a U never typed here: "the term", not "your term"
    assert [m.name for m in carried if "your" in m.name and m.family == "travelled"] == []


def test_a_g_is_refused_with_why_only_where_no_height_changes():
    # issue 41, 4: the coupled oscillators' masses move on a horizontal line; the rail's bodies likewise; the
    # pendulum has g, and a system of T and U alone shows no bodies to say why by
    level = problem(derive(SCENES["coupled-oscillators"].system), "potential", None, mistakes=False)
    with pytest.raises(CheckError) as refused:
        read_answer("m g x1", "potential", None, level.kinds, level.absent)
    assert "g is not a name in this problem: the masses move on a horizontal line, so their heights never change " in str(refused.value)
    assert not level.gravity and problem(_derivation("simple-pendulum"), "potential", None, mistakes=False).gravity


def test_an_angle_that_grows_with_time_is_said_rate_first():
    # prof-m 7: the rotating wire's practice feedback read "the bead's position (ρ cos(t ω), ρ sin(t ω), α ρ²)
    # changes along z": SymPy's order; a textbook prints ω t
    d = _derivation("rotating-parabola")
    wheres = [m.where for m in kinetic_mistakes(d) if m.family == "velocity_axis"]
    assert wheres and all("(ρ cos(ω t), ρ sin(ω t), α ρ²)" in w for w in wheres), wheres
    assert [w for w in wheres if "t ω" in w] == []
