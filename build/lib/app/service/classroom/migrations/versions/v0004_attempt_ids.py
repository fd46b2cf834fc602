"""Exactly once: each attempt may carry the id the student's page made for it, unique per student, and the
verdict it was answered with, so a retried Check returns the first verdict and records nothing new.

Revision ID: 0004
Revises: 0003
"""

import sqlalchemy as sa
from alembic import op

revision = "0004"
down_revision = "0003"
branch_labels = None
depends_on = None


def upgrade() -> None:
    # attempts recorded before this revision have no id (NULL, which a unique constraint never compares equal)
    with op.batch_alter_table("attempts") as batch:
        batch.add_column(sa.Column("attempt_id", sa.String(64), nullable=True))
        batch.add_column(sa.Column("response", sa.Text, nullable=True))
        batch.create_unique_constraint("uq_attempts_student_attempt", ["student_id", "attempt_id"])


def downgrade() -> None:
    with op.batch_alter_table("attempts") as batch:
        batch.drop_constraint("uq_attempts_student_attempt", type_="unique")
        batch.drop_column("response")
        batch.drop_column("attempt_id")
