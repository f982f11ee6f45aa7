"""Text columns without one Python string per row.

:class:`TextColumn` keeps UTF-8 strings as one byte buffer and row offsets (Arrow's layout, so
pyarrow can use it without a copy); :class:`Categorical` keeps a few distinct strings and one
integer code per row (10^6 rows of warnings are 10^6 small integers, not 10^6 strings).

Examples
--------
>>> from asymslip.files.text import TextColumn
>>> column = TextColumn.from_strings(["fig5", None, "Fläche"])
>>> len(column), column[0], column[1], column[2]
(3, 'fig5', '', 'Fläche')
>>> column.offsets.tolist()  # bytes: "ä" takes two
[0, 4, 4, 11]
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Characters that make a CSV field need quotes (RFC 4180).
SPECIAL = b',"\r\n'


def quote(text: str) -> str:
    """A CSV field: quoted (quotes doubled) only when it holds a comma, a quote or a line break."""
    if any(character in text for character in ',"\r\n'):
        return '"' + text.replace('"', '""') + '"'
    return text


def quote_always(text: str) -> str:
    """A CSV text field, always in quotes (quotes doubled), as ``pyarrow.csv`` writes strings
    with ``quoting_style="needed"``."""
    return '"' + text.replace('"', '""') + '"'


def ragged_take(
    data: NDArray[np.uint8], offsets: NDArray[np.int64], rows: NDArray[np.intp]
) -> tuple[NDArray[np.uint8], NDArray[np.int64]]:
    """The byte strings ``rows`` of a ragged (data, offsets) column, vectorised."""
    starts, ends = offsets[rows], offsets[np.asarray(rows) + 1]
    lengths = ends - starts
    new_offsets = np.zeros(len(lengths) + 1, np.int64)
    np.cumsum(lengths, out=new_offsets[1:])
    total = int(new_offsets[-1])
    if total == 0:
        return np.zeros(0, np.uint8), new_offsets
    index = np.repeat(starts - new_offsets[:-1], lengths) + np.arange(total, dtype=np.int64)
    return data[index], new_offsets


@dataclass(frozen=True)
class TextColumn:
    """UTF-8 strings: row ``i`` is ``data[offsets[i]:offsets[i + 1]]``.

    Attributes
    ----------
    data
        The bytes of all rows, one after another.
    offsets
        ``len(self) + 1`` increasing positions into ``data``, starting at ``offsets[0]``.
    """

    data: NDArray[np.uint8]
    offsets: NDArray[np.int64]

    @classmethod
    def from_strings(cls, items: Iterable[str | None]) -> TextColumn:
        """From Python strings (``None`` gives an empty string)."""
        encoded = [(item or "").encode("utf-8") for item in items]
        offsets = np.zeros(len(encoded) + 1, np.int64)
        np.cumsum([len(item) for item in encoded], out=offsets[1:])
        return cls(np.frombuffer(b"".join(encoded), np.uint8), offsets)

    @classmethod
    def empty(cls, rows: int) -> TextColumn:
        return cls(np.zeros(0, np.uint8), np.zeros(rows + 1, np.int64))

    def __len__(self) -> int:
        return len(self.offsets) - 1

    def __getitem__(self, row: int) -> str:
        return self.data[self.offsets[row] : self.offsets[row + 1]].tobytes().decode("utf-8")

    def to_list(self) -> list[str]:
        return [item.decode("utf-8") for item in self.to_bytes_list()]

    def to_bytes_list(self) -> list[bytes]:
        buffer = self.data[self.offsets[0] : self.offsets[-1]].tobytes()
        bounds = (self.offsets - self.offsets[0]).tolist()
        return [buffer[a:b] for a, b in zip(bounds[:-1], bounds[1:], strict=True)]

    def slice(self, start: int, stop: int) -> TextColumn:
        """Rows ``start:stop`` without copying."""
        return TextColumn(self.data, self.offsets[start : stop + 1])

    def take(self, rows: ArrayLike) -> TextColumn:
        """The given rows (a copy)."""
        data, offsets = ragged_take(self.data, self.offsets, np.asarray(rows, dtype=np.intp))
        return TextColumn(data, offsets)

    def needs_quotes(self) -> bool:
        """Whether any row holds a comma, a quote or a line break."""
        used = self.data[self.offsets[0] : self.offsets[-1]]
        return bool(np.isin(used, np.frombuffer(SPECIAL, np.uint8)).any())


@dataclass(frozen=True)
class Categorical:
    """One of a few strings per row: ``categories[codes[i]]``, or no value where ``codes < 0``.

    Attributes
    ----------
    codes
        Integer code of each row (``-1``: no value, an empty field / a null).
    categories
        The distinct strings.
    """

    codes: NDArray[np.int32]
    categories: tuple[str, ...]

    def __init__(self, codes: ArrayLike, categories: Sequence[str]) -> None:
        codes = np.asarray(codes, dtype=np.int32)
        categories = tuple(categories)
        if codes.size and (codes.max() >= len(categories) or codes.min() < -1):
            raise ValueError(f"codes must lie in [-1, {len(categories) - 1}]")
        object.__setattr__(self, "codes", codes)
        object.__setattr__(self, "categories", categories)

    @classmethod
    def from_strings(cls, items: Iterable[str | None]) -> Categorical:
        """Encode Python strings (``None`` gives no value)."""
        index: dict[str, int] = {}
        codes = [-1 if item is None else index.setdefault(item, len(index)) for item in items]
        return cls(np.array(codes, dtype=np.int32), list(index))

    def __len__(self) -> int:
        return len(self.codes)

    def to_list(self) -> list[str | None]:
        names = [*self.categories, None]  # code -1 picks the last entry
        return [names[code] for code in self.codes.tolist()]

    def slice(self, start: int, stop: int) -> Categorical:
        return Categorical(self.codes[start:stop], self.categories)
