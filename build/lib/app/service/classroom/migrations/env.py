"""Alembic's environment: run the migrations on the connection ``database.migrate`` hands over."""

from alembic import context

connection = context.config.attributes["connection"]
# batch mode: SQLite alters a table by copying it
context.configure(connection=connection, render_as_batch=True)
with context.begin_transaction():
    context.run_migrations()
