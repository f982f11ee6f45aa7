"""A sweep killed while writing leaves nothing behind, or says so next time (issue 17).

SIGTERM or SIGKILL during a sweep left the hidden ``.partial`` file (up to 709 MB).  Now
SIGTERM, SIGHUP and SIGINT remove it (exit 128 + the signal); after SIGKILL, which nothing can
catch, the next write of the same target says that an old partial file exists and removes it
only when it is provably a left-over of this tool.  Real processes, real signals.
"""

from __future__ import annotations

import logging
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from asymslip.files.atomic import atomic_write
from asymslip.files.partials import host_tag, parse_partial_name, partial_prefix

pytestmark = pytest.mark.skipif(os.name != "posix", reason="POSIX signals")

ROWS = 200_000


@pytest.fixture(scope="module")
def cases(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("partials") / "cases.csv"
    line = "100,0,105,1\n"
    path.write_text("P1,Q1,P2,Q2\n" + line * ROWS)
    return path


HERTZ = ("--law", "hertz", "--R", "1", "--E-star", "1", "--mu", "0.1")


def sweep_command(cases: Path, out: Path, *options: str) -> list[str]:
    return [
        sys.executable,
        "-m",
        "asymslip",
        "sweep",
        str(cases),
        *HERTZ,
        *options,
        "--out",
        str(out),
    ]


def _as_in_a_terminal() -> None:
    """The child's SIGINT as a terminal gives it (Ctrl-C raises KeyboardInterrupt).

    A job started in the background by a non-interactive shell -- as CI may run this suite --
    inherits SIGINT *ignored*, and Python then installs no KeyboardInterrupt handler: the sweep,
    rightly, runs to its end.  The test is about what Ctrl-C does, so it sets the default.
    """
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def start_sweep(cases: Path, out: Path) -> subprocess.Popen[str]:
    command = sweep_command(cases, out, "--chunk-rows", "2000")
    return subprocess.Popen(
        command,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=_as_in_a_terminal,
    )


def partials(folder: Path) -> list[Path]:
    return sorted(path for path in folder.iterdir() if path.name.endswith(".partial"))


def wait_for_partial(process: subprocess.Popen[str], folder: Path) -> Path:
    """The partial file, once the sweep has started writing (and before it ends)."""
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        found = partials(folder)
        if found and found[0].stat().st_size > 0:
            return found[0]
        assert process.poll() is None, process.communicate()
        time.sleep(0.01)
    process.kill()
    raise AssertionError("the sweep never started writing")


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_a_termination_signal_during_a_sweep_removes_the_partial_file(
    cases: Path, tmp_path: Path, signum: int
):
    out = tmp_path / "results.csv"
    process = start_sweep(cases, out)
    partial = wait_for_partial(process, tmp_path)
    assert parse_partial_name(out, partial.name) == (process.pid, host_tag())
    process.send_signal(signum)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 128 + signum, err
    assert "Traceback" not in err and "nothing partial was written" in err, err
    assert partials(tmp_path) == [] and not out.exists()


def test_after_sigkill_the_next_run_says_so_and_removes_the_left_over(cases: Path, tmp_path: Path):
    out = tmp_path / "results.csv"
    process = start_sweep(cases, out)
    partial = wait_for_partial(process, tmp_path)
    process.kill()
    process.communicate(timeout=60)
    assert partials(tmp_path) == [partial]  # SIGKILL cannot be caught: it is left
    small = tmp_path / "small.csv"
    small.write_text("P1,Q1,P2,Q2\n100,0,105,1\n")
    done = subprocess.run(sweep_command(small, out), capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    note = (
        f"asymslip: note: removed {partial}: a partial file left by an interrupted asymslip "
        f"run (process {process.pid}, no longer running)"
    )
    assert done.stderr.splitlines()[0] == note
    assert partials(tmp_path) == [] and len(out.read_text().splitlines()) == 2


def _write(target: Path, caplog: pytest.LogCaptureFixture) -> list[str]:
    caplog.clear()
    with caplog.at_level(logging.WARNING, logger="asymslip.files"):
        with atomic_write(target, mode="w") as handle:
            handle.write("done\n")
    assert target.read_text() == "done\n"
    return [record.getMessage() for record in caplog.records]


def test_partial_files_that_are_not_provably_left_overs_are_reported_and_kept(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
):
    target = tmp_path / "results.csv"
    running = os.getppid()  # a process that certainly runs: pytest's parent
    kept = {
        # a live process's partial file (perhaps another sweep writing the same target)
        f".results.csv.asymslip-{running}-{host_tag()}-abc.partial": "is still running",
        # from another machine sharing the folder
        ".results.csv.asymslip-999999-00000000-abc.partial": "written on another machine",
        # named by an older version (no process id)
        ".results.csv.k2x9q1.partial": "does not say which process wrote it",
    }
    for name in kept:
        (tmp_path / name).write_text("half\n")
    messages = _write(target, caplog)
    assert len(messages) == 3
    for name, reason in kept.items():
        assert (tmp_path / name).exists()
        (message,) = [text for text in messages if name in text]
        assert "was not removed because" in message and reason in message, message


def test_another_users_partial_file_is_kept(tmp_path: Path, caplog: pytest.LogCaptureFixture):
    if os.getuid() != 0:
        pytest.skip("giving a file to another user needs root")
    target = tmp_path / "results.csv"
    dead = _dead_pid()
    other = tmp_path / f".results.csv.asymslip-{dead}-{host_tag()}-abc.partial"
    other.write_text("half\n")
    os.chown(other, 65534, 65534)
    (message,) = _write(target, caplog)
    assert other.exists() and "belongs to another user" in message


def test_a_link_named_like_a_left_over_is_kept(tmp_path: Path, caplog: pytest.LogCaptureFixture):
    target = tmp_path / "results.csv"
    precious = tmp_path / "precious.csv"
    precious.write_text("data\n")
    link = tmp_path / f".results.csv.asymslip-{_dead_pid()}-{host_tag()}-abc.partial"
    os.symlink(precious, link)
    (message,) = _write(target, caplog)
    assert link.is_symlink() and precious.read_text() == "data\n"
    assert "not a regular file" in message


def test_a_dead_process_s_partial_file_of_this_machine_and_user_is_removed(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
):
    target = tmp_path / "results.csv"
    dead = _dead_pid()
    left = tmp_path / f".results.csv.asymslip-{dead}-{host_tag()}-abc.partial"
    left.write_text("half\n")
    other_target = tmp_path / f".other.csv.asymslip-{dead}-{host_tag()}-abc.partial"
    other_target.write_text("half\n")
    (message,) = _write(target, caplog)
    assert not left.exists() and message.startswith(f"removed {left}")
    assert other_target.exists()  # another target's: not looked at


def test_the_partial_file_is_named_for_its_process_and_machine(tmp_path: Path):
    target = tmp_path / "results.csv"
    prefix = partial_prefix(target)
    assert prefix == f".results.csv.asymslip-{os.getpid()}-{host_tag()}-"
    with atomic_write(target, mode="w") as handle:
        (partial,) = partials(tmp_path)
        assert partial.name.startswith(prefix)
        assert parse_partial_name(target, partial.name) == (os.getpid(), host_tag())
        handle.write("x")
    assert partials(tmp_path) == []


def _dead_pid() -> int:
    """The id of a process that has ended."""
    command = [sys.executable, "-c", "import os; print(os.getpid())"]
    return int(subprocess.run(command, capture_output=True, text=True).stdout)
