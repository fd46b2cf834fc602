"""A student's recovery code: with their pseudonym it opens their record again on another device; the database
keeps only its SHA-256.

Revision ID: 0007
Revises: 0006
"""

import sqlalchemy as sa
from alembic import op

revision = "0007"
down_revision = "0006"
branch_labels = None
depends_on = None


def upgrade() -> None:
    # students who joined before this revision have none: their teacher can give them one
    with op.batch_alter_table("students") as batch:
        batch.add_column(sa.Column("recovery_hash", sa.String(64), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("students") as batch:
        batch.drop_column("recovery_hash")
