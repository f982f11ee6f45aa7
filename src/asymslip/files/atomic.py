"""Write a file so that it is either complete or absent: never a truncated result.

A sweep interrupted by Ctrl-C, a full disk or a killed process must not leave a results file
that looks complete.  Everything the tool writes goes to a temporary file beside the target
(same folder, hence same file system) and is renamed over it only once it is closed and synced;
on any error, an interrupt, SIGTERM or SIGHUP (:mod:`.signals`) the temporary file is removed
and the target is untouched.  A partial file that a killed run (SIGKILL) left behind is found
by the next write of the same target, and removed only when it is provably a left-over of this
tool (:mod:`.partials`).

The file gets the permissions any program would give it: a new file ``0666`` less the user's
umask (``0644`` with the usual umask 022), a replaced file keeps its own -- not the ``0600``
of a temporary file.

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
import stat
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Any, Literal

from ..errors import InputError
from .partials import SUFFIX, clean_left_overs, partial_prefix
from .signals import terminate_cleanly


def _umask() -> int:
    """The process's umask (set and restored at once: there is no way only to read it)."""
    mask = os.umask(0o077)  # briefly the stricter one, never a looser one
    os.umask(mask)
    return mask


def permissions_for(target: Path) -> int:
    """The mode a written ``target`` gets: an existing regular file's own permission bits,
    else ``0o666`` less the umask, as ``open(target, "w")`` would give it."""
    try:
        status = os.stat(target)
    except OSError:
        return 0o666 & ~_umask()
    if stat.S_ISREG(status.st_mode):
        return stat.S_IMODE(status.st_mode) & 0o777
    return 0o666 & ~_umask()


@contextmanager
def atomic_write(
    path: str | Path, option: str = "out", mode: Literal["wb", "w"] = "wb"
) -> Iterator[IO[Any]]:
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
    Terminated
        SIGTERM or SIGHUP arrived while writing (:mod:`.signals`); the partial file is gone.
    """
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    clean_left_overs(target)
    permissions = permissions_for(target)
    with terminate_cleanly():
        try:
            descriptor, temporary = tempfile.mkstemp(
                dir=folder, prefix=partial_prefix(target), suffix=SUFFIX
            )
        except OSError as error:
            raise InputError(option, f"cannot write {target}: {error.strerror}") from None
        try:
            handle: IO[Any] = (
                os.fdopen(descriptor, "w", encoding="utf-8")
                if mode == "w"
                else os.fdopen(descriptor, "wb")
            )
            with handle:
                yield handle
                handle.flush()
                os.chmod(handle.fileno() if os.chmod in os.supports_fd else temporary, permissions)
                os.fsync(handle.fileno())
            os.replace(temporary, target)
        except BaseException as error:  # an interrupt too: never leave the partial file behind
            Path(temporary).unlink(missing_ok=True)
            if isinstance(error, OSError) and not isinstance(error, InputError):
                raise InputError(
                    option, f"cannot write {target}: {error.strerror or error}"
                ) from None
            raise
