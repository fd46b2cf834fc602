"""A student's institution login, when the class asks for it, for grades that import into an LMS: the class keeps
the header its LMS matches rows by ("SIS Login ID", "username" or "Login"), each student their login.

Revision ID: 0008
Revises: 0007
"""

import sqlalchemy as sa
from alembic import op

revision = "0008"
down_revision = "0007"
branch_labels = None
depends_on = None


def upgrade() -> None:
    # classes before this revision ask for no login; their students have none
    with op.batch_alter_table("classes") as batch:
        batch.add_column(sa.Column("login_column", sa.String(20), nullable=True))
    with op.batch_alter_table("students") as batch:
        batch.add_column(sa.Column("login", sa.String(64), nullable=True))


def downgrade() -> None:
    # in place (SQLite 3.35+ and PostgreSQL): a batch copy would drop the table, and SQLite's foreign keys would
    # delete every row that refers to it (a class's students, assignments and answers) with it
    op.execute("ALTER TABLE students DROP COLUMN login")
    op.execute("ALTER TABLE classes DROP COLUMN login_column")
