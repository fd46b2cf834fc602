"""Assignments (the items and steps a class practises) and the named mistake of an attempt.

Revision ID: 0002
Revises: 0001
"""

import sqlalchemy as sa
from alembic import op

revision = "0002"
down_revision = "0001"
branch_labels = None
depends_on = None


def upgrade() -> None:
    op.create_table(
        "assignments",
        sa.Column("id", sa.Integer, primary_key=True),
        sa.Column("class_id", sa.Integer, sa.ForeignKey("classes.id", ondelete="CASCADE"), nullable=False, index=True),
        sa.Column("position", sa.Integer, nullable=False),
        sa.Column("item", sa.String(40), nullable=False),
        sa.Column("system", sa.Text, nullable=True),
        sa.Column("steps", sa.Text, nullable=False),
        sa.Column("parameters", sa.Text, nullable=False),
        sa.UniqueConstraint("class_id", "position", name="uq_assignments_class_position"),
    )
    # attempts recorded before this revision have no named mistake: null
    with op.batch_alter_table("attempts") as batch:
        batch.add_column(sa.Column("mistake", sa.String(60), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("attempts") as batch:
        batch.drop_column("mistake")
    op.drop_table("assignments")
