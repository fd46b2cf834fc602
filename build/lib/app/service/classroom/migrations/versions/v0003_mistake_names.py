"""The named mistake's display text beside its stable key (the tutor's ``mistake.name``).

Revision ID: 0003
Revises: 0002
"""

import sqlalchemy as sa
from alembic import op

revision = "0003"
down_revision = "0002"
branch_labels = None
depends_on = None


def upgrade() -> None:
    # attempts recorded before this revision keep their key; the dashboard words the key itself for them
    with op.batch_alter_table("attempts") as batch:
        batch.add_column(sa.Column("mistake_name", sa.String(200), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("attempts") as batch:
        batch.drop_column("mistake_name")
