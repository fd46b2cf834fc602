"""Work threads give way to the event loop that answers requests.

Linux schedules threads, not processes, and weighs each by its nice value: at
nice 0 a thread's share of a busy core is about 3x that of one at nice 5 (the
weights are 1024 and 335).  A web process runs its event loop (accepting
connections, /healthz, dispatching) on one thread and the work (simulations,
work-precision reports) on pool threads; renicing the pool threads lets the loop
run first whenever both are ready, so a flood of simulations slows simulations,
not every answer.  Without privileges a thread's nice value can only rise, so
each thread is reniced once and never back; the pool workers of user systems,
already at ``app.service.worker.WORKER_NICENESS``, are left as they are.
"""

from __future__ import annotations

import os
import threading

from app.settings import settings

_seen = threading.local()


def yield_to_the_loop() -> None:
    """Raise this thread's nice value to the ``work_niceness`` setting (once per thread; never lower it)."""
    if getattr(_seen, "done", False):
        return
    _seen.done = True
    wanted = settings().work_niceness
    if wanted <= 0 or not hasattr(os, "setpriority") or threading.current_thread() is threading.main_thread():
        return
    tid = threading.get_native_id()
    try:
        # PRIO_PROCESS with a thread id sets that one thread's value (Linux; each thread is a task)
        if os.getpriority(os.PRIO_PROCESS, tid) < wanted:
            os.setpriority(os.PRIO_PROCESS, tid, wanted)
    except OSError:  # not permitted here: the thread keeps its priority
        pass
