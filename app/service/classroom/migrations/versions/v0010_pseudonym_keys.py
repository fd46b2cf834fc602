"""Each student's pseudonym key (``store.pseudonym_digest``: the SHA-256 of the name after case folding between two
NFKC normalisations), unique in its class, so that two students typing "Grace" and "grace" at the same moment cannot both join, on any replica: the
database refuses the second, as it already refused the same spelling twice.

A class that joined two names equal by the key before this rule keeps both: the first to join gets the key, the
others none (NULL, which a unique index allows more than once); they open their records with their exact spelling.

Revision ID: 0010
Revises: 0009
"""

import sqlalchemy as sa
from alembic import op

from app.service.classroom.store import pseudonym_digest

revision = "0010"
down_revision = "0009"
branch_labels = None
depends_on = None

INDEX = "uq_students_class_name_key"


def upgrade() -> None:
    op.add_column("students", sa.Column("name_key", sa.String(64), nullable=True))
    students = sa.table("students", sa.column("id", sa.Integer), sa.column("class_id", sa.Integer),
                        sa.column("name", sa.String), sa.column("name_key", sa.String))
    connection = op.get_bind()
    seen: set[tuple[int, str]] = set()
    # oldest first: of two names equal by the key, the first to join keeps it
    for row in connection.execute(sa.select(students.c.id, students.c.class_id, students.c.name).order_by(students.c.id)):
        key = (row.class_id, pseudonym_digest(row.name))
        if key in seen:
            continue
        seen.add(key)
        connection.execute(students.update().where(students.c.id == row.id).values(name_key=key[1]))
    op.create_index(INDEX, "students", ["class_id", "name_key"], unique=True)


def downgrade() -> None:
    op.drop_index(INDEX, table_name="students")
    # in place (SQLite 3.35+ and PostgreSQL): a batch copy would drop the table, and SQLite's foreign keys would
    # delete every row that refers to it (a class's students, assignments and answers) with it
    op.execute("ALTER TABLE students DROP COLUMN name_key")
