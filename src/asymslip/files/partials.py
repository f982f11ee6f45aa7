"""The hidden partial file every write goes through, and what a killed run leaves of one.

:func:`asymslip.files.atomic.atomic_write` writes into a hidden file beside the target and
renames it over the target when complete.  An interrupt or SIGTERM removes it
(:mod:`asymslip.files.signals`); SIGKILL, a power cut or a crash of the machine cannot, and a
sweep's partial file can be hundreds of megabytes.  So the name says whose it is::

    .{target}.asymslip-{process id}-{host tag}-{random}.partial

(the host tag: 8 hex digits of a hash of the machine's name), and the next write of the same
target looks for such files (:func:`clean_left_overs`).  It removes one only when it is
provably a left-over of this tool: the name is this pattern, written on this machine by a
process that is no longer running, the file belongs to the user running now and is a regular
file (not a link).  Anything else that looks like a partial file of the target -- another
user's, one whose process still runs (perhaps another sweep), one from another machine sharing
the folder, one named by an older version -- is only reported.  Every finding is said once, as a
warning of the ``asymslip.files`` logger (the command line prints it on stderr).

Examples
--------
>>> from pathlib import Path
>>> from asymslip.files.partials import parse_partial_name
>>> parse_partial_name(Path("results.csv"), ".results.csv.asymslip-4242-0a1b2c3d-x7.partial")
(4242, '0a1b2c3d')
>>> parse_partial_name(Path("results.csv"), ".results.csv.x7k2.partial") is None
True
"""

from __future__ import annotations

import errno
import hashlib
import logging
import os
import re
import socket
import stat
from dataclasses import dataclass
from functools import cache
from pathlib import Path

#: The word in every partial file's name that says this tool wrote it.
MARKER = "asymslip"
SUFFIX = ".partial"
#: Where the findings are said (the command line prints this logger's warnings on stderr).
LOGGER = logging.getLogger("asymslip.files")


@cache
def host_tag() -> str:
    """8 hex digits naming this machine (a hash of its name: no name leaks into file names)."""
    return hashlib.sha256(socket.gethostname().encode("utf-8", "replace")).hexdigest()[:8]


def partial_prefix(target: Path) -> str:
    """The start of the name of this process's partial file for ``target`` (mkstemp adds a
    random part and :data:`SUFFIX`)."""
    return f".{target.name}.{MARKER}-{os.getpid()}-{host_tag()}-"


def parse_partial_name(target: Path, name: str) -> tuple[int, str] | None:
    """(process id, host tag) of a partial file of ``target`` named by this tool, else None."""
    pattern = rf"\.{re.escape(target.name)}\.{MARKER}-(\d+)-([0-9a-f]{{8}})-[^/]+{SUFFIX}"
    match = re.fullmatch(pattern, name)
    return (int(match.group(1)), match.group(2)) if match else None


def process_is_running(pid: int) -> bool | None:
    """True or False where the system can tell; None where it cannot (Windows, where signal 0
    would end the process)."""
    if os.name != "posix":
        return None
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process: running
        return True
    except OSError as error:
        return True if error.errno == errno.EPERM else None
    return True


@dataclass(frozen=True)
class LeftOver:
    """A file beside the target that looks like a partial file of it."""

    path: Path
    #: The process that wrote it, where the name says so.
    pid: int | None
    #: Why it may not be removed; empty when it is provably a left-over of this tool.
    kept_because: str


def left_overs(target: Path) -> list[LeftOver]:
    """The partial files of ``target`` in its folder, each with why it must be kept (if so)."""
    folder = target.parent if str(target.parent) else Path(".")
    try:
        names = [
            entry.name
            for entry in os.scandir(folder)
            if entry.name.startswith(f".{target.name}.") and entry.name.endswith(SUFFIX)
        ]
    except OSError:
        return []
    found = []
    for name in sorted(names):
        path = folder / name
        parsed = parse_partial_name(target, name)
        if parsed is None:
            found.append(LeftOver(path, None, "its name does not say which process wrote it"))
            continue
        pid, host = parsed
        found.append(LeftOver(path, pid, _why_kept(path, pid, host)))
    return found


def _why_kept(path: Path, pid: int, host: str) -> str:
    if host != host_tag():
        return "it was written on another machine"
    if pid == os.getpid():
        return "this process is writing it"
    running = process_is_running(pid)
    if running is None:
        return "this system cannot tell whether its process still runs"
    if running:
        return f"its process {pid} is still running (perhaps another asymslip writing the file)"
    try:
        status = os.lstat(path)
    except OSError:
        return "it cannot be looked at"
    if not stat.S_ISREG(status.st_mode):
        return "it is not a regular file"
    if hasattr(os, "getuid") and status.st_uid != os.getuid():
        return "it belongs to another user"
    return ""


def clean_left_overs(target: Path) -> list[LeftOver]:
    """Remove the provable left-overs of ``target`` and report every partial file found.

    Returns what was found (removed ones have an empty ``kept_because``).
    """
    found = left_overs(target)
    for left in found:
        if not left.kept_because:
            try:
                left.path.unlink()
            except OSError as error:
                LOGGER.warning(
                    "%s is a partial file left by an interrupted asymslip run (process %s); it "
                    "could not be removed (%s)",
                    left.path,
                    left.pid,
                    error.strerror or error,
                )
                continue
            LOGGER.warning(
                "removed %s: a partial file left by an interrupted asymslip run (process %s, "
                "no longer running)",
                left.path,
                left.pid,
            )
        else:
            LOGGER.warning(
                "%s looks like a partial file of %s left by an interrupted run; it was not "
                "removed because %s: delete it yourself if nothing is writing %s",
                left.path,
                target.name,
                left.kept_because,
                target.name,
            )
    return found
