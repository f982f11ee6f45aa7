"""pyarrow, imported only when a table is read or written, and only if it is installed.

pyarrow is the optional ``parquet`` extra: it reads and writes CSV with multithreaded C++ and
is the only way to write Parquet.  Without it everything but Parquet works with NumPy alone.
"""

from __future__ import annotations

from functools import cache
from types import ModuleType

from ..errors import InputError

INSTALL = "pip install 'asymslip[parquet]'"


@cache
def available() -> bool:
    """Whether pyarrow (with its csv, compute and parquet modules) can be imported."""
    try:
        import pyarrow  # noqa: F401
        import pyarrow.compute  # noqa: F401
        import pyarrow.csv  # noqa: F401
        import pyarrow.parquet  # noqa: F401
    except ImportError:
        return False
    return True


def require(option: str, why: str) -> ModuleType:
    """pyarrow, or an :class:`InputError` naming ``option`` and the extra to install."""
    if not available():
        raise InputError(option, f"{why} needs pyarrow: {INSTALL}")
    import pyarrow

    module: ModuleType = pyarrow  # no type information of its own
    return module
