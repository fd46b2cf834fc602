"""A typed system's set-up: the instructor's words for what its coordinates are, where they are measured from and
where U = 0, shown to students above its boxes.

Revision ID: 0006
Revises: 0005
"""

import sqlalchemy as sa
from alembic import op

revision = "0006"
down_revision = "0005"
branch_labels = None
depends_on = None


def upgrade() -> None:
    # items stored before this revision (scenes, and systems assigned without one) have none: NULL
    with op.batch_alter_table("assignments") as batch:
        batch.add_column(sa.Column("setup", sa.Text, nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("assignments") as batch:
        batch.drop_column("setup")
