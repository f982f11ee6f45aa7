"""Nothing the tool writes replaces one of its inputs (issue 17): the one check, and every
command that writes.

``sweep c.csv --law table --table t.csv --out t.csv`` replaced the table with results, exit 0;
``solve --path d/tractions.csv --out d`` and ``solve --profile-table d/slip.csv --out d``
replaced an input inside the output folder.  Every writing command now lists what it reads and
writes and refuses a collision before anything is read, computed or written.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
from pathlib import Path

import pytest

from asymslip.cli import main
from asymslip.errors import InputError
from asymslip.files.collisions import Input, Output, refuse_overwriting_inputs, same_file


def refuse(target: Path, source: Path, names: tuple[str, ...] = ()) -> None:
    refuse_overwriting_inputs(
        [Input(source, "table", "the table law")], [Output(target, "out", names)]
    )


@pytest.fixture
def table(tmp_path: Path) -> Path:
    path = tmp_path / "t.csv"
    path.write_text("P,a\n1,1\n")
    return path


# --- the check ---------------------------------------------------------------------------------
def test_the_same_path_is_refused_naming_the_output_option_and_the_input(table: Path):
    with pytest.raises(InputError, match=r"^out: .*t\.csv is also an input \(the table law, "):
        refuse(table, table)


@pytest.mark.parametrize("form", ["./x", "a/../x", "absolute vs relative"])
def test_another_spelling_of_the_same_path_is_refused(table: Path, form: str, monkeypatch):
    monkeypatch.chdir(table.parent)
    (table.parent / "a").mkdir()
    target = {
        "./x": Path("./t.csv"),
        "a/../x": Path("a/../t.csv"),
        "absolute vs relative": Path("t.csv"),
    }[form]
    with pytest.raises(InputError, match="is also an input"):
        refuse(target, table)


def test_a_symbolic_link_to_the_input_is_refused_either_way(table: Path):
    link = table.parent / "link.csv"
    os.symlink(table, link)
    for target, source in ((link, table), (table, link)):
        with pytest.raises(InputError, match="is also an input"):
            refuse(target, source)


def test_a_path_through_a_linked_folder_is_refused(table: Path):
    folder = table.parent / "linked"
    os.symlink(table.parent, folder)
    with pytest.raises(InputError, match="is also an input"):
        refuse(folder / "t.csv", table)


def test_a_hard_link_of_the_input_is_refused(table: Path):
    hard = table.parent / "hard.csv"
    os.link(table, hard)
    with pytest.raises(InputError, match="is also an input"):
        refuse(hard, table)


def test_a_name_differing_in_case_is_refused_where_the_file_system_ignores_case(
    table: Path, monkeypatch
):
    """Simulated (this machine's file systems are case-sensitive): ``os.stat`` looks names up
    as macOS and Windows do, ignoring case.  The check decides by the file the system finds,
    so ``T.CSV`` is ``t.csv`` there; on a case-sensitive system it is another file."""
    real_stat = os.stat

    def case_blind_stat(path, *args, **kwargs):  # noqa: ANN001, ANN202
        try:
            return real_stat(path, *args, **kwargs)
        except FileNotFoundError:
            folder, name = os.path.split(os.fspath(path))
            for sibling in os.listdir(folder or "."):
                if sibling.casefold() == name.casefold():
                    return real_stat(os.path.join(folder, sibling), *args, **kwargs)
            raise

    upper = table.parent / "T.CSV"
    refuse(upper, table)  # case-sensitive: another file, fine
    monkeypatch.setattr(os, "stat", case_blind_stat)
    with pytest.raises(InputError, match="is also an input"):
        refuse(upper, table)


def test_a_new_file_or_another_file_is_fine(table: Path):
    other = table.parent / "other.csv"
    refuse(table.parent / "new.csv", table)
    other.write_text("x")
    refuse(other, table)
    refuse_overwriting_inputs([None, Input(table, "table", "t")], [None, Output(other, "out")])


def test_a_folder_output_is_refused_only_for_an_input_among_the_files_it_writes(tmp_path: Path):
    folder = tmp_path / "d"
    folder.mkdir()
    inside = folder / "tractions.csv"
    inside.write_text("P,Q\n")
    names = ("tractions.csv", "slip.csv")
    with pytest.raises(
        InputError, match=r"^out: .*tractions\.csv is also an input.*another folder"
    ):
        refuse(folder, inside, names)
    kept = folder / "path.csv"
    kept.write_text("P,Q\n")
    refuse(folder, kept, names)  # not a file the output writes
    refuse(tmp_path / "elsewhere", inside, names)


def test_same_file_on_paths_that_do_not_exist_compares_resolved_names(tmp_path: Path):
    assert same_file(tmp_path / "x" / ".." / "y", tmp_path / "y")
    assert not same_file(tmp_path / "y", tmp_path / "z")


# --- every command that writes -----------------------------------------------------------------
HERTZ_TABLE = "P,a\n" + "".join(
    f"{P},{(4 * P / 3.141592653589793) ** 0.5!r}\n" for P in (60, 80, 100, 120, 140)
)
HERTZ = ("--law", "hertz", "--R", "1", "--E-star", "1")
CYCLE = ("--mu", "0.1", "--P1", "100", "--Q1", "0", "--P2", "105", "--Q2", "1")
SOLVE = ("--elements", "100", "--steps", "3")


def run(argv: list[str]) -> tuple[int, str]:
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        status = main(argv)
    return status, err.getvalue()


def make_inputs(folder: Path) -> dict[str, bytes]:
    """Every kind of input file a writing command reads."""
    files = {
        "cases.csv": b"P1,Q1,P2,Q2\n100,0,105,1\n",
        "t.csv": HERTZ_TABLE.encode(),
        "d/tractions.csv": b"P,Q\n100,0\n105,1\n",
        "d/slip.csv": b"x,h\n" + b"".join(f"{x},{x * x / 2}\n".encode() for x in range(-30, 31)),
        "traces.csv": b"P,x,p\n",  # never read: the collision is refused first
        "law.py": b"x = 1\n",
        "cal.json": b"{}\n",
    }
    for name, content in files.items():
        (folder / name).parent.mkdir(exist_ok=True)
        (folder / name).write_bytes(content)
    return files


COLLISIONS = {
    "sweep --out the table": (
        [
            "sweep",
            "{d}/cases.csv",
            "--law",
            "table",
            "--table",
            "{d}/t.csv",
            "--mu",
            "0.1",
            "--out",
            "{d}/t.csv",
        ],
        r"^asymslip: error: --out: .*t\.csv is also an input \(the table law",
    ),
    "sweep --out the cases": (
        ["sweep", "{d}/cases.csv", *HERTZ, "--mu", "0.1", "--out", "{d}/./cases.csv"],
        r"is also an input \(the cases",
    ),
    "sweep --out the law module": (
        [
            "sweep",
            "{d}/cases.csv",
            "--law",
            "module",
            "--module",
            "{d}/law.py",
            "--mu",
            "0.1",
            "--out",
            "{d}/law.py",
        ],
        r"is also an input \(the law module",
    ),
    "sweep --out the calibration": (
        [
            "sweep",
            "{d}/cases.csv",
            "--law",
            "calibrated",
            "--calibration",
            "{d}/cal.json",
            "--mu",
            "0.1",
            "--out",
            "{d}/cal.json",
        ],
        r"is also an input \(the calibration",
    ),
    "solve --path inside --out": (
        ["solve", *HERTZ, "--mu", "0.1", "--path", "{d}/d/tractions.csv", *SOLVE, "--out", "{d}/d"],
        r"^asymslip: error: --out: .*tractions\.csv is also an input \(the load path",
    ),
    "solve --profile-table inside --out": (
        [
            "solve",
            "--profile-table",
            "{d}/d/slip.csv",
            "--E-star",
            "1",
            *CYCLE,
            *SOLVE,
            "--out",
            "{d}/d",
        ],
        r"slip\.csv is also an input \(the profile table",
    ),
    "solve --table inside --out": (
        ["solve", "--law", "table", "--table", "{d}/d/slip.csv", *CYCLE, *SOLVE, "--out", "{d}/d"],
        r"slip\.csv is also an input \(the table law",
    ),
    "calibrate --out the traces": (
        ["calibrate", "{d}/traces.csv", "--out", "{d}/traces.csv"],
        r"is also an input \(the traces",
    ),
}


@pytest.mark.parametrize("name", list(COLLISIONS))
def test_a_command_whose_output_is_its_input_refuses_before_anything_is_written(
    tmp_path: Path, name: str
):
    inputs = make_inputs(tmp_path)
    argv, message = COLLISIONS[name]
    before = sorted(path.relative_to(tmp_path) for path in tmp_path.rglob("*"))
    status, err = run([item.replace("{d}", str(tmp_path)) for item in argv])
    assert status == 2 and len(err.splitlines()) == 1, err
    assert re.search(message, err), err
    for relative, content in inputs.items():
        assert (tmp_path / relative).read_bytes() == content  # every input intact
    assert sorted(path.relative_to(tmp_path) for path in tmp_path.rglob("*")) == before


def test_figure_redraw_refuses_a_png_that_is_its_csv(tmp_path: Path):
    """error-map --redraw reads DATA/error_map.csv and writes OUT/error_map.png: a PNG path that
    is a link to the CSV would replace the data."""
    data = tmp_path / "data"
    data.mkdir()
    csv = data / "error_map.csv"
    csv.write_text("a2_a1\n")
    out = tmp_path / "out"
    out.mkdir()
    os.symlink(csv, out / "error_map.png")
    status, err = run(["figure", "error-map", "--redraw", "--data", str(data), "--out", str(out)])
    assert status == 2 and "--out" in err and "is also an input (the error map's data" in err, err
    assert csv.read_text() == "a2_a1\n"


def test_the_files_solve_checks_are_the_files_it_writes(tmp_path: Path):
    """The collision check of ``solve --out`` lists asymslip.solver.outputs.FILES: exactly what
    write_outputs puts into the folder (so that the list cannot fall behind)."""
    from asymslip.solver.outputs import FILES

    status, err = run(["solve", *HERTZ, *CYCLE, *SOLVE, "--out", str(tmp_path / "out")])
    assert status == 0, err
    assert sorted(path.name for path in (tmp_path / "out").iterdir()) == sorted(FILES)
