"""The progress bar: one redrawn line on a terminal, nothing otherwise."""

from __future__ import annotations

import io

from asymslip.files import Progress


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_silent_when_the_stream_is_not_a_terminal():
    stream = io.StringIO()
    with Progress(100, stream) as bar:
        bar.update(50)
        bar.update(100)
    assert stream.getvalue() == ""


def test_one_redrawn_line_on_a_terminal():
    stream = Terminal()
    with Progress(1_000_000, stream) as bar:
        bar.update(250_000)
        bar.update(1_000_000)
    text = stream.getvalue()
    assert text.count("\n") == 1 and text.endswith("\n")
    assert text.startswith("\rsweep [#######.......................] 250,000/1,000,000 rows")
    assert text.rstrip("\n").endswith("\rsweep [" + "#" * 30 + "] 1,000,000/1,000,000 rows")


def test_forced_on_or_off_and_nothing_for_zero_rows():
    on, off, empty = Terminal(), Terminal(), Terminal()
    Progress(10, io.StringIO(), enabled=True).update(10)
    with Progress(10, off, enabled=False) as bar:
        bar.update(10)
    with Progress(0, empty) as bar:
        bar.update(0)
    with Progress(10, on, enabled=True, label="read") as bar:
        bar.update(10)
    assert off.getvalue() == "" and empty.getvalue() == ""
    assert on.getvalue().startswith("\rread [")
