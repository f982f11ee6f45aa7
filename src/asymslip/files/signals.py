"""A termination signal during a write ends it like Ctrl-C: the partial file is removed.

Python turns SIGINT into :class:`KeyboardInterrupt`, which unwinds the write and removes its
partial file; SIGTERM (``kill``, a batch system's time limit) and SIGHUP (the terminal closed)
end the process at once by default, leaving the partial file behind.  While a file is being
written, :func:`terminate_cleanly` turns them into :class:`Terminated`, which unwinds the same
way; the command line then exits with status 128 + the signal's number, as the shell expects of
a process killed by it.

Only the main thread can install signal handlers, and a handler the program has set itself is
left alone; the previous handlers are restored when the write ends.

Examples
--------
>>> import os, signal, time
>>> from asymslip.files.signals import Terminated, terminate_cleanly
>>> try:
...     with terminate_cleanly():
...         os.kill(os.getpid(), signal.SIGTERM)
...         time.sleep(5)  # the handler raises as soon as the signal arrives
... except Terminated as stopped:
...     print(stopped, 128 + stopped.signum)
terminated by SIGTERM 143
>>> signal.getsignal(signal.SIGTERM) is signal.SIG_DFL  # restored
True
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from types import FrameType

#: The signals that end a process and that a write turns into :class:`Terminated`.
TERMINATING = tuple(
    getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name)
)


class Terminated(BaseException):
    """A termination signal arrived (like :class:`KeyboardInterrupt`, not an ``Exception``)."""

    def __init__(self, signum: int) -> None:
        self.signum = signum
        super().__init__(f"terminated by {signal.Signals(signum).name}")


def _raise_terminated(signum: int, frame: FrameType | None) -> None:
    raise Terminated(signum)


@contextmanager
def terminate_cleanly() -> Iterator[None]:
    """Within the block, SIGTERM and SIGHUP raise :class:`Terminated` (main thread only, and
    only where the default handler is installed)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {}
    for signum in TERMINATING:
        if signal.getsignal(signum) is signal.SIG_DFL:
            previous[signum] = signal.signal(signum, _raise_terminated)
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
