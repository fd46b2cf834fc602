"""A series of assignments (each with a title and an optional due time), the hints shown, and the class's recovery
code: a class's single assignment becomes the first of its series, with its attempts.

Revision ID: 0005
Revises: 0004
"""

import sqlalchemy as sa
from alembic import op

revision = "0005"
down_revision = "0004"
branch_labels = None
depends_on = None

FIRST_TITLE = "Assignment 1"  # the title the single assignment of a class from before this revision takes


def upgrade() -> None:
    with op.batch_alter_table("classes") as batch:
        batch.add_column(sa.Column("recovery_hash", sa.String(64), nullable=True))
    op.create_table(
        "class_assignments",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("class_id", sa.Integer, sa.ForeignKey("classes.id", ondelete="CASCADE"), nullable=False, index=True),
        sa.Column("position", sa.Integer, nullable=False),
        sa.Column("title", sa.String(200), nullable=False),
        sa.Column("due", sa.DateTime, nullable=True),
        sa.UniqueConstraint("class_id", "position", name="uq_class_assignments_position"),
    )
    bind = op.get_bind()
    # every class with an assignment: that assignment is the first of its series
    bind.execute(sa.text(
        "INSERT INTO class_assignments (class_id, position, title) "
        "SELECT DISTINCT class_id, 0, :title FROM assignments"
    ), {"title": FIRST_TITLE})
    with op.batch_alter_table("assignments") as batch:
        batch.add_column(sa.Column("assignment_id", sa.Integer, nullable=True))
    bind.execute(sa.text(
        "UPDATE assignments SET assignment_id = (SELECT ca.id FROM class_assignments ca "
        "WHERE ca.class_id = assignments.class_id AND ca.position = 0)"
    ))
    with op.batch_alter_table("assignments") as batch:
        batch.alter_column("assignment_id", existing_type=sa.Integer, nullable=False)
        batch.drop_constraint("uq_assignments_class_position", type_="unique")
        batch.create_unique_constraint("uq_assignments_assignment_position", ["assignment_id", "position"])
        batch.create_foreign_key("fk_assignments_assignment", "class_assignments", ["assignment_id"], ["id"],
                                 ondelete="CASCADE")
        batch.create_index("ix_assignments_assignment_id", ["assignment_id"])
    with op.batch_alter_table("attempts") as batch:
        batch.add_column(sa.Column("assignment_id", sa.Integer, nullable=True))
        batch.create_foreign_key("fk_attempts_assignment", "class_assignments", ["assignment_id"], ["id"])
        batch.create_index("ix_attempts_assignment_id", ["assignment_id"])
    # the attempts at an item of the class's assignment answered it; others (free practice before it) stay None
    bind.execute(sa.text(
        "UPDATE attempts SET assignment_id = (SELECT ca.id FROM class_assignments ca "
        "WHERE ca.class_id = attempts.class_id AND ca.position = 0) "
        "WHERE EXISTS (SELECT 1 FROM assignments a WHERE a.class_id = attempts.class_id AND a.item = attempts.item)"
    ))
    op.create_table(
        "hints",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("class_id", sa.Integer, sa.ForeignKey("classes.id", ondelete="CASCADE"), nullable=False, index=True),
        sa.Column("student_id", sa.Integer, sa.ForeignKey("students.id", ondelete="CASCADE"), nullable=False,
                  index=True),
        sa.Column("assignment_id", sa.Integer, sa.ForeignKey("class_assignments.id", ondelete="CASCADE"),
                  nullable=False, index=True),
        sa.Column("item", sa.String(40), nullable=False),
        sa.Column("step", sa.String(20), nullable=False),
        sa.Column("coordinate", sa.String(40), nullable=False),
        sa.Column("at", sa.DateTime, nullable=False),
        sa.UniqueConstraint("student_id", "assignment_id", "item", "step", "coordinate", name="uq_hints_student_step"),
    )


def downgrade() -> None:
    op.drop_table("hints")
    with op.batch_alter_table("attempts") as batch:
        batch.drop_index("ix_attempts_assignment_id")
        batch.drop_constraint("fk_attempts_assignment", type_="foreignkey")
        batch.drop_column("assignment_id")
    bind = op.get_bind()
    # only the first assignment of each series survives as the class's single assignment
    bind.execute(sa.text(
        "DELETE FROM assignments WHERE assignment_id NOT IN "
        "(SELECT id FROM class_assignments WHERE position = 0)"
    ))
    with op.batch_alter_table("assignments") as batch:
        batch.drop_index("ix_assignments_assignment_id")
        batch.drop_constraint("fk_assignments_assignment", type_="foreignkey")
        batch.drop_constraint("uq_assignments_assignment_position", type_="unique")
        batch.create_unique_constraint("uq_assignments_class_position", ["class_id", "position"])
        batch.drop_column("assignment_id")
    op.drop_table("class_assignments")
    # in place (SQLite 3.35+ and PostgreSQL): a batch copy would drop the table, and SQLite's foreign keys would
    # delete every class's rows with it
    op.execute("ALTER TABLE classes DROP COLUMN recovery_hash")
