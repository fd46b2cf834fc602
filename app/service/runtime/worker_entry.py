"""The first module a worker process runs, in place of the server's ``__main__``.

multiprocessing starts a child by re-running its parent's main script (as
``__mp_main__``) so that functions defined there can be unpickled.  The server's
main script may be anything: uvicorn's command line, a hand-written launcher
that starts a server at its top level, or a script fed on stdin that no child
can read again.  Workers run only module-level jobs of ``app``, so they start
from this module instead (app/service/runtime/worker.py), which does nothing.
"""
