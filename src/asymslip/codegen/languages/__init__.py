"""Backends that print the same reduced formula records in C, Fortran and MATLAB/Octave.

One backend per language, each a SymPy printer configured through ``_print_*`` methods and
settings (never a string replacement of its output) and a renderer that lays out the files.
All of them take the CSE'd records (:mod:`asymslip.codegen.cse`) the NumPy package is written
from, so every language has the same functions, arguments and temporaries.  A function that
needs something a language lacks (a special function) is left out of that language, with a
note in the file saying which and why.
"""

from __future__ import annotations

from .base import Language, Rendered
from .c import C_LANGUAGE
from .fortran import FORTRAN_LANGUAGE
from .matlab import MATLAB_LANGUAGE

#: Every language beyond Python, in the order the report lists them.
LANGUAGES: tuple[Language, ...] = (C_LANGUAGE, FORTRAN_LANGUAGE, MATLAB_LANGUAGE)

__all__ = ["LANGUAGES", "Language", "Rendered"]
