"""A one-line progress bar on a terminal; silent when stderr is not one."""

from __future__ import annotations

from typing import TextIO


class Progress:
    """A one-line progress bar on a terminal; silent when stderr is not one."""

    def __init__(self, total: int, stream: TextIO, enabled: bool | None) -> None:
        self.total, self.stream = total, stream
        self.enabled = stream.isatty() if enabled is None else enabled

    def update(self, done: int) -> None:
        if self.enabled and self.total:
            filled = int(30 * done / self.total)
            self.stream.write(f"\rsweep [{'#' * filled}{'.' * (30 - filled)}] "
                              f"{done:,}/{self.total:,} rows")  # fmt: skip
            self.stream.flush()

    def close(self) -> None:
        if self.enabled and self.total:
            self.stream.write("\n")
            self.stream.flush()
