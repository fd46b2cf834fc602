"""Request and response models of the classes (app/web/api/classes.py).

Shapes only: whether a scene, system, step or parameter exists is checked by
the service (app/service/classroom/assignments.py) with located messages.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import AwareDatetime, BaseModel, ConfigDict, Field, StrictBool, StringConstraints

from app.service.classroom.logins import LoginColumn
from app.service.classroom.setup import MAX_SETUP
from app.service.classroom.store import MAX_ASSIGNMENTS
from app.web.schemas.check import CheckRequest, Step
from app.web.schemas.user import STRICT, Name, SystemSpec

Title = Annotated[str, StringConstraints(strip_whitespace=True, min_length=1, max_length=200, pattern=r"^[^\x00-\x1f\x7f]+$")]
# a set-up is prose of a few lines: line breaks and tabs allowed, no other control character
Setup = Annotated[str, StringConstraints(strip_whitespace=True, max_length=MAX_SETUP, pattern=r"^[^\x00-\x08\x0b-\x1f\x7f]*$")]
Pseudonym = Annotated[str, StringConstraints(strip_whitespace=True, min_length=1, max_length=40, pattern=r"^[^\x00-\x1f\x7f]+$")]
SceneId = Annotated[str, Field(min_length=1, max_length=40, pattern=r"^[a-z0-9_-]+$")]
AttemptId = Annotated[str, Field(min_length=8, max_length=64, pattern=r"^[A-Za-z0-9_-]+$")]
Number = Annotated[int, Field(ge=1, le=MAX_ASSIGNMENTS, description="An assignment's number in the series (1: first).")]


LOGIN_COLUMN = (
    "Ask students for their institution login at joining, under the header the LMS matches grades by: Canvas's "
    "`SIS Login ID`, Moodle's `username`, or `Login`; null (the default): ask for none."
)


class NewClass(BaseModel):
    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"title": "Mechanics II, Tuesday",
                                                                       "login_column": "SIS Login ID"}})
    title: Title
    login_column: LoginColumn | None = Field(None, description=LOGIN_COLUMN)


class LoginSetting(BaseModel):
    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"login_column": "username"}})
    login_column: LoginColumn | None = Field(description=LOGIN_COLUMN)


class LoginSet(BaseModel):
    code: str
    login_column: LoginColumn | None


class SessionSetting(BaseModel):
    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"answers_open": False}})
    joining_open: StrictBool | None = Field(None, description="false: close joining (new students are refused; those "
                                      "joined keep working); true: reopen it; left out: as it is.")
    answers_open: StrictBool | None = Field(None, description="false: stop answers (refused, the record kept); true: take "
                                      "them again; left out: as it is.")


class SessionState(BaseModel):
    code: str
    joining_open: bool
    joining_closed_at: str | None = Field(description="When joining was closed (ISO 8601, UTC); null while open.")
    answers_open: bool
    answers_stopped_at: str | None = Field(description="When answers were stopped (ISO 8601, UTC); null while open.")


class ClassCreated(BaseModel):
    code: str = Field(description="What students type to join: 6 characters without look-alikes.")
    teacher_key: str = Field(description="The instructor's secret (shown once; the server keeps only its hash).")
    recovery_code: str = Field(
        description="Shown once: on another machine, POST /api/classes/{code}/recover with it gives the "
        "instructor's key back (the server keeps only its hash)."
    )
    teacher_link: str = Field(
        description="/teach with the class code and the recovery code in the fragment (never sent to a server): "
        "opened in another browser, it restores the class there."
    )


class RecoverRequest(BaseModel):
    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"recovery_code": "ACEF-HKMN-PRTW-XY34-79AC-EFHK"}})
    recovery_code: str = Field(min_length=1, max_length=60, description="The recovery code shown at creation.")


class Recovered(BaseModel):
    code: str
    title: str
    teacher_key: str = Field(description="The instructor's key of the class, the same as the first browser's.")


class JoinRequest(BaseModel):
    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"name": "Ada"}})
    name: Pseudonym = Field(description="A pseudonym, unique in the class; no account, no e-mail.")
    # bounded here only as a body's size; what a login may be is said by the service (app/service/classroom/logins.py)
    login: str | None = Field(
        None, max_length=1000, description="The student's institution login (at most 64 characters, one line): "
        "required when the class asks for it (`login_column`), refused when it does not."
    )


class RejoinRequest(BaseModel):
    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"name": "Ada", "recovery_code": "ACEF-HKMN-PRTW"}})
    name: Pseudonym = Field(description="The pseudonym the student joined with.")
    recovery_code: str = Field(min_length=1, max_length=40, description="The student's recovery code from joining.")


class StudentCodeRequest(BaseModel):
    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"name": "Ada"}})
    name: Pseudonym = Field(description="The student's pseudonym.")


class StudentCode(BaseModel):
    name: str
    recovery_code: str = Field(description="The student's new recovery code (their old one no longer works).")


class StepRef(BaseModel):
    model_config = ConfigDict(**STRICT)
    step: Step
    coordinate: Name | None = None


class AssignmentItem(BaseModel):
    model_config = ConfigDict(**STRICT)
    scene: SceneId | None = Field(None, description="A scene's id (or give `system` and `name`).")
    system: SystemSpec | None = Field(None, description="A system you declare, as for POST /api/derive.")
    name: Name | None = Field(None, description="The system's name: students check against it by this name.")
    steps: list[StepRef] = Field(
        default_factory=list, max_length=40, description="The steps to practise (a scene: none means all)."
    )
    parameters: dict[Name, float] = Field(default_factory=dict, description="Parameter values to show the class.")
    setup: Setup | None = Field(
        None,
        description="For a system (required there): what each coordinate is, where it is measured from and where "
        "U = 0, shown to the students above the boxes with the system's positions, T and U typeset (`given`), "
        "except what an assigned step asks for.",
    )

    def to_item(self) -> dict[str, Any]:
        return {
            "scene": self.scene,
            "system": self.system.to_spec() if self.system is not None else None,
            "name": self.name,
            "steps": [s.model_dump() for s in self.steps],
            "parameters": self.parameters,
            "setup": self.setup,
        }


class Assignment(BaseModel):
    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={
            "example": {
                "items": [
                    {"scene": "double-pendulum", "steps": [{"step": "kinetic"}, {"step": "potential"}]},
                    {"scene": "simple-pendulum", "parameters": {"g": 9.81, "R": 1.0}},
                ]
            }
        },
    )
    items: list[AssignmentItem] = Field(max_length=20)


class NewAssignment(BaseModel):
    """An assignment of the series: a title, an optional due time, its items (as for the single assignment)."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={
            "example": {
                "title": "Week 3: the pendulum's T, U and equation",
                "due": "2030-12-06T17:00:00Z",
                "items": [{"scene": "simple-pendulum", "steps": [{"step": "kinetic"}, {"step": "potential"}]}],
            }
        },
    )
    title: Title
    due: AwareDatetime | None = Field(
        None, description="When it is due: ISO 8601 with its time zone (e.g. 2030-12-06T17:00:00Z), not past."
    )
    items: list[AssignmentItem] = Field(min_length=1, max_length=20)


class AssignmentView(BaseModel):
    model_config = ConfigDict(extra="allow")
    n: int = Field(description="Its number in the series (1: first); a deleted assignment's later ones move up.")
    title: str
    due: str | None = Field(description="When it is due (ISO 8601, UTC), or null.")
    items: list[dict[str, Any]]


class Assignments(BaseModel):
    code: str
    assignments: list[AssignmentView]


class ShowStep(BaseModel):
    """A step whose answer a student was shown ("Show this step"), recorded as a hint used."""

    model_config = ConfigDict(
        **STRICT, json_schema_extra={"example": {"scene": "simple-pendulum", "step": "kinetic", "assignment": 1}}
    )
    scene: SceneId | None = Field(None, description="The scene's id (or `system`).")
    system: Name | None = Field(None, description="The name of a system the instructor assigned.")
    step: Step
    coordinate: Name | None = None
    assignment: Number | None = Field(None, description="The assignment (else the first holding the step).")


class Shown(BaseModel):
    assignment: int
    step: str
    coordinate: str | None


class Grade(BaseModel):
    assignment: int
    steps: int = Field(description="The assignment's steps.")
    first_try: int = Field(description="Steps whose first answer was right (and not shown before).")
    right: int = Field(description="Steps answered right, at any try.")
    shown: int = Field(description="Steps whose answer the student was shown (Show this step).")
    score: float | None = Field(description="Steps right on their own (not shown before), out of `points` for all "
                                "steps; null when nothing of it was tried and it is not yet due (or has no due time).")


class StudentGrades(BaseModel):
    name: str
    login: str | None = Field(None, description="Their institution login, when the class asks for it.")
    grades: list[Grade]


class Grades(BaseModel):
    points: int = Field(description="What an assignment's score is out of.")
    login_column: str | None = Field(None, description="The header of the institution login the class asks for.")
    assignments: list[dict[str, Any]] = Field(description="The series: `n`, `title`, `due`, `steps`.")
    students: list[StudentGrades]


class ClassCheckRequest(CheckRequest):
    """A student's answer for one step of an item of the class's assignment."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={
            "example": {"scene": "simple-pendulum", "step": "kinetic", "answer": "m*R**2*theta_dot**2/2",
                        "attempt": "k3v9Qx2mTa7Lw0pZ"}
        },
    )
    scene: SceneId | None = Field(None, description="The scene's id (or `system`).")
    system: Name | None = Field(None, description="The name of a system the instructor assigned.")
    assignment: Number | None = Field(None, description="The assignment (else the first holding the step).")
    attempt: AttemptId | None = Field(
        None,
        description="An id the page makes for this press of Check (8-64 letters, digits, `-` or `_`), sent again "
        "with any retry of it: a retry gets the first verdict and records nothing new. Another answer under an "
        "id already used is refused.",
    )


class StepSummary(BaseModel):
    model_config = ConfigDict(extra="allow")
    step: str
    coordinate: str | None
    correct: int = Field(description="Answers judged correct or equivalent.")
    incorrect: int = Field(description="Answers judged wrong.")
    not_read: int = Field(0, description="Answers the checker could not read (\"Not checked\"): never judged.")
    students_done: int = Field(
        description="Students who answered the step right on their own: right, and not shown (\"Show this step\") "
        "before their first right answer (the gradebook's rule)."
    )
    students_shown: int = Field(0, description="Students shown the step before any right answer of theirs.")
    students_right: int = Field(0, description="Students with a correct or equivalent answer (each counted once).")
    students_wrong: int = Field(0, description="Students with a wrong answer and no right one (each counted once).")
    students_equivalent: int = Field(
        0, description="Students with an equivalent answer: U, L or h plus a constant (another zero of U), or an "
        "equation times a factor."
    )
    mistakes: dict[str, int] = Field(
        description="Named mistakes among the incorrect answers, by the tutor's stable key, most common first."
    )
    mistake_names: dict[str, str] = Field(
        default_factory=dict, description="Each named mistake's key in words, as the student was told it."
    )
    stuck: int = Field(
        description="Students who answered the step (an answer not read included) and have no correct answer yet."
    )
    students_stuck: list[str] = Field(description="Their names, in alphabetical order.")


class MistakeTotal(BaseModel):
    key: str = Field(description="The tutor's stable key of the mistake (of its first step, most common first).")
    name: str = Field(description="The mistake in words, as the students were told it (empty when it has none).")
    count: int = Field(description="Incorrect answers with this mistake, over every step and scene.")
    steps: list[dict[str, Any]] = Field(description="Where it was made: `scene` or `system`, step, coordinate, count.")
    students: list[str] = Field(description="The students who made it, in alphabetical order.")
    students_since_right: list[str] = Field(
        [], description="Of them, those who have since answered right every step where they made it, alphabetical."
    )


class AssignmentProgress(BaseModel):
    n: int
    title: str
    due: str | None
    steps: int
    students_done: list[str] = Field(description="Students with every step of it right on their own, alphabetical.")
    students_shown: list[str] = Field(
        default_factory=list, description="Students through every step with one shown at least, alphabetical."
    )
    students_stuck: list[str] = Field(description="Students stuck on one of its steps, alphabetical.")


class Summary(BaseModel):
    students: int
    attempts: int = Field(description="Every answer recorded: right, wrong and not read.")
    assignments: list[AssignmentProgress] = Field(default_factory=list, description="The series, in order.")
    steps: list[StepSummary] = Field(description="Each step: `scene` or `system`, then the counts.")
    mistakes: list[MistakeTotal] = Field(
        description="Each named mistake totalled over steps and scenes (by its words), most common first."
    )


class StudentStep(BaseModel):
    model_config = ConfigDict(extra="allow")
    assignment: int | None = Field(None, description="The assignment's number (null: nothing was assigned).")
    item: str
    step: str
    coordinate: str | None
    attempts: int = Field(description="The student's answers to the step, those not read included.")
    not_read: int = Field(0, description="Of them, answers the checker could not read.")
    done: bool
    shown: bool = Field(False, description="\"Show this step\" pressed before the first right answer (or none).")
    counted: bool = Field(False, description="Right on one's own by the due time: the step counts toward the grade.")
    late: bool = Field(False, description="Right on one's own, but only after the due time: not counted.")
    last: str


class StudentProgress(BaseModel):
    name: str
    login: str | None = Field(None, description="Their institution login, when the class asks for it.")
    joined: str
    attempts: int = Field(description="Every answer the student sent, those not read included.")
    not_read: int = Field(0, description="Of them, answers the checker could not read (never counted wrong).")
    done: int = Field(description="Assigned steps done (all steps done when nothing is assigned).")
    own: int = Field(0, description="Of them, those done on one's own (not shown first).")
    counted: int = Field(0, description="Of those, the ones the grade counts: right on one's own by the due time.")
    shown: int = Field(0, description="Assigned steps shown before any right answer.")
    assigned: int
    steps: list[StudentStep]


class Students(BaseModel):
    students: list[StudentProgress]


class Joined(BaseModel):
    model_config = ConfigDict(extra="allow")
    student_key: str = Field(description="The student's secret: send it as `Authorization: Bearer <key>`.")
    recovery_code: str | None = Field(
        None, description="At joining only, shown once: with the pseudonym, POST …/rejoin opens the record again on "
        "another device (the server keeps only its hash)."
    )
    code: str
    title: str
    name: str
    login_column: str | None = Field(None, description="The header of the institution login the class asks for.")
    login: str | None = Field(None, description="The student's institution login as given at joining (kept on "
                              "another device).")
    assignment: list[dict[str, Any]]


class ClassView(BaseModel):
    model_config = ConfigDict(extra="allow")
    code: str
    title: str
    role: str = Field(description="`instructor` or `student`.")
    assignment: list[dict[str, Any]]
    record: list[dict[str, Any]] | None = Field(
        None, description="A student's own page as they left it, per step answered or shown: `assignment`, `item`, "
        "`step`, `coordinate`, the last `answer` as typed, what it was `answered` (`status` 200 and the verdict as "
        "`body`, or 422 and the refusal of an answer not read; null for one recorded without it) and `shown`."
    )
