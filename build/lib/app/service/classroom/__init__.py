"""Classes: an instructor's class, its students (pseudonyms), its assignment and every recorded attempt.

The only part of the app with a database (SQLAlchemy 2, Alembic migrations):
SQLite in ``settings().data_dir`` by default, PostgreSQL when
``settings().database_url`` names one.  Nothing touches the database until a
class route is first used (``database.Database`` connects and migrates then).

* ``models``: the tables; ``migrations/``: their history, applied at first use;
* ``database``: the engine, the migrations under a lock, retention;
* ``keys``: class codes, secret keys and their hashes;
* ``store``: the queries (synchronous; the service runs them in threads);
* ``reports``: the summary, per-student progress and the CSV export;
* ``rates``: joins and checks per minute, per class and per client;
* ``service``: ``Classroom``, what the web routes call.
"""
