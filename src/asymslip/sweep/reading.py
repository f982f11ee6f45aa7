"""Reading a cases file: header, rows, 1-based line numbers, per-row parse errors (NumPy only).

The CSV is parsed by NumPy's C reader (``np.loadtxt``) with a per-line fallback that locates
bad fields; a bad row is reported, not fatal.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from .columns import CYCLE_COLUMNS, DEFAULTS, REQUIRED_COLUMNS, output_columns

FloatArray = NDArray[np.float64]


@dataclass
class Chunk:
    """Rows of one chunk: their text, line numbers, parsed values and errors so far."""

    lines: list[bytes]
    line_numbers: NDArray[np.int64]
    values: dict[str, FloatArray]
    errors: list[str | None]


def read_header(path: Path) -> tuple[list[str], list[bytes], NDArray[np.int64]]:
    try:
        data = path.read_bytes()
    except OSError as error:
        raise InputError("cases", f"cannot read {path}: {error.strerror}") from None
    lines = data.replace(b"\r\n", b"\n").split(b"\n")
    first = next((i for i, line in enumerate(lines) if line.strip()), None)
    if first is None:
        raise InputError("cases", f"{path} is empty: it needs a header row naming P1, Q1, P2, Q2")
    try:
        header = [name.strip() for name in lines[first].decode("utf-8").split(",")]
    except UnicodeDecodeError:
        raise InputError("cases", f"{path}: line {first + 1}: the header is not text") from None
    missing = [name for name in REQUIRED_COLUMNS if name not in header]
    if missing:
        raise InputError("cases", f"{path}: line {first + 1}: the header has no column "
                         f"{', '.join(missing)} (found {', '.join(header)})")  # fmt: skip
    repeated = sorted({name for name in header if header.count(name) > 1})
    if repeated:
        raise InputError("cases", f"{path}: column {', '.join(repeated)} appears twice")
    clash = sorted(set(header) & set(output_columns([], "both")))
    if clash:
        raise InputError("cases", f"{path}: input column {', '.join(clash)} has the name of an "
                         "output column; rename it")  # fmt: skip
    body = lines[first + 1 :]
    numbers = np.arange(first + 2, first + 2 + len(body), dtype=np.int64)
    keep = [i for i, line in enumerate(body) if line.strip()]
    if len(keep) != len(body):
        body = [body[i] for i in keep]
        numbers = numbers[keep]
    return header, body, numbers


def parse_chunk(lines: list[bytes], numbers: NDArray[np.int64], header: list[str],
                 default_mu: float | None) -> Chunk:  # fmt: skip
    """Parse the numeric columns; per-line fallback when NumPy's reader meets a bad field."""
    wanted = [name for name in (*CYCLE_COLUMNS, "mu") if name in header]
    index = [header.index(name) for name in wanted]
    commas = len(header) - 1
    well_formed = np.array([line.count(b",") == commas for line in lines], dtype=bool)
    errors: list[str | None] = [None] * len(lines)
    table = None
    if well_formed.all():
        try:
            table = np.loadtxt(io.BytesIO(b"\n".join(lines)), delimiter=",", usecols=index,
                               dtype=np.float64, comments=None, ndmin=2)  # fmt: skip
        except ValueError:
            table = None  # a bad field somewhere: find it line by line below
        if table is not None and table.shape[0] != len(lines):
            table = None
    if table is None:
        table = np.full((len(lines), len(wanted)), np.nan)
        for row, line in enumerate(lines):
            if not well_formed[row]:
                fields = line.count(b",") + 1
                errors[row] = (f"line has {fields} fields, the header has {len(header)}: "
                               f"{line.decode('utf-8', 'replace')!r}")  # fmt: skip
                continue
            fields = line.split(b",")
            for column, (name, position) in enumerate(zip(wanted, index, strict=True)):
                text = fields[position].strip()
                if not text and (name in DEFAULTS or name == "mu"):
                    continue  # an empty optional cell takes the default
                try:
                    table[row, column] = float(text)
                except ValueError:
                    shown = text.decode("utf-8", "replace")
                    errors[row] = (f"{name}: {shown!r} is not a number" if text
                                   else f"{name}: missing value")  # fmt: skip
                    break
    values = {name: table[:, column] for column, name in enumerate(wanted)}
    missing_mu = np.nan if default_mu is None else default_mu
    for name, default in (*DEFAULTS.items(), ("mu", missing_mu)):
        if name not in values:
            values[name] = np.full(len(lines), default)
            continue
        empty = _empty_cells(lines, header, name, values[name])
        values[name][empty] = default
        if name == "mu" and default_mu is None:
            for row in np.flatnonzero(empty):
                errors[row] = errors[row] or "mu: missing (give --mu or a value in the mu column)"
    return Chunk(lines, numbers, values, errors)


def _empty_cells(lines: list[bytes], header: list[str], name: str,
                 parsed: FloatArray) -> NDArray[np.bool_]:  # fmt: skip
    """True where the cell of column ``name`` is blank (looked at only where parsing gave NaN)."""
    position, commas = header.index(name), len(header) - 1
    empty = np.zeros(len(lines), dtype=bool)
    for row in np.flatnonzero(np.isnan(parsed)):
        line = lines[row]
        empty[row] = line.count(b",") == commas and not line.split(b",")[position].strip()
    return empty
