"""The sweep: every row of a cases file evaluated like slip_zone; bad rows reported, not fatal."""

from __future__ import annotations

import csv
import io
import re

import numpy as np
import pytest

import asymslip_gen as gen
from asymslip import HertzLaw, InputError, LoadCycle, slip_zone
from asymslip.sweep import WARNING_SEPARATOR, edge_columns, sweep_file
from tests.transcription.section2 import eq21, eq22, eq28

LAW = HertzLaw(R=1.0, E_star=1.0)

# Line numbers count the header as line 1.  Good rows cover every warning slip_zone gives:
# none, no slip (lam < mu), validity (large dP), eta != 0 (no b_exact), a row-level mu, and an
# empty mu cell taking --mu; bad rows break a rule of the cycle, of mu, or of partial slip.
CASES = """\
case,P1,Q1,P2,Q2,sigma1,sigma2,mu
fig5,100,0,105,1,0,0,0.1
swapped,105,0,100,1,0,0,0.1
no-slip,100,0.5,110,2.5,0,0,0.3
big-step,100,0,160,15,0,0,0.1
mu-zero,100,0,105,1,0,0,0
text,100,abc,105,1,0,0,0.1
gross-sliding,100,0,101,90,0,0,0.2
tension,100,0,104,1,0.5,0.9,0.1

default-mu,100,0,103,2,,,
negative-mu,100,0,105,1,0,0,-0.3
short,100,0,105
nan-load,nan,0,105,1,0,0,0.1
backward,200,1,210,-3,0,0,0.15
"""
BAD_LINES = {
    3: r"^P2: must exceed P1",
    6: r"^mu: must be > 0 \(got 0\.0\)",
    7: r"^Q1: 'abc' is not a number",
    8: r"^Q2: \|Q2\| = 90 must be < mu P2 = 20.2: at state 2 the contact would slide",
    12: r"^mu: must be > 0 \(got -0\.3\)",
    13: r"^line has 4 fields, the header has 8",
    14: r"^P1: must be finite",
}
DEFAULT_MU = 0.25


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


@pytest.fixture
def swept(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text(CASES)
    out = tmp_path / "results.csv"
    summary = sweep_file(cases, LAW, out, mu=DEFAULT_MU, progress=False)
    return summary, read(out)


def expected_row(fields: dict[str, str], edge: str):
    mu = float(fields["mu"]) if fields["mu"] else DEFAULT_MU
    cycle = LoadCycle(
        *(
            float(fields[name]) if fields[name] else 0.0
            for name in ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2")
        )
    )
    return slip_zone(LAW, cycle, mu, edge=edge)


def test_bad_rows_are_reported_by_line_number_and_the_others_are_kept(swept):
    summary, rows = swept
    assert [line for line, _ in summary.invalid] == sorted(BAD_LINES)
    assert len(rows) == summary.rows == 13  # every non-blank data line, in order
    assert [row["case"] for row in rows][:3] == ["fig5", "swapped", "no-slip"]
    by_case = {row["case"]: row for row in rows}
    for line, message in summary.invalid:
        assert re.match(BAD_LINES[line], message), message
    assert by_case["swapped"]["b"] == "" and by_case["swapped"]["error"].startswith("P2:")
    good = [row for row in rows if not row["error"]]
    assert {row["case"] for row in good} == {
        "fig5",
        "no-slip",
        "big-step",
        "tension",
        "default-mu",
        "backward",
    }


def test_error_messages_are_the_ones_the_api_raises_for_that_row(swept):
    _, rows = swept
    row = next(row for row in rows if row["case"] == "swapped")
    with pytest.raises(InputError) as raised:
        LoadCycle(105, 0, 100, 1)
    assert row["error"] == str(raised.value)


def _hertz_transcribed(P):
    """(29) and (31) with R = E* = 1, typed from the paper: a, L_I and a'(P) = a/(2P)."""
    a = np.sqrt(4 * P / np.pi)
    return a, 2 * P / np.pi * np.sqrt(2 / a**3), a / (2 * P)


def test_good_rows_give_the_paper_eq22_and_eq28_at_both_edges_to_1e_12(swept):
    """The physics of every good row against the paper transcribed by hand, not the API."""
    _, rows = swept
    checked = 0
    for row in (row for row in rows if not row["error"]):
        P1, Q1, P2, Q2 = (float(row[name]) for name in ("P1", "Q1", "P2", "Q2"))
        s1, s2 = (float(row[name]) if row[name] else 0.0 for name in ("sigma1", "sigma2"))
        mu = float(row["mu"]) if row["mu"] else DEFAULT_MU
        lam, eta = (Q2 - Q1) / (P2 - P1), (s2 - s1) / (P2 - P1)
        (a1, L_I1, slope1), (a2, L_I2, _) = _hertz_transcribed(P1), _hertz_transcribed(P2)
        for prefix, edge_lam in (("", lam), ("left_", -lam)):
            direction = float(row[prefix + "slip_direction"])
            if direction == 0:  # no slip: b = a1 (derivations/edge_symmetry.py)
                assert abs(eq21(edge_lam, eta, a2, L_I2)) <= mu * L_I2
                assert float(row[prefix + "b"]) == pytest.approx(a1, rel=1e-14)
                continue
            # Backward slip is forward slip of (-lam, -eta) (derivations/edge_symmetry.py).
            lam_o, eta_o = direction * edge_lam, direction * eta
            b = eq22(mu, lam_o, eta_o, a1, a2, L_I1, L_I2)
            assert float(row[prefix + "b_paper"]) == pytest.approx(b, rel=1e-12), row["case"]
            first = a1 * eq28(mu, lam_o, eta_o, a1, P2 - P1, slope1)
            assert float(row[prefix + "b_first_order"]) == pytest.approx(first, rel=1e-12)
            checked += 1
    assert checked >= 6


def test_good_rows_carry_exactly_the_doubles_and_warnings_of_slip_zone(swept):
    """The sweep writes what the API computes, every column, to the last bit (shortest
    round-trip text reads back to the same double)."""
    _, rows = swept
    for row in (row for row in rows if not row["error"]):
        expected = expected_row(row, "both")
        for prefix, result in (("", expected), ("left_", expected.left)):
            data = result.to_dict()
            data.update(data.pop("validity"))
            for key in edge_columns():
                written = row[prefix + key]
                if key == "warnings":
                    assert written == WARNING_SEPARATOR.join(data[key]), (row["case"], key)
                elif data[key] is None:
                    assert written == "", (row["case"], key)
                else:
                    assert float(written) == data[key], (row["case"], prefix + key)


def test_rows_exercise_every_warning_kind(swept):
    _, rows = swept
    warnings = " ".join(row["warnings"] + row["left_warnings"] for row in rows)
    for start in ("no slip at this edge", "eq24 > 0.1"):
        assert start in warnings
    tension = next(row for row in rows if row["case"] == "tension")
    assert tension["b_exact"] == "" and tension["eta"] != "0"


def test_chunked_and_single_chunk_sweeps_write_the_same_bytes(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text(CASES)
    one = sweep_file(cases, LAW, tmp_path / "one.csv", mu=DEFAULT_MU, progress=False)
    many = sweep_file(
        cases, LAW, tmp_path / "many.csv", mu=DEFAULT_MU, chunk_rows=3, progress=False
    )
    assert (tmp_path / "one.csv").read_bytes() == (tmp_path / "many.csv").read_bytes()
    assert one.invalid == many.invalid and one.invalid


def test_one_edge_gives_only_its_columns(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text("P1,Q1,P2,Q2\n100,0,105,1\n")
    sweep_file(cases, LAW, tmp_path / "left.csv", mu=0.1, edge="left", progress=False)
    header = (tmp_path / "left.csv").read_text().splitlines()[0].split(",")
    assert header == ["P1", "Q1", "P2", "Q2", *("left_" + key for key in edge_columns()), "error"]
    (row,) = read(tmp_path / "left.csv")
    left = slip_zone(LAW, LoadCycle(100, 0, 105, 1), 0.1, edge="left")
    assert float(row["left_b"]) == left.b and float(row["left_lam"]) == -0.2


def test_a_file_wide_problem_is_one_input_error(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text("P1,Q1,P2\n100,0,105\n")
    with pytest.raises(InputError, match=r"^cases: .*line 1: the header has no column Q2"):
        sweep_file(cases, LAW, tmp_path / "out.csv", mu=0.1)
    cases.write_text("P1,Q1,P2,Q2\n100,0,105,1\n")
    with pytest.raises(InputError, match=r"^mu: is required: give --mu or a mu column"):
        sweep_file(cases, LAW, tmp_path / "out.csv")


def test_an_empty_mu_cell_without_a_default_is_a_row_error(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text("P1,Q1,P2,Q2,mu\n100,0,105,1,\n100,0,105,1,0.1\n")
    summary = sweep_file(cases, LAW, tmp_path / "out.csv", progress=False)
    assert summary.invalid == [(2, "mu: missing (give --mu or a value in the mu column)")]


def test_many_rows_breaking_one_rule_each_get_the_api_message_with_their_value(tmp_path):
    cases = tmp_path / "cases.csv"
    P1 = 100 + np.arange(60)
    cases.write_text("P1,Q1,P2,Q2\n" + "".join(f"{p},0,{p - 1},1\n" for p in P1))
    summary = sweep_file(cases, LAW, tmp_path / "out.csv", mu=0.1, progress=False)
    assert len(summary.invalid) == 60
    for (line, message), p in zip(summary.invalid, P1, strict=True):
        with pytest.raises(InputError) as raised:
            LoadCycle(float(p), 0, float(p - 1), 1)
        assert message == str(raised.value), line


def test_progress_bar_only_when_asked_or_on_a_terminal(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text("P1,Q1,P2,Q2\n100,0,105,1\n100,0,106,1\n")
    quiet, loud = io.StringIO(), io.StringIO()
    sweep_file(cases, LAW, tmp_path / "a.csv", mu=0.1, stream=quiet)  # StringIO is no tty
    sweep_file(cases, LAW, tmp_path / "b.csv", mu=0.1, stream=loud, progress=True)
    assert quiet.getvalue() == ""
    assert "2/2 rows" in loud.getvalue()


def test_parquet_output_holds_the_same_numbers_text_and_nulls_as_the_csv(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    cases = tmp_path / "cases.csv"
    cases.write_text(CASES)
    sweep_file(cases, LAW, tmp_path / "out.csv", mu=DEFAULT_MU, progress=False)
    sweep_file(cases, LAW, tmp_path / "out.parquet", mu=DEFAULT_MU, progress=False)
    table = pq.read_table(tmp_path / "out.parquet").to_pylist()
    rows = read(tmp_path / "out.csv")
    assert len(table) == len(rows)
    for parquet, csv_row in zip(table, rows, strict=True):
        assert parquet["b"] == (float(csv_row["b"]) if csv_row["b"] else None)
        assert (parquet["warnings"] or "") == csv_row["warnings"]
        assert (parquet["error"] or "") == csv_row["error"] and parquet["case"] == csv_row["case"]


def test_parquet_keeps_the_numbers_it_read_as_numbers_and_csv_their_text(tmp_path):
    """The copied cycle columns were strings in Parquet (pandas arithmetic on them raised
    TypeError).  They are float64 there -- the doubles the sweep computed with, null where a
    field is empty, not a number, or its row has the wrong number of fields -- and arithmetic
    works on them; other input columns stay text; CSV copies every field as written."""
    pa = pytest.importorskip("pyarrow")
    pq = pytest.importorskip("pyarrow.parquet")
    import pyarrow.compute as pc

    cases = tmp_path / "cases.csv"
    cases.write_text(CASES.replace("fig5,100,0,105,1", "fig5,1e2,0,105.0,1"))
    sweep_file(cases, LAW, tmp_path / "out.parquet", mu=DEFAULT_MU, progress=False)
    sweep_file(cases, LAW, tmp_path / "out.csv", mu=DEFAULT_MU, progress=False)
    table = pq.read_table(tmp_path / "out.parquet")
    numeric = ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2", "mu")
    assert all(table.schema.field(name).type == pa.float64() for name in numeric)
    assert pa.types.is_string(table.schema.field("case").type) or pa.types.is_large_string(
        table.schema.field("case").type
    )
    listed = table.to_pylist()
    rows = {row["case"]: row for row in listed}
    assert (rows["fig5"]["P1"], rows["fig5"]["P2"]) == (100.0, 105.0)
    assert rows["text"]["Q1"] is None and "Q1: 'abc' is not a number" in rows["text"]["error"]
    assert rows["default-mu"]["sigma1"] is None and rows["default-mu"]["mu"] is None
    short = listed[10]  # "short,100,0,105": every field of a wrong field count is empty
    assert short["P1"] is None and short["error"].startswith("line has 4 fields")
    assert rows["nan-load"]["P1"] is None
    assert rows["tension"]["sigma2"] == 0.9
    doubled = pc.multiply(table["P2"], 2).to_pylist()  # arithmetic on the column works
    assert doubled[0] == 210.0
    # CSV: the same rows, every input field as written
    text = {row["case"]: row for row in read(tmp_path / "out.csv")}
    assert (text["fig5"]["P1"], text["fig5"]["P2"]) == ("1e2", "105.0")
    assert text["text"]["Q1"] == "abc" and text["default-mu"]["sigma1"] == ""


def test_an_output_that_is_the_input_is_refused_and_the_input_kept(tmp_path):
    cases = tmp_path / "cases.csv"
    cases.write_text(CASES)
    with pytest.raises(InputError, match=r"^out: .*is also an input \(the cases"):
        sweep_file(cases, LAW, cases, mu=DEFAULT_MU)
    assert cases.read_text() == CASES


def test_an_interrupted_sweep_leaves_no_results_file(tmp_path, monkeypatch):
    from asymslip.sweep import chunk

    cases = tmp_path / "cases.csv"
    cases.write_text(CASES)
    calls = []

    def interrupted(*args, **kwargs):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt  # Ctrl-C during the second chunk
        return original(*args, **kwargs)

    original = chunk.evaluate_chunk  # the evaluation of every way of running a sweep
    monkeypatch.setattr(chunk, "evaluate_chunk", interrupted)
    with pytest.raises(KeyboardInterrupt):
        sweep_file(cases, LAW, tmp_path / "out.csv", mu=DEFAULT_MU, chunk_rows=4, progress=False)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cases.csv"]


def test_sweep_with_a_table_law_warns_of_loads_outside_the_table(tmp_path):
    from asymslip.laws.table import TableLaw

    P = np.linspace(90.0, 110.0, 6)
    law = TableLaw(P, np.sqrt(4 * P / np.pi))
    cases = tmp_path / "cases.csv"
    cases.write_text("P1,Q1,P2,Q2\n100,0,105,1\n100,0,115,3\n")
    sweep_file(cases, law, tmp_path / "out.csv", mu=0.1, edge="right", progress=False)
    inside, outside = read(tmp_path / "out.csv")
    assert inside["warnings"] == ""
    assert outside["warnings"].endswith(
        "P2 is outside the table's loads [90, 110] (table): a(P) there is the end "
        "power law, extrapolated"
    )


def test_cli_sweep_and_derive_through_the_registered_commands(tmp_path, capsys):
    from asymslip.cli import main

    law_file = tmp_path / "hertz_user.py"
    assert (
        main(
            [
                "derive",
                "--P-of-a",
                "pi*E_star*a**2/(4*R)",
                "--params",
                "R E_star",
                "--name",
                "hertz_user",
                "--out",
                str(law_file),
            ]
        )
        == 0
    )
    assert law_file.exists()
    cases = tmp_path / "cases.csv"
    cases.write_text(CASES)
    status = main(
        [
            "sweep",
            str(cases),
            "--law",
            "module",
            "--module",
            str(law_file),
            "--param",
            "R=1",
            "--param",
            "E_star=1",
            "--mu",
            "0.25",
            "--out",
            str(tmp_path / "out.csv"),
        ]
    )
    assert status == 1  # some rows are invalid
    report = capsys.readouterr().err
    assert f"{len(BAD_LINES)} invalid rows" in report and "line 3: P2: must exceed P1" in report
    rows = read(tmp_path / "out.csv")
    (a1, L_I1, _), (a2, L_I2, _) = _hertz_transcribed(100.0), _hertz_transcribed(105.0)
    assert rows[0]["case"] == "fig5"  # (22) with (29), (31), lam = 0.2, mu = 0.1 from the row
    expected = eq22(0.1, 0.2, 0.0, a1, a2, L_I1, L_I2)
    assert float(rows[0]["b_paper"]) == pytest.approx(expected, rel=1e-13)


# --- the generated kernels work on chunked dask arrays unchanged --------------------------
def test_generated_kernels_give_the_numpy_values_on_chunked_dask_arrays():
    da = pytest.importorskip("dask.array")
    rng = np.random.default_rng(3)
    n = 10_000
    a1 = rng.uniform(1, 10, n)
    da_ = a1 * rng.uniform(1e-6, 0.05, n)
    inputs = {
        "mu": rng.uniform(0.05, 1, n),
        "lam": rng.uniform(-2, 2, n),
        "eta": rng.uniform(-0.05, 0.05, n),
        "a1": a1,
        "a2": a1 + da_,
        "da": da_,
        "L_I1": rng.uniform(1, 3, n),
        "x": a1 * rng.uniform(0.5, 1.2, n),
        "E_star": rng.uniform(0.5, 2, n),
    }
    inputs["L_I2"] = inputs["L_I1"] * rng.uniform(0.99, 1.01, n)
    stick_args = ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2")
    inputs["b"] = gen.stick_boundary_proportional(*(inputs[k] for k in stick_args))
    inputs["L_II1"] = gen.shear_edge_multiplier_proportional(
        inputs["lam"], inputs["eta"], a1, inputs["L_I1"]
    )
    inputs["L_II2"] = gen.shear_edge_multiplier_proportional(
        inputs["lam"], inputs["eta"], inputs["a2"], inputs["L_I2"]
    )
    chunked = {key: da.from_array(value, chunks=2_500) for key, value in inputs.items()}
    kernels = {
        gen.stick_boundary_proportional: ("mu", "lam", "eta", "a1", "a2", "L_I1", "L_I2"),
        gen.slip_zone_width: ("mu", "lam", "eta", "a1", "da", "L_I1", "L_I2"),
        gen.dislocation_density: ("x", "b", "a1", "mu", "L_I1", "L_I2", "L_II1", "L_II2", "E_star"),
        gen.hertz_half_width: ("a1", "mu", "E_star"),
    }
    for kernel, names in kernels.items():
        lazy = kernel(*(chunked[name] for name in names))
        assert isinstance(lazy, da.Array), kernel.__name__
        assert lazy.chunks == ((2_500,) * 4,)
        assert np.array_equal(lazy.compute(), kernel(*(inputs[name] for name in names))), (
            kernel.__name__
        )


@pytest.mark.parametrize(
    "text",
    [
        "P1,Q1,P2,Q2\n100,0,105\n",
        "P1,Q1,P2,Q2\n1,000,0,105,1\n",
        'P1,Q1,P2,Q2\n"100",0,105\n1,000,0,105,1\n',
    ],
    ids=["short", "long", "quoted, both"],
)
def test_rows_of_the_wrong_field_count_give_the_same_result_with_or_without_pyarrow(
    tmp_path, monkeypatch, text
):
    """With no well-formed row, the pyarrow reader ended in a traceback ("Empty CSV file")
    while the NumPy one marked every row: now both mark them, byte for byte the same file."""
    from asymslip.files import arrow

    if not arrow.available():
        pytest.skip("pyarrow not installed")
    cases = tmp_path / "cases.csv"
    cases.write_text(text)
    with_arrow = sweep_file(cases, LAW, tmp_path / "arrow.csv", mu=DEFAULT_MU, progress=False)
    monkeypatch.setattr(arrow, "available", lambda: False)
    with_numpy = sweep_file(cases, LAW, tmp_path / "numpy.csv", mu=DEFAULT_MU, progress=False)
    assert (tmp_path / "arrow.csv").read_bytes() == (tmp_path / "numpy.csv").read_bytes()
    assert with_arrow.invalid == with_numpy.invalid and all(
        re.match(r"line has [35] fields, the header has 4", message)
        for _, message in with_arrow.invalid
    )
