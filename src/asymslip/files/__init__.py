"""Files the tool reads and writes.

- :func:`read_table` (:mod:`.reader`): a cases CSV -> :class:`CaseTable` (text of every column,
  numeric columns as float64, 1-based file line and error of each row).
- :func:`open_table` (:mod:`.writer`): a result table, chunk by chunk, to ``.csv`` (shortest
  round-trip doubles) or ``.parquet``, atomically; :class:`TextColumn` and :class:`Categorical`
  (:mod:`.text`) hold text without a Python string per row.
- :func:`format_doubles` (:mod:`.numbers`): the NumPy formatter of shortest round-trip doubles.
- :class:`Progress` (:mod:`.progress`), :func:`atomic_write` (:mod:`.atomic`).
- :func:`refuse_overwriting_inputs` (:mod:`.collisions`): every command that writes lists what
  it reads (:class:`Input`) and writes (:class:`Output`) and calls it before anything else, so
  that nothing it writes replaces one of its inputs.  New commands must do the same.

pyarrow (the ``parquet`` extra) is used when installed and imported only when a table is read
or written; without it everything but Parquet works with NumPy alone.
"""

from .atomic import atomic_write
from .collisions import Input, Output, refuse_overwriting_inputs
from .numbers import format_doubles
from .progress import Progress
from .reader import CaseTable, read_table
from .text import Categorical, TextColumn
from .writer import TableWriter, WrittenTable, open_table, table_format

__all__ = [
    "CaseTable",
    "Categorical",
    "Input",
    "Output",
    "Progress",
    "TableWriter",
    "TextColumn",
    "WrittenTable",
    "atomic_write",
    "format_doubles",
    "open_table",
    "read_table",
    "refuse_overwriting_inputs",
    "table_format",
]
