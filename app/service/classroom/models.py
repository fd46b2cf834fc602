"""The classes' tables (SQLAlchemy 2 declarative models); their history is in ``migrations/versions``.

A class has a short public ``code`` and an instructor's key kept only as its
SHA-256 (``teacher_hash``); each student a pseudonym and a key kept the same
way.  The assignment is a list of items (a scene, or a system the instructor
declared), each with its steps; a class holds a series of assignments (``ClassAssignmentRow``: a title, an
optional due time, a place in the series), each with its items.  An attempt is one judged answer: who, which
item and step, the verdict, the named mistake when the checker found one, the
answer's text and when, and, when the page sent one, the attempt's id (unique
per student: a retry records nothing new) with the verdict it was answered, and the assignment it was for.
A hint is a step's answer shown to a student ("Show this step"), once per student, assignment and step.
A class's recovery code (shown once at creation) is kept as its SHA-256 only.  A class may ask its students for their
institution login (``login_column``: the header the LMS matches grades by), kept beside the pseudonym.  Its instructor
may close joining and stop answers (``joining_closed_at``, ``answers_stopped_at``), and reopen either.  Times are naive UTC.
"""

from __future__ import annotations

from datetime import datetime

from sqlalchemy import DateTime, ForeignKey, Index, Integer, String, Text, UniqueConstraint
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column


class Base(DeclarativeBase):
    pass


class ClassRow(Base):
    __tablename__ = "classes"

    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    code: Mapped[str] = mapped_column(String(12), unique=True)
    title: Mapped[str] = mapped_column(String(200))
    teacher_hash: Mapped[str] = mapped_column(String(64))
    created_at: Mapped[datetime] = mapped_column(DateTime, index=True)
    # the recovery code's SHA-256 (classes created before migration 0005 have none)
    recovery_hash: Mapped[str | None] = mapped_column(String(64), nullable=True)
    # the header of the institution login students give at joining ("SIS Login ID", "username", "Login"; None: not
    # asked), for the grades to import into an LMS (migration 0008)
    login_column: Mapped[str | None] = mapped_column(String(20), nullable=True)
    # the session's ends, kept until reopened (migration 0009): when the instructor closed joining (no new
    # student; those joined keep working) and when they stopped answers (none recorded; the record kept)
    joining_closed_at: Mapped[datetime | None] = mapped_column(DateTime, nullable=True)
    answers_stopped_at: Mapped[datetime | None] = mapped_column(DateTime, nullable=True)


class ClassAssignmentRow(Base):
    __tablename__ = "class_assignments"
    __table_args__ = (UniqueConstraint("class_id", "position", name="uq_class_assignments_position"),)

    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    class_id: Mapped[int] = mapped_column(ForeignKey("classes.id", ondelete="CASCADE"), index=True)
    position: Mapped[int] = mapped_column(Integer)  # 0, 1, 2, ...: the series' order (its number is position + 1)
    title: Mapped[str] = mapped_column(String(200))
    due: Mapped[datetime | None] = mapped_column(DateTime, nullable=True)


class StudentRow(Base):
    __tablename__ = "students"
    __table_args__ = (
        UniqueConstraint("class_id", "name", name="uq_students_class_name"),
        # one pseudonym per class whatever its case or Unicode form (migration 0010; NULL: a name that joined before
        # the rule beside another equal to it, kept apart)
        Index("uq_students_class_name_key", "class_id", "name_key", unique=True),
    )

    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    class_id: Mapped[int] = mapped_column(ForeignKey("classes.id", ondelete="CASCADE"), index=True)
    name: Mapped[str] = mapped_column(String(40))
    key_hash: Mapped[str] = mapped_column(String(64), unique=True)
    joined_at: Mapped[datetime] = mapped_column(DateTime)
    # the SHA-256 of the student's recovery code (migration 0007; None: joined before, or no code given yet)
    recovery_hash: Mapped[str | None] = mapped_column(String(64), nullable=True)
    # the student's institution login, when their class asks for it (migration 0008)
    login: Mapped[str | None] = mapped_column(String(64), nullable=True)
    # ``store.pseudonym_digest(name)``, unique in the class (migration 0010)
    name_key: Mapped[str | None] = mapped_column(String(64), nullable=True)


class AssignmentRow(Base):
    """One item of an assignment of the series (the table keeps its first name: it held the single assignment)."""

    __tablename__ = "assignments"
    __table_args__ = (UniqueConstraint("assignment_id", "position", name="uq_assignments_assignment_position"),)

    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    class_id: Mapped[int] = mapped_column(ForeignKey("classes.id", ondelete="CASCADE"), index=True)
    assignment_id: Mapped[int] = mapped_column(ForeignKey("class_assignments.id", ondelete="CASCADE"), index=True)
    position: Mapped[int] = mapped_column(Integer)
    item: Mapped[str] = mapped_column(String(40))  # a scene's id, or the name of the instructor's system
    system: Mapped[str | None] = mapped_column(Text, nullable=True)  # the declared system (JSON), for a system
    steps: Mapped[str] = mapped_column(Text)  # JSON: [{"step", "coordinate"}]
    parameters: Mapped[str] = mapped_column(Text)  # JSON: {name: value}
    # a typed system's set-up in the instructor's words (its coordinates, from where, the zero of U); migration 0006
    setup: Mapped[str | None] = mapped_column(Text, nullable=True)


class AttemptRow(Base):
    __tablename__ = "attempts"
    __table_args__ = (UniqueConstraint("student_id", "attempt_id", name="uq_attempts_student_attempt"),)

    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    class_id: Mapped[int] = mapped_column(ForeignKey("classes.id", ondelete="CASCADE"), index=True)
    student_id: Mapped[int] = mapped_column(ForeignKey("students.id", ondelete="CASCADE"), index=True)
    # the assignment of the series it answered (None: practice with nothing assigned, or before migration 0005)
    assignment_id: Mapped[int | None] = mapped_column(ForeignKey("class_assignments.id"), nullable=True, index=True)
    item: Mapped[str] = mapped_column(String(40))
    step: Mapped[str] = mapped_column(String(20))
    coordinate: Mapped[str | None] = mapped_column(String(40), nullable=True)
    verdict: Mapped[str] = mapped_column(String(12))
    mistake: Mapped[str | None] = mapped_column(String(60), nullable=True)  # the tutor's stable key
    mistake_name: Mapped[str | None] = mapped_column(String(200), nullable=True)  # and its display text
    answer: Mapped[str] = mapped_column(Text)
    at: Mapped[datetime] = mapped_column(DateTime)
    # the id the student's page gave this press of Check (a retry sends it again), and the verdict answered
    attempt_id: Mapped[str | None] = mapped_column(String(64), nullable=True)
    response: Mapped[str | None] = mapped_column(Text, nullable=True)


class HintRow(Base):
    """A step's answer shown to a student ("Show this step" on /join): once per student, assignment and step."""

    __tablename__ = "hints"
    __table_args__ = (
        UniqueConstraint("student_id", "assignment_id", "item", "step", "coordinate", name="uq_hints_student_step"),
    )

    id: Mapped[int] = mapped_column(Integer, primary_key=True)
    class_id: Mapped[int] = mapped_column(ForeignKey("classes.id", ondelete="CASCADE"), index=True)
    student_id: Mapped[int] = mapped_column(ForeignKey("students.id", ondelete="CASCADE"), index=True)
    assignment_id: Mapped[int] = mapped_column(ForeignKey("class_assignments.id", ondelete="CASCADE"), index=True)
    item: Mapped[str] = mapped_column(String(40))
    step: Mapped[str] = mapped_column(String(20))
    coordinate: Mapped[str] = mapped_column(String(40))  # "" for a step of no coordinate (a unique key compares it)
    at: Mapped[datetime] = mapped_column(DateTime)
