"""Files the tool writes get the user's permissions, not 0600 (issue 17).

Every file went through a temporary file made by ``tempfile.mkstemp`` (mode 0600) and kept that
mode whatever the umask: a colleague could not read a sweep's results.  Now a new file is 0666
less the umask and a folder 0777 less the umask, as any program makes them, and a replaced file
keeps its own mode.  Every command that writes, under two umasks.
"""

from __future__ import annotations

import contextlib
import io
import math
import os
import stat
from collections.abc import Iterator
from pathlib import Path

import pytest

from asymslip.cli import main
from asymslip.files import arrow

pytestmark = pytest.mark.skipif(os.name != "posix", reason="POSIX permissions")

HERTZ = ("--law", "hertz", "--R", "1", "--E-star", "1")
CYCLE = ("--mu", "0.1", "--P1", "100", "--Q1", "0", "--P2", "105", "--Q2", "1")


@contextlib.contextmanager
def umask(mask: int) -> Iterator[None]:
    previous = os.umask(mask)
    try:
        yield
    finally:
        os.umask(previous)


def run(argv: list[str]) -> None:
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        assert main(argv) == 0


def mode(path: Path) -> int:
    return stat.S_IMODE(path.stat().st_mode)


def traces(folder: Path) -> Path:
    """Hertz pressures (48), R = E* = 1, at three loads (as the bad-input table's)."""
    rows = ["P,x,p"]
    for P in (80.0, 100.0, 120.0):
        a = math.sqrt(4 * P / math.pi)
        for k in range(-120, 121):
            x = 1.2 * a * k / 120
            rows.append(
                f"{P!r},{x!r},{2 * P / (math.pi * a * a) * math.sqrt(max(a * a - x * x, 0))!r}"
            )
    path = folder / "traces.csv"
    path.write_text("\n".join(rows) + "\n")
    return path


def commands(folder: Path) -> list[tuple[list[str], list[Path]]]:
    """(command line, the files and folders it writes) for every writing command."""
    cases = folder / "cases.csv"
    cases.write_text("P1,Q1,P2,Q2\n100,0,105,1\n")
    out = folder / "out"
    written: list[tuple[list[str], list[Path]]] = [
        (
            ["sweep", str(cases), *HERTZ, "--mu", "0.1", "--out", str(out / "r.csv")],
            [out / "r.csv"],
        ),
        (
            ["solve", *HERTZ, *CYCLE, "--elements", "100", "--steps", "3", "--out", str(out / "s")],
            [
                out / "s",
                *(
                    out / "s" / name
                    for name in ("tractions.csv", "slip.csv", "energy.csv", "solver.png")
                ),
            ],
        ),
        (
            ["calibrate", str(traces(folder)), "--out", str(out / "cal.json")],
            [out / "cal.json"],
        ),
        (
            [
                "derive",
                "--P-of-a",
                "k*a**2",
                "--params",
                "k",
                "--name",
                "square",
                "--out",
                str(out / "square.py"),
            ],
            [out / "square.py"],
        ),
        (
            ["figure", "fig5", "--out", str(out / "f")],
            [out / "f", out / "f" / "fig5.csv", out / "f" / "fig5.png"],
        ),
    ]
    if arrow.available():
        written.append(
            (
                ["sweep", str(cases), *HERTZ, "--mu", "0.1", "--out", str(out / "r.parquet")],
                [out / "r.parquet"],
            )
        )
    return written


@pytest.mark.parametrize(
    "mask, file_mode, folder_mode", [(0o022, 0o644, 0o755), (0o077, 0o600, 0o700)]
)
def test_every_written_file_and_folder_has_the_umask_s_mode(
    tmp_path: Path, mask: int, file_mode: int, folder_mode: int
):
    (tmp_path / "out").mkdir()
    with umask(mask):
        for argv, paths in commands(tmp_path):
            run(argv)
            for path in paths:
                expected = folder_mode if path.is_dir() else file_mode
                assert mode(path) == expected, (argv[0], path, oct(mode(path)))


def test_a_replaced_file_keeps_its_own_mode(tmp_path: Path):
    (tmp_path / "out").mkdir()
    with umask(0o022):
        for argv, paths in commands(tmp_path):
            for path in paths:
                if path.exists() and not path.is_dir():
                    path.chmod(0o640)
            if argv[0] in ("sweep", "calibrate", "derive"):  # write once, then replace it
                run(argv)
                paths[0].chmod(0o640)
                run(argv)
                assert mode(paths[0]) == 0o640, argv[0]
