"""Nothing the tool writes may replace one of its inputs: the one check every writing command
makes before it writes anything.

A command lists what it reads (:class:`Input`: the cases, a table law, a law module, a
calibration, a load path, a profile table, a trace file ...) and what it writes
(:class:`Output`: a file, or a folder with the names of the files it will put there), and
calls :func:`refuse_overwriting_inputs` first -- before it reads, computes or writes -- so
that ``sweep c.csv --law table --table t.csv --out t.csv`` or ``solve --path d/tractions.csv
--out d`` is one line naming the option, and the input is intact.

Two paths are the same file when they resolve to the same file: ``./x`` and ``x``, a symbolic
link and its target, two hard links of one file (the same device and inode), and, on a file
system that ignores the case of names (macOS, Windows), ``T.csv`` and ``t.csv`` -- all decided
by the file system itself (:func:`os.stat`), not by comparing names.  An output that does not
exist yet cannot be an existing input; an input that does not exist is compared by its
resolved path.

**New commands** (stress, nucleation, match, solve-batch ...) call it the same way: list every
file they read and every file or folder they write, before doing anything else.

Examples
--------
>>> import pathlib, tempfile
>>> from asymslip.files.collisions import Input, Output, refuse_overwriting_inputs
>>> with tempfile.TemporaryDirectory() as folder:  # doctest: +ELLIPSIS
...     table = pathlib.Path(folder) / "t.csv"
...     _ = table.write_text("P,a\\n")
...     refuse_overwriting_inputs(
...         [Input(table, "table", "the table law")],
...         [Output(pathlib.Path(folder) / "." / "t.csv", "out")],
...     )
Traceback (most recent call last):
    ...
asymslip.errors.InputError: out: ...t.csv is also an input (the table law, ...t.csv): writing it ...
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError


@dataclass(frozen=True)
class Input:
    """A file a command reads.

    Attributes
    ----------
    path
        The file as given.
    option
        The parameter that named it (``cases``, ``table``, ``path`` ...).
    what
        What it is, in words, for the message (``"the cases"``, ``"the table law"``).
    """

    path: Path
    option: str
    what: str


@dataclass(frozen=True)
class Output:
    """What a command writes: the file ``path``, or, with ``names``, the folder ``path`` and
    the files of those names it will write into it.

    Attributes
    ----------
    path
        The file, or the folder.
    option
        The parameter that named it (``out``, ``data`` ...): the one the refusal names.
    names
        For a folder: the names of the files written there; empty for a file.
    """

    path: Path
    option: str
    names: tuple[str, ...] = ()

    def files(self) -> list[Path]:
        """Every file this output writes."""
        return [self.path / name for name in self.names] if self.names else [self.path]


def same_file(first: Path, second: Path) -> bool:
    """Whether two paths name one file (see the module docstring for what counts)."""
    try:
        return os.path.samefile(first, second)
    except OSError:  # one of them does not exist (or cannot be looked at): compare names
        pass
    try:
        return os.path.normcase(os.path.realpath(first)) == os.path.normcase(
            os.path.realpath(second)
        )
    except (OSError, ValueError):
        return False


def refuse_overwriting_inputs(
    inputs: Iterable[Input | None], outputs: Iterable[Output | None]
) -> None:
    """Refuse any output file that is one of the inputs, before anything is written.

    ``None`` entries (an option not given) are skipped.

    Raises
    ------
    InputError
        Naming the output's option, the file, and the input it would replace.
    """
    read = [entry for entry in inputs if entry is not None]
    for output in outputs:
        if output is None:
            continue
        for target in output.files():
            for source in read:
                if same_file(Path(target), Path(source.path)):
                    kind = "folder" if output.names else "file"
                    raise InputError(
                        output.option,
                        f"{target} is also an input ({source.what}, {source.path}): writing it "
                        f"would replace the data being read; choose another {kind}",
                    )
