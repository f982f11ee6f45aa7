"""Write a file so that it is either complete or absent: never a truncated result.

A sweep interrupted by Ctrl-C, a full disk or a killed process must not leave a results file
that looks complete.  Everything the tool writes goes to a temporary file beside the target
(same folder, hence same file system) and is renamed over it only once it is closed and synced;
on any error, or an interrupt, the temporary file is removed and the target is untouched.

Examples
--------
>>> import pathlib, tempfile
>>> from asymslip.files.atomic import atomic_write
>>> with tempfile.TemporaryDirectory() as folder:
...     path = pathlib.Path(folder) / "result.txt"
...     try:
...         with atomic_write(path, mode="w") as handle:
...             _ = handle.write("half a result")
...             raise KeyboardInterrupt
...     except KeyboardInterrupt:
...         pass
...     print(sorted(pathlib.Path(folder).iterdir()))
...     with atomic_write(path, mode="w") as handle:
...         _ = handle.write("complete")
...     print(path.read_text())
[]
complete
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Literal

from ..errors import InputError


@contextmanager
def atomic_write(
    path: str | Path, option: str = "out", mode: Literal["wb", "w"] = "wb"
) -> Iterator[IO]:
    """Open a temporary file beside ``path``; rename it to ``path`` when the block succeeds.

    Parameters
    ----------
    path
        The file to write.  Its folder must exist.
    option
        The option named in the error when the folder cannot be written.
    mode
        ``"wb"`` (bytes) or ``"w"`` (UTF-8 text).

    Raises
    ------
    InputError
        When the temporary file cannot be created (no such folder, no permission), or the
        data cannot be written (a full disk): the message names ``option``.
    """
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    try:
        descriptor, temporary = tempfile.mkstemp(
            dir=folder, prefix=f".{target.name}.", suffix=".partial"
        )
    except OSError as error:
        raise InputError(option, f"cannot write {target}: {error.strerror}") from None
    try:
        encoding = {"encoding": "utf-8"} if mode == "w" else {}
        with os.fdopen(descriptor, mode, **encoding) as handle:
            yield handle
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, target)
    except BaseException as error:  # an interrupt too: never leave the partial file behind
        Path(temporary).unlink(missing_ok=True)
        if isinstance(error, OSError) and not isinstance(error, InputError):
            raise InputError(option, f"cannot write {target}: {error.strerror or error}") from None
        raise
