"""A session a lecturer can end without deleting the class: when joining was closed (no new student) and when
answers were stopped (none recorded, the record kept); None while open.

Revision ID: 0009
Revises: 0008
"""

import sqlalchemy as sa
from alembic import op

revision = "0009"
down_revision = "0008"
branch_labels = None
depends_on = None


def upgrade() -> None:
    # classes before this revision are open to both
    with op.batch_alter_table("classes") as batch:
        batch.add_column(sa.Column("joining_closed_at", sa.DateTime(), nullable=True))
        batch.add_column(sa.Column("answers_stopped_at", sa.DateTime(), nullable=True))


def downgrade() -> None:
    # in place (SQLite 3.35+ and PostgreSQL): a batch copy would drop the table, and SQLite's foreign keys would
    # delete every row that refers to it (a class's students, assignments and answers) with it
    op.execute("ALTER TABLE classes DROP COLUMN answers_stopped_at")
    op.execute("ALTER TABLE classes DROP COLUMN joining_closed_at")
