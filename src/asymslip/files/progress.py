"""A one-line progress bar on a terminal; silent when the stream is not one."""

from __future__ import annotations

import sys
import time
from typing import TextIO


class Progress:
    """``update(done)`` redraws ``label [####....] done/total rows``; ``close()`` ends the line.

    Parameters
    ----------
    total
        Rows to do.
    stream
        Where to draw (default ``sys.stderr``).
    enabled
        Draw or not; default: only when ``stream`` is a terminal (never into a log file).
    label
        The word in front of the bar.
    """

    def __init__(
        self,
        total: int,
        stream: TextIO | None = None,
        enabled: bool | None = None,
        label: str = "sweep",
    ) -> None:
        self.total, self.label = total, label
        self.stream = stream if stream is not None else sys.stderr
        isatty = getattr(self.stream, "isatty", None)
        self.enabled = (bool(isatty and isatty()) if enabled is None else enabled) and total > 0
        self._last = 0.0

    def update(self, done: int) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if done < self.total and now - self._last < 0.1:  # at most ten redraws a second
            return
        self._last = now
        filled = int(30 * min(done, self.total) / self.total)
        self.stream.write(
            f"\r{self.label} [{'#' * filled}{'.' * (30 - filled)}] {done:,}/{self.total:,} rows"
        )
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self.stream.write("\n")
            self.stream.flush()

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
