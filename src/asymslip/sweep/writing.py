"""Writing result rows as CSV text: exact 17-digit numbers, quoted text (NumPy only)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


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
