"""A worker ends only a process group it leads: never its web process's (and the server's, and the test's)."""

from __future__ import annotations

import os
import signal

from app.service.runtime import worker


def test_ending_its_group_before_it_has_one_ends_only_the_worker():
    # a child still in this process's group (as a pool worker is before initialize_worker makes its own)
    child = os.fork()
    if child == 0:  # pragma: no cover - the child
        worker._kill_group()
        os._exit(0)  # not reached: the worker ends itself
    _, status = os.waitpid(child, 0)
    assert os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGKILL
    # this process, in the group the child did not lead, is still here to say so

