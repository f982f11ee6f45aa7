"""Doubles as text: shortest, read back to the identical double, in pyarrow's layout."""

from __future__ import annotations

import io
import struct

import numpy as np
import pytest

from asymslip.files.numbers import WIDTH, format_doubles

ADVERSARIAL = [
    0.0,
    -0.0,
    5e-324,
    -5e-324,
    1e-323,
    2.2250738585072014e-308,
    2.225073858507201e-308,
    1.7976931348623157e308,
    -1.7976931348623157e308,
    1e308,
    1e-308,
    0.1,
    0.2,
    0.3,
    1 / 3,
    2 / 3,
    1e16,
    1e15,
    1e21,
    1e22,
    1e23,
    9.999999999999999e22,
    1e-7,
    1e-6,
    1e-5,
    1e9,
    1e10,
    100.0,
    123456789.5,
    1234567890.5,
    9007199254740993.0,
    9007199254740992.0,
    2.0**-25,
    2.0**60,
    2.0**-1022,
    2.0**-1074,
    5e-310,
    4.35,
    0.000123456789,
    1.5,
    2.5,
    1e-300,
    123e300,
    np.pi,
]


def texts(values) -> list[str]:
    block = format_doubles(values)
    return [row[row != 0].tobytes().decode() for row in block]


def random_doubles(count: int, seed: int) -> np.ndarray:
    """Every finite double is as likely as any other: random bit patterns, NaN/inf dropped."""
    bits = np.random.default_rng(seed).integers(0, 2**64, count, dtype=np.uint64)
    values = bits.view(np.float64)
    return values[np.isfinite(values)]


def shortest_in_arrow_layout(value: float) -> str:
    """The expected text, written independently: the digits of Python's repr (shortest
    round-trip), laid out by double-conversion's rule (fixed for -6 <= exponent < 10)."""
    if value == 0:
        return "-0" if struct.pack(">d", value)[0] & 0x80 else "0"
    sign = "-" if value < 0 else ""
    mantissa, _, power = repr(abs(value)).partition("e")
    whole, _, part = mantissa.partition(".")
    digits = (whole + part).lstrip("0")
    exponent = (
        int(power or 0) + len(whole.lstrip("0")) - 1
        if whole.strip("0")
        else int(power or 0) - (len(part) - len(part.lstrip("0"))) - 1
    )
    digits = digits.rstrip("0")
    if -6 <= exponent < 10:
        if exponent < 0:
            return sign + "0." + "0" * (-exponent - 1) + digits
        if len(digits) <= exponent + 1:
            return sign + digits + "0" * (exponent + 1 - len(digits))
        return sign + digits[: exponent + 1] + "." + digits[exponent + 1 :]
    shown = digits[0] + ("." + digits[1:] if len(digits) > 1 else "")
    return f"{sign}{shown}e{'+' if exponent >= 0 else '-'}{abs(exponent)}"


def test_adversarial_doubles_read_back_identically():
    values = np.array(ADVERSARIAL)
    back = np.array([float(text) for text in texts(values)])
    assert back.view(np.uint64).tolist() == values.view(np.uint64).tolist()  # sign of 0 too


def test_random_doubles_of_every_exponent_read_back_identically():
    values = random_doubles(40_000, seed=1)
    back = np.array([float(text) for text in texts(values)])
    assert np.array_equal(back.view(np.uint64), values.view(np.uint64))


def test_text_is_the_shortest_round_trip_digits_in_arrows_layout():
    values = np.concatenate(
        [
            ADVERSARIAL,
            random_doubles(20_000, seed=2),
            np.ldexp(1.0, np.arange(-1074, 1024)),  # every power of two
            np.arange(1.0, 5_001.0),
            np.round(np.linspace(0, 1, 5001), 4),
        ]
    )
    expected = [shortest_in_arrow_layout(value) for value in values.tolist()]
    assert texts(values) == expected


def test_zero_infinities_and_no_value():
    assert texts([0.0, -0.0, np.inf, -np.inf, np.nan]) == ["0", "-0", "inf", "-inf", ""]


def test_formats_into_a_given_block():
    block = np.zeros((3, WIDTH + 1), np.uint8)
    format_doubles([1.5, -2e-7, 1e100], out=block[:, :WIDTH])
    assert [row[row != 0].tobytes() for row in block] == [b"1.5", b"-2e-7", b"1e+100"]


def test_pyarrow_csv_writer_round_trips_every_double():
    """What pyarrow.csv.write_csv does with doubles, tested rather than assumed: every double
    (subnormals, -0.0, 1e308, 5e-324, random bit patterns) reads back identically."""
    pa = pytest.importorskip("pyarrow")
    pcsv = pytest.importorskip("pyarrow.csv")
    values = np.concatenate([ADVERSARIAL, random_doubles(40_000, seed=3)])
    sink = io.BytesIO()
    pcsv.write_csv(pa.table({"x": values}), sink, pcsv.WriteOptions(include_header=False))
    back = np.array([float(line) for line in sink.getvalue().split(b"\n")[:-1]])
    assert np.array_equal(back.view(np.uint64), values.view(np.uint64))


def test_numpy_formatter_gives_pyarrows_bytes():
    pa = pytest.importorskip("pyarrow")
    pcsv = pytest.importorskip("pyarrow.csv")
    values = np.concatenate(
        [
            ADVERSARIAL,
            random_doubles(60_000, seed=4),
            np.ldexp(1.0, np.arange(-1074, 1024)),
            [np.inf, -np.inf],
        ]
    )
    sink = io.BytesIO()
    pcsv.write_csv(pa.table({"x": values}), sink, pcsv.WriteOptions(include_header=False))
    assert sink.getvalue().decode().split("\n")[:-1] == texts(values)
