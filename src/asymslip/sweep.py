"""``asymslip sweep``: everything ``slip-zone`` reports, for every load cycle of a CSV file.

One cycle per row (columns ``P1, Q1, P2, Q2``; optional ``sigma1, sigma2`` (default 0) and
``mu`` (overrides ``--mu``); other columns are carried through untouched).  The rows are
evaluated in chunks with the vectorised :func:`asymslip.edge_solution.edge_quantities`; each
row is checked by the rules of :class:`LoadCycle` and :func:`slip_zone`, and a row that breaks
one is written with its reason in the ``error`` column (the message the API would raise for
that row) instead of stopping the others.  Nothing is dropped: every non-blank input line
gives one output line, in order.

Output columns: the input columns as given, then the JSON keys of ``slip-zone`` flattened
(``validity.eq24 -> eq24``; ``warnings`` joined by :data:`WARNING_SEPARATOR`), the left edge's
prefixed ``left_``, then ``error``.  Numbers are written with 17 significant digits, which
read back to the same doubles.

Runtime needs NumPy only: the CSV is parsed by NumPy's C reader (``np.loadtxt``) with a
per-line fallback that locates bad fields, and written by a vectorised formatter.
"""

from __future__ import annotations

import dataclasses
import io
import multiprocessing
import os
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal, TextIO

import numpy as np
from numpy.typing import NDArray

from .cycle import LoadCycle
from .edge_solution import (
    INTERNAL_KEYS,
    VALIDITY_MEANING,
    SlipZoneResult,
    denominator_vanishes,
    edge_quantities,
    edge_warnings,
    slip_zone,
)
from .errors import InputError
from .laws.base import ContactLaw

FloatArray = NDArray[np.float64]
Edges = Literal["right", "left", "both"]

#: Input columns the sweep reads; the first four are required.
CYCLE_COLUMNS = ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2")
REQUIRED_COLUMNS = ("P1", "Q1", "P2", "Q2")
DEFAULTS = {"sigma1": 0.0, "sigma2": 0.0}
#: Rows evaluated at once: large enough to amortise NumPy's per-call cost, small enough that
#: a chunk's text and arrays stay well under 100 MB.
CHUNK_ROWS = 100_000
#: Joins a row's warnings.  Not ";": one of the API's warning texts contains a semicolon.
WARNING_SEPARATOR = " | "
#: Flagged rows whose message is taken from the API itself; the rest reuse its rule text.
_API_MESSAGES_PER_RULE = 20


# --- output columns -------------------------------------------------------------------------
def edge_columns() -> list[str]:
    """The flattened keys of one edge's :class:`SlipZoneResult`, in JSON order."""
    columns: list[str] = []
    for item in dataclasses.fields(SlipZoneResult):
        if item.name == "left":
            continue
        if item.name == "validity":
            columns.extend(VALIDITY_MEANING)
        else:
            columns.append(item.name)
    return columns


def edges_of(edge: Edges) -> list[str]:
    return {"right": ["right"], "left": ["left"], "both": ["right", "left"]}[edge]


def output_columns(input_columns: Sequence[str], edge: Edges) -> list[str]:
    prefixes = {"right": "", "left": "left_"}
    names = list(input_columns)
    for side in edges_of(edge):
        names.extend(prefixes[side] + name for name in edge_columns())
    return [*names, "error"]


# --- reading ----------------------------------------------------------------------------------
@dataclass
class _Chunk:
    """Rows of one chunk: their text, line numbers, parsed values and errors so far."""

    lines: list[bytes]
    line_numbers: NDArray[np.int64]
    values: dict[str, FloatArray]
    errors: list[str | None]


def _read_header(path: Path) -> tuple[list[str], list[bytes], NDArray[np.int64]]:
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


def _parse_chunk(lines: list[bytes], numbers: NDArray[np.int64], header: list[str],
                 default_mu: float | None) -> _Chunk:  # fmt: skip
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
    return _Chunk(lines, numbers, values, errors)


def _empty_cells(lines: list[bytes], header: list[str], name: str,
                 parsed: FloatArray) -> NDArray[np.bool_]:  # fmt: skip
    """True where the cell of column ``name`` is blank (looked at only where parsing gave NaN)."""
    position, commas = header.index(name), len(header) - 1
    empty = np.zeros(len(lines), dtype=bool)
    for row in np.flatnonzero(np.isnan(parsed)):
        line = lines[row]
        empty[row] = line.count(b",") == commas and not line.split(b",")[position].strip()
    return empty


# --- checking, the API's rules per row ------------------------------------------------------
def _cycle_checks(v: dict[str, FloatArray]) -> list[tuple[str, NDArray[np.bool_], FloatArray]]:
    """(rule id, broken, value shown) in the order LoadCycle and slip_zone check them."""
    checks = []
    for name in ("P1", "Q1", "P2", "Q2", "sigma1", "sigma2"):
        checks.append((f"{name} finite", ~np.isfinite(v[name]), v[name]))
        if name in ("P1", "P2"):
            checks.append((f"{name} positive", ~(v[name] > 0), v[name]))
    # LoadCycle validates each value, then the order of the states; slip_zone then mu.
    checks.append(("P2 order", ~(v["P2"] > v["P1"]), v["P2"]))
    checks.append(("mu finite", ~np.isfinite(v["mu"]), v["mu"]))
    checks.append(("mu positive", ~(v["mu"] > 0), v["mu"]))
    return checks


class _Messages:
    """Error messages of flagged rows, in the API's words.

    The first few rows that break a rule are re-run through the public API (LoadCycle and
    slip_zone) and its InputError is taken as it is; later rows that break the same rule reuse
    that error's parameter and rule text with their own value, so that a file whose every row
    is wrong (say P1 and P2 swapped) costs no more than a valid one.
    """

    def __init__(self, law: ContactLaw, edge: Edges) -> None:
        self.law, self.edge = law, edge
        self.rules: dict[str, tuple[str, str]] = {}
        self.calls: dict[str, int] = {}

    def api_error(self, row: dict[str, float]) -> InputError | None:
        try:
            cycle = LoadCycle(row["P1"], row["Q1"], row["P2"], row["Q2"],
                              row["sigma1"], row["sigma2"])  # fmt: skip
            slip_zone(self.law, cycle, row["mu"], edge=self.edge)
        except InputError as error:
            return error
        return None

    def message(self, rule: str, row: dict[str, float], shown: float) -> str:
        if rule in self.rules and self.calls.get(rule, 0) >= _API_MESSAGES_PER_RULE:
            parameter, text = self.rules[rule]
            return str(InputError(parameter, text, float(shown)))
        self.calls[rule] = self.calls.get(rule, 0) + 1
        error = self.api_error(row)
        if error is None:  # the vectorised check and the API disagree: say so, do not guess
            return f"internal: rule {rule!r} flagged this row but slip_zone accepts it"
        self.rules.setdefault(rule, (error.parameter, error.rule))
        return str(error)


def _rows(values: dict[str, FloatArray], index: int) -> dict[str, float]:
    return {name: float(column[index]) for name, column in values.items()}


def _flag(errors: list[str | None], broken: NDArray[np.bool_], positions: NDArray[np.intp],
          make: Callable[[int, int], str]) -> None:  # fmt: skip
    """Give each newly broken row (index into ``positions``) its message."""
    for local in np.flatnonzero(broken):
        row = int(positions[local])
        if errors[row] is None:
            errors[row] = make(row, int(local))


# --- one edge of the valid rows --------------------------------------------------------------
def _evaluate_edge(law: ContactLaw, cycle: LoadCycle, mu: FloatArray,
                   side: str) -> tuple[dict[str, FloatArray], dict[str, FloatArray]]:  # fmt: skip
    """(result columns, internal values) of one edge, as :func:`edge_quantities` gives them."""
    with np.errstate(all="ignore"):  # a law's NaN becomes a row error below, not a warning
        values = edge_quantities(law, cycle, mu, side)
        internal = {key: values.pop(key) for key in INTERNAL_KEYS}
        # The sign of dP/da at a1 and a2, as check_increasing asks (1/a'(P) needs no inversion).
        internal["dP_da1"] = 1.0 / law.half_width_slope(cycle.P1)
        internal["dP_da2"] = 1.0 / law.half_width_slope(cycle.P2)
    return values, internal


def _edge_breaks(values: dict[str, FloatArray], internal: dict[str, FloatArray],
                 mu: FloatArray) -> list[tuple[str, NDArray[np.bool_], FloatArray]]:  # fmt: skip
    """The rules slip_zone checks per edge, in its order: an increasing law, then a non-zero
    denominator of (17) where the edge slips."""
    increasing = (internal["dP_da1"] > 0) & (internal["dP_da2"] > 0)
    singular = denominator_vanishes({**values, **internal}, mu)
    finite = np.logical_and.reduce([np.isfinite(column) for column in values.values()])
    return [
        ("law increasing", ~increasing, np.minimum(internal["dP_da1"], internal["dP_da2"])),
        ("denominator", increasing & singular, mu),
        ("finite", increasing & ~singular & ~finite, mu),
    ]


def _edge_warnings(law: ContactLaw, cycle: LoadCycle, mu: FloatArray, values: dict[str, FloatArray],
                   internal: dict[str, FloatArray]) -> tuple[list[str], FloatArray]:  # fmt: skip
    """Per-row warnings (joined) and b_exact, from slip_zone's own vectorised helper."""
    texts, b_exact = edge_warnings(law, cycle, {**values, **internal})
    rows = len(texts)
    outside = getattr(law, "outside_range", None)
    if outside is not None:  # a tabulated law says where it extrapolates
        for label, P in (("P1", cycle.P1), ("P2", cycle.P2)):
            P = np.broadcast_to(P, (rows,))
            for i in np.flatnonzero(outside(P)):
                texts[i].append(law.range_warning(label, float(P[i])))
    return [WARNING_SEPARATOR.join(row) for row in texts], b_exact


# --- writing ----------------------------------------------------------------------------------
_LONG = np.longdouble
_EXACT_DIGITS = np.finfo(_LONG).nmant >= 63  # x87 extended: 17 digits exact by scaling
_POW10_OFFSET = 400
_POW10 = (_LONG(10) ** np.arange(-_POW10_OFFSET, _POW10_OFFSET + 1).astype(_LONG)
          if _EXACT_DIGITS else None)  # fmt: skip
_FOUR_DIGITS = np.frombuffer("".join(f"{i:04d}" for i in range(10_000)).encode(),
                             np.uint8).reshape(10_000, 4)  # fmt: skip
_EXPONENT = np.zeros((400, 3), np.uint8)
for _value in range(400):
    _text = f"{_value:02d}".encode()
    _EXPONENT[_value, 3 - len(_text) :] = np.frombuffer(_text, np.uint8)
_DIGITS = 17  # enough to read back the same double


def format_numbers(values: FloatArray, empty: NDArray[np.bool_] | None = None) -> NDArray[np.uint8]:
    """Rows of ASCII bytes, zero-padded, writing each double with 17 significant digits.

    ``d.ddd...e+XX`` with trailing zeros dropped, ``0``, ``nan``, ``inf``; nothing where
    ``empty``.  Vectorised: the digits come from the integer round(|x| 10^(16 - e)), scaled in
    x87 extended precision (64-bit mantissa), so every double reads back exactly.
    """
    values = np.asarray(values, dtype=np.float64)
    rows = values.size
    width = _DIGITS + 7
    if not _EXACT_DIGITS:  # no extended precision: let Python format (slower, as exact)
        hidden = np.zeros(rows, bool) if empty is None else empty
        pairs = zip(values.tolist(), hidden.tolist(), strict=True)
        return _bytes_rows([b"" if hide else f"{value:.17g}".encode() for value, hide in pairs])
    out = np.zeros((rows, width), np.uint8)
    magnitude = np.abs(values)
    regular = np.flatnonzero(np.isfinite(values) & (magnitude > 0)
                             & (True if empty is None else ~empty))  # fmt: skip
    if regular.size:
        x = magnitude[regular]
        exponent = np.floor(np.log10(x)).astype(np.int64)
        extended = x.astype(_LONG)
        for _ in range(3):  # log10 can be one off at powers of ten
            mantissa = np.rint(extended * _POW10[_POW10_OFFSET + _DIGITS - 1 - exponent])
            up, down = mantissa >= 10**_DIGITS, mantissa < 10 ** (_DIGITS - 1)
            if not (up.any() or down.any()):
                break
            exponent = exponent + up - down
        integer = mantissa.astype(np.int64)
        groups = (_DIGITS + 3) // 4
        digits = np.empty((regular.size, 4 * groups), np.uint8)
        for group in range(groups):
            digits[:, 4 * (groups - 1 - group) : 4 * (groups - group)] = _FOUR_DIGITS[
                integer % 10_000
            ]
            integer //= 10_000
        digits = digits[:, 4 * groups - _DIGITS :]
        fraction = digits[:, 1:]
        nonzero = fraction != ord("0")
        kept = (_DIGITS - 1) - np.argmax(nonzero[:, ::-1], axis=1)
        kept[~nonzero.any(axis=1)] = 0
        block = np.zeros((regular.size, width), np.uint8)
        block[:, 0] = np.where(values[regular] < 0, ord("-"), 0)
        block[:, 1] = digits[:, 0]
        block[:, 2] = np.where(kept > 0, ord("."), 0)
        block[:, 3 : _DIGITS + 2] = np.where(np.arange(_DIGITS - 1) < kept[:, None], fraction, 0)
        block[:, _DIGITS + 2] = ord("e")
        block[:, _DIGITS + 3] = np.where(exponent < 0, ord("-"), ord("+"))
        block[:, _DIGITS + 4 :] = _EXPONENT[np.abs(exponent)]
        out[regular] = block
    shown = np.ones(rows, bool) if empty is None else ~empty
    out[shown & (values == 0), 0] = ord("0")
    for mask, text in ((np.isnan(values), b"nan"), (values == np.inf, b"inf"),
                       (values == -np.inf, b"-inf")):  # fmt: skip
        out[shown & mask, : len(text)] = np.frombuffer(text, np.uint8)
    return out


def _quoted(text: str) -> bytes:
    """A CSV field: quoted when it holds a comma, a quote or a line break."""
    if text and ('"' in text or "," in text or "\n" in text or "\r" in text):
        text = '"' + text.replace('"', '""') + '"'
    return text.encode("utf-8")


def _bytes_rows(items: Sequence[bytes]) -> NDArray[np.uint8]:
    """One zero-padded row of bytes per item."""
    width = max((len(item) for item in items), default=0)
    if width == 0:
        return np.zeros((len(items), 0), np.uint8)
    return np.array(items, dtype=f"S{width}").view(np.uint8).reshape(len(items), width)


def _compressed_rows(fields: list[NDArray[np.uint8]]) -> list[bytes]:
    """Zero-padded field blocks -> one ``b"f1,f2,..."`` per row (padding dropped)."""
    rows = fields[0].shape[0]
    comma = np.full((rows, 1), ord(","), np.uint8)
    pieces: list[NDArray[np.uint8]] = []
    for position, block in enumerate(fields):
        if position:
            pieces.append(comma)
        pieces.append(block)
    matrix = np.concatenate(pieces, axis=1)
    kept = matrix != 0
    ends = np.cumsum(kept.sum(axis=1)).tolist()
    flat = matrix[kept].tobytes()
    return [flat[start:end] for start, end in zip([0, *ends[:-1]], ends, strict=True)]


# --- the sweep ---------------------------------------------------------------------------------
@dataclass
class SweepSummary:
    """What a sweep did: rows written, the invalid ones (line, message), time taken."""

    rows: int
    out: Path
    seconds: float
    invalid: list[tuple[int, str]] = field(default_factory=list)

    @property
    def rows_per_second(self) -> float:
        return self.rows / self.seconds if self.seconds > 0 else float("inf")

    def report(self, shown: int = 10) -> str:
        """The stderr summary."""
        lines = [f"asymslip sweep: {self.rows} rows written to {self.out} in "
                 f"{self.seconds:.2f} s ({self.rows_per_second:,.0f} rows/s)"]  # fmt: skip
        if self.invalid:
            lines.append(f"{len(self.invalid)} invalid rows (reason in the error column):")
            lines.extend(f"  line {line}: {message}" for line, message in self.invalid[:shown])
            if len(self.invalid) > shown:
                lines.append(f"  ... and {len(self.invalid) - shown} more")
        return "\n".join(lines)


class _Progress:
    """A one-line progress bar on a terminal; silent when stderr is not one."""

    def __init__(self, total: int, stream: TextIO, enabled: bool | None) -> None:
        self.total, self.stream = total, stream
        self.enabled = stream.isatty() if enabled is None else enabled

    def update(self, done: int) -> None:
        if self.enabled and self.total:
            filled = int(30 * done / self.total)
            self.stream.write(f"\rsweep [{'#' * filled}{'.' * (30 - filled)}] "
                              f"{done:,}/{self.total:,} rows")  # fmt: skip
            self.stream.flush()

    def close(self) -> None:
        if self.enabled and self.total:
            self.stream.write("\n")
            self.stream.flush()


def _process_chunk(chunk: _Chunk, law: ContactLaw, edge: Edges, messages: _Messages,
                   header: list[str]) -> bytes:  # fmt: skip
    rows = len(chunk.lines)
    values, errors = chunk.values, chunk.errors
    everything = np.arange(rows)
    for rule, broken, shown in _cycle_checks(values):
        _flag(errors, broken, everything,
              lambda row, _local, rule=rule, shown=shown: messages.message(
                  rule, _rows(values, row), shown[row]))  # fmt: skip
    results: dict[str, dict[str, FloatArray]] = {}
    texts: dict[str, list[str]] = {}
    for side in edges_of(edge):
        valid = np.flatnonzero([error is None for error in errors])
        cycle = LoadCycle(*(values[name][valid] for name in CYCLE_COLUMNS))
        mu = values["mu"][valid]
        evaluated, internal = _evaluate_edge(law, cycle, mu, side)
        for rule, broken, shown in _edge_breaks(evaluated, internal, mu):
            if rule == "finite":
                _flag(errors, broken, valid, lambda row, local, side=side: (
                    f"the {law.name} law gives a non-finite result for this cycle "
                    f"({side} edge)"))  # fmt: skip
                continue
            _flag(errors, broken, valid,
                  lambda row, local, rule=rule, shown=shown, side=side: messages.message(
                      f"{rule} {side}", _rows(values, row), shown[local]))  # fmt: skip
        results[side] = {}
        for key, column in evaluated.items():
            results[side][key] = np.full(rows, np.nan)
            results[side][key][valid] = column
        warnings, b_exact = _edge_warnings(law, cycle, mu, evaluated, internal)
        results[side]["b_exact"] = np.full(rows, np.nan)
        results[side]["b_exact"][valid] = b_exact
        texts[side] = [""] * rows
        for local, row in enumerate(valid.tolist()):
            texts[side][row] = warnings[local]
    # Rows that failed an edge check after the other edge was computed are blanked too.
    invalid = np.array([error is not None for error in errors], dtype=bool)
    commas = len(header) - 1
    # The input columns exactly as read; a line with the wrong number of fields gets empty ones.
    segments = [[line if line.count(b",") == commas else b"," * commas for line in chunk.lines]]
    for side in edges_of(edge):
        numbers: list[NDArray[np.uint8]] = []
        for column in edge_columns():
            if column == "warnings":
                # Number columns before the warnings are one block; the warnings are text.
                segments.append(_compressed_rows(numbers))
                segments.append([b"" if invalid[i] else _quoted(text)
                                 for i, text in enumerate(texts[side])])  # fmt: skip
                numbers = []
                continue
            if column in results[side]:
                hidden = invalid | np.isnan(results[side][column]) if column == "b_exact" \
                    else invalid  # fmt: skip
                numbers.append(format_numbers(results[side][column], hidden))
            else:  # a key edge_quantities does not supply: empty
                numbers.append(np.zeros((rows, 0), np.uint8))
        if numbers:
            segments.append(_compressed_rows(numbers))
    segments.append([_quoted(error or "") for error in errors])
    # One C-level join over all fields: seg0 , seg1 , ... segK \n for every row.
    width = 2 * len(segments)
    pieces: list[bytes] = [b","] * (rows * width)
    for position, segment in enumerate(segments):
        pieces[2 * position :: width] = segment
    pieces[width - 1 :: width] = [b"\n"] * rows
    return b"".join(pieces)


@dataclass(frozen=True)
class _Job:
    """Everything a worker needs to turn one chunk of the input into output bytes."""

    lines: list[bytes]
    numbers: NDArray[np.int64]
    header: list[str]
    mu: float | None
    law: ContactLaw
    edge: Edges
    chunk_rows: int


#: The job of the current sweep, inherited by forked workers (set before the pool starts).
_JOB: _Job | None = None
_WORKER_MESSAGES: _Messages | None = None


def _evaluate_chunk(
    job: _Job, begin: int, messages: _Messages
) -> tuple[bytes, list[tuple[int, str]]]:
    end = begin + job.chunk_rows
    chunk = _parse_chunk(job.lines[begin:end], job.numbers[begin:end], job.header, job.mu)
    text = _process_chunk(chunk, job.law, job.edge, messages, job.header)
    errors = [(int(chunk.line_numbers[row]), message)
              for row, message in enumerate(chunk.errors) if message is not None]  # fmt: skip
    return text, errors


def _worker_chunk(begin: int) -> tuple[bytes, list[tuple[int, str]]]:
    global _WORKER_MESSAGES
    assert _JOB is not None
    if _WORKER_MESSAGES is None:
        _WORKER_MESSAGES = _Messages(_JOB.law, _JOB.edge)
    return _evaluate_chunk(_JOB, begin, _WORKER_MESSAGES)


def _run_chunks(job: _Job, starts: range, workers: int | None):
    """(output bytes, row errors) of each chunk, in input order.

    With more than one chunk and worker, chunks go to forked processes: the work is NumPy and
    text formatting under the GIL, so threads would not help.  Each worker keeps its own
    message cache; the messages are the same text either way.
    """
    global _JOB
    if workers is None:
        workers = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1
    fork = "fork" in multiprocessing.get_all_start_methods()
    if workers <= 1 or len(starts) <= 1 or not fork:
        messages = _Messages(job.law, job.edge)
        for begin in starts:
            yield _evaluate_chunk(job, begin, messages)
        return
    _JOB = job
    try:
        with multiprocessing.get_context("fork").Pool(min(workers, len(starts))) as pool:
            yield from pool.imap(_worker_chunk, starts)
    finally:
        _JOB = None


def sweep_file(
    cases: str | Path,
    law: ContactLaw,
    out: str | Path,
    *,
    mu: float | None = None,
    edge: Edges = "both",
    chunk_rows: int = CHUNK_ROWS,
    progress: bool | None = None,
    stream: TextIO | None = None,
    workers: int | None = None,
) -> SweepSummary:
    """Evaluate the slip zone of every cycle in ``cases`` and write one CSV row per cycle.

    Parameters
    ----------
    cases
        CSV with a header row: ``P1, Q1, P2, Q2`` required; ``sigma1, sigma2`` (default 0) and
        ``mu`` (default ``mu``) optional; any other columns are copied through.
    law
        The contact law.
    out
        The result CSV (see the module docstring for its columns).
    mu
        Coefficient of friction for rows without their own ``mu``.
    edge
        ``"right"``, ``"left"`` or ``"both"`` (default).
    chunk_rows
        Rows evaluated at once.
    progress
        Show a progress bar; default: only when ``stream`` is a terminal.
    stream
        Where the progress bar goes (default ``sys.stderr``).
    workers
        Processes evaluating chunks at once (default: the CPUs this process may use).  The
        output is the same bytes whatever the number.

    Returns
    -------
    SweepSummary
        Rows written, the invalid ones with their line numbers and reasons, time taken.

    Raises
    ------
    InputError
        Only for the file as a whole: unreadable, no header, a required column missing, no
        friction coefficient at all.  Bad rows are reported in the output instead.
    """
    start = time.perf_counter()
    cases, out = Path(cases), Path(out)
    if edge not in ("right", "left", "both"):
        raise InputError("edge", "must be 'right', 'left' or 'both'", edge)
    if mu is not None:
        mu = float(mu)
    header, lines, numbers = _read_header(cases)
    if mu is None and "mu" not in header:
        raise InputError("mu", "is required: give --mu or a mu column in the cases file")
    bar = _Progress(len(lines), stream or sys.stderr, progress)
    invalid: list[tuple[int, str]] = []
    try:
        handle = out.open("wb")
    except OSError as error:
        raise InputError("out", f"cannot write {out}: {error.strerror}") from None
    job = _Job(lines, numbers, header, mu, law, edge, chunk_rows)
    starts = range(0, len(lines), chunk_rows)
    with handle:
        handle.write((",".join(output_columns(header, edge)) + "\n").encode())
        for done, (text, errors) in enumerate(_run_chunks(job, starts, workers), start=1):
            handle.write(text)
            invalid.extend(errors)
            bar.update(min(done * chunk_rows, len(lines)))
    bar.close()
    return SweepSummary(len(lines), out, time.perf_counter() - start, invalid)
