"""Cases files: 1-based lines as an editor shows them, bad rows located, both engines alike."""

from __future__ import annotations

import numpy as np
import pytest

from asymslip.errors import InputError
from asymslip.files import arrow, read_table

ENGINES = [
    "numpy",
    pytest.param(
        "pyarrow", marks=pytest.mark.skipif(not arrow.available(), reason="pyarrow not installed")
    ),
]
REQUIRED = ["P1", "Q1", "P2", "Q2"]
NUMERIC = ["sigma1", "sigma2", "mu"]

CASES = """\
# cases for the sweep (line 1 is a comment)

case,P1,Q1,P2,Q2,sigma1,sigma2,mu
fig5,100,0,105,1,0,0,0.1
text,100,abc,105,1,0,0,0.1
  # an indented comment
blank-optional,100,0,103,2,,,
"quoted, label",100, 1e2 ,105,1,0,0,0.1
"two
lines",100,0,105,1,0,0,0.1
short,100,0,105
missing,,0,105,1,0,0,0.1
odd-nan,100,0,105,1,0,0,nan(1)
nan-load,nan,-inf,105,1e400,0,0,0.1


"""
LINES = [4, 5, 7, 8, 9, 11, 12, 13, 14]
ERRORS = {
    1: "Q1: 'abc' is not a number",
    5: "line has 4 fields, the header has 8: 'short,100,0,105'",
    6: "P1: missing value",
    7: "mu: 'nan(1)' is not a number",
}


def read(tmp_path, text: str | bytes, engine: str, **options):
    path = tmp_path / "cases.csv"
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    return read_table(path, required=REQUIRED, numeric=NUMERIC, engine=engine, **options)


@pytest.mark.parametrize("engine", ENGINES)
def test_rows_carry_their_file_line_counting_header_blank_and_comment_lines(tmp_path, engine):
    table = read(tmp_path, CASES, engine)
    assert table.line.tolist() == LINES
    assert table.comments == [1, 6]
    assert table.header == ["case", "P1", "Q1", "P2", "Q2", "sigma1", "sigma2", "mu"]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("form", ["crlf", "bom", "crlf+bom"])
def test_crlf_and_a_byte_order_mark_change_nothing(tmp_path, engine, form):
    text = CASES.replace("\n", "\r\n") if "crlf" in form else CASES
    data = ("\ufeff" + text if "bom" in form else text).encode()
    table = read(tmp_path, data, engine)
    assert table.line.tolist() == LINES and table.errors == ERRORS
    assert table.text["case"][4] == ("two\r\nlines" if "crlf" in form else "two\nlines")
    assert table.values["P2"][0] == 105.0


@pytest.mark.parametrize("engine", ENGINES)
def test_bad_fields_are_located_and_the_other_rows_kept(tmp_path, engine):
    table = read(tmp_path, CASES, engine)
    assert table.errors == ERRORS
    assert table.bad.tolist() == [False, True, False, False, False, True, True, True, False]
    assert np.isnan(table.values["Q1"][1]) and table.values["P1"][1] == 100.0


@pytest.mark.parametrize("engine", ENGINES)
def test_numbers_empty_cells_and_text(tmp_path, engine):
    table = read(tmp_path, CASES, engine)
    assert table.values["Q1"][3] == 100.0  # " 1e2 ": spaces around a number are fine
    assert table.text["Q1"][3] == " 1e2 "  # and the text is kept as written
    assert table.text["case"][3] == "quoted, label"
    assert table.empty["sigma1"].tolist() == [False, False, True] + [False] * 6
    assert np.isnan(table.values["mu"][2]) and table.empty["mu"][2]
    last = {name: table.values[name][8] for name in REQUIRED}
    assert np.isnan(last["P1"]) and last["Q1"] == -np.inf and last["Q2"] == np.inf
    assert table.text["P1"][5] == "" and table.values["P1"][5] != table.values["P1"][5]


def test_both_engines_read_the_same_table(tmp_path):
    """Random rows of numbers written every way people write them, and of bad tokens: both
    engines give the same values (bit for bit), empty cells, text and errors."""
    if not arrow.available():
        pytest.skip("pyarrow not installed")
    rng = np.random.default_rng(5)
    good = [
        "1",
        "-2.5",
        "+3",
        ".5",
        "5.",
        "1e5",
        "1E-5",
        "1e+05",
        "-0",
        " 7 ",
        "\t8",
        "inf",
        "-Infinity",
        "NaN",
        "+nan",
        "0001.2500",
        "1e400",
        "1e-400",
        repr(float(rng.standard_normal())),
    ]
    bad = ["abc", "1_000", "0x10", "1d5", "nan(2)", "1e", "e5", "--1", "1.2.3", "١", "1 2", "."]
    tokens = good + bad + [""]
    rows = ["P1,Q1,P2,Q2,mu,label"]
    for i in range(3000):
        fields = [tokens[j] for j in rng.integers(0, len(tokens), 5)]
        rows.append(",".join(fields) + f",row{i}")
        if i % 500 == 0:
            rows.append("")
    path = tmp_path / "fuzz.csv"
    path.write_text("\n".join(rows) + "\n")
    tables = [
        read_table(path, required=REQUIRED, numeric=["mu"], engine=engine)
        for engine in ("numpy", "pyarrow")
    ]
    numpy, pyarrow = tables
    assert numpy.errors == pyarrow.errors and len(numpy.errors) > 2000
    assert numpy.line.tolist() == pyarrow.line.tolist()
    for name in [*REQUIRED, "mu"]:
        assert np.array_equal(
            numpy.values[name].view(np.uint64) * ~np.isnan(numpy.values[name]),
            pyarrow.values[name].view(np.uint64) * ~np.isnan(pyarrow.values[name]),
        )
        assert np.array_equal(np.isnan(numpy.values[name]), np.isnan(pyarrow.values[name]))
        assert numpy.empty[name].tolist() == pyarrow.empty[name].tolist()
        assert numpy.text[name].to_list() == pyarrow.text[name].to_list()


@pytest.mark.parametrize("engine", ENGINES)
def test_numbers_are_read_correctly_rounded(tmp_path, engine):
    values = np.random.default_rng(6).standard_normal((2000, 4)) * 1e-3
    lines = ["P1,Q1,P2,Q2"] + [",".join(f"{v:.17g}" for v in row) for row in values]
    path = tmp_path / "c.csv"
    path.write_text("\n".join(lines))  # no final line break
    table = read_table(path, required=REQUIRED, engine=engine)
    for index, name in enumerate(REQUIRED):
        assert np.array_equal(table.values[name], values[:, index])
    assert table.line[-1] == 2001


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize(
    ("text", "message"),
    [
        (b"", r"^cases: .*cases\.csv: has no header: it needs a header row naming P1, Q1, P2, Q2$"),
        (b"\n# only a comment\n\n", r"has no header"),
        (
            b"P1,Q1,P2\n1,2,3\n",
            r"cases\.csv: line 1: the header has no column Q2 \(found P1, Q1, P2\)",
        ),
        (b"\n\nP1,Q1,P2,Q2,P1\n", r"cases\.csv: line 3: column P1 appears twice in the header"),
        (b"P1,,Q1,P2,Q2\n", r"line 1: column 2 of the header has no name"),
        (b'P1,Q1,P2,Q2\n1,2,3,4\n5,"6,7,8\n', r"line 3: a quoted field is never closed"),
        (b"P1,Q1,P2,Q2\n1,2,3,4\n1,2\x00,3,4\n", r"line 3: holds a NUL byte"),
        (b"P1,Q1,P2,Q2\n1,2,3,4\n\xff,2,3,4\n", r"line 3: is not UTF-8 text"),
    ],
)
def test_file_level_problems_raise_naming_the_file_and_line(tmp_path, engine, text, message):
    with pytest.raises(InputError, match=message) as raised:
        read(tmp_path, text, engine)
    assert raised.value.parameter == "cases"


def test_an_unreadable_file_names_the_option(tmp_path):
    with pytest.raises(InputError, match=r"^table: cannot read .*missing\.csv: No such file"):
        read_table(tmp_path / "missing.csv", option="table")


@pytest.mark.parametrize("engine", ENGINES)
def test_chunks_keep_lines_errors_and_text(tmp_path, engine):
    table = read(tmp_path, CASES, engine)
    parts = list(table.chunks(4))
    assert [len(part) for part in parts] == [4, 4, 1]
    assert parts[1].line.tolist() == LINES[4:8]
    assert parts[1].errors == {1: ERRORS[5], 2: ERRORS[6], 3: ERRORS[7]}
    assert parts[1].text["case"].to_list() == ["two\nlines", "", "missing", "odd-nan"]


WRONG_FIELD_COUNTS = {
    "one short row": ("P1,Q1,P2,Q2\n100,0,105\n", {0: "line has 3 fields, the header has 4"}),
    "one long row": ("P1,Q1,P2,Q2\n1,000,0,105,1\n", {0: "line has 5 fields, the header has 4"}),
    "both, quoted": (
        'P1,Q1,P2,Q2\n"100",0,105\n1,000,0,105,1\n',
        {0: "line has 3 fields, the header has 4", 1: "line has 5 fields, the header has 4"},
    ),
    "both, after a comment": (
        "# c\nP1,Q1,P2,Q2\n100,0,105\n\n1,000,0,105,1",
        {0: "line has 3 fields, the header has 4", 1: "line has 5 fields, the header has 4"},
    ),
}


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("name", list(WRONG_FIELD_COUNTS))
def test_a_file_whose_every_row_has_the_wrong_field_count_gives_each_row_its_error(
    tmp_path, engine, name
):
    """pyarrow refuses to parse an empty body ("Empty CSV file"): with no well-formed row
    left, the reader must still mark every row, as the NumPy engine does (issue 17)."""
    text, expected = WRONG_FIELD_COUNTS[name]
    table = read(tmp_path, text, engine)
    assert {row: message.split(":")[0] for row, message in table.errors.items()} == expected
    assert all(np.isnan(table.values["P1"])) and table.text["P1"].to_list() == [""] * len(expected)
