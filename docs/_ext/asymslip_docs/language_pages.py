"""The generated functions in every language, written from the records at build time.

``docs/reference/languages/`` (not committed) gets an index -- one row per formula record of
``formulas.json`` with its paper equations and its name in Python, C, Fortran and MATLAB/Octave
-- and one page per language that shows the committed files themselves (the C header, the
Fortran module, each MATLAB function file), so what is documented is exactly what ships.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

from .api_pages import write_if_changed
from .records import GENERATED, FormulaRecord, formula_records

FOLDER = Path("reference") / "languages"
#: From the generated pages to the repository root.
UP = "../../../"
C_HEADER = GENERATED / "c" / "asymslip_gen.h"
FORTRAN_MODULE = GENERATED / "fortran" / "asymslip_gen.f90"
MATLAB_FOLDER = GENERATED / "matlab"


def _row(record: FormulaRecord) -> list[str]:
    equations = ", ".join(f"({number})" for number in record.equations) or "--"
    symbol = f"asymslip_{record.name}"

    def has(language: str) -> str:
        return f"``{symbol}``" if language in record.languages else "--"

    matlab = (
        f":ref:`{symbol}.m <matlab-{record.name}>`" if "MATLAB/Octave" in record.languages else "--"
    )
    return [
        f":py:func:`~{record.python}`",
        equations,
        has("C"),
        has("Fortran"),
        matlab,
    ]


def render_index(records: tuple[FormulaRecord, ...]) -> str:
    lines = [
        "Generated functions in every language",
        "=====================================",
        "",
        "``make generate`` writes every formula from the same record into four languages: the",
        "NumPy package ``asymslip_gen``, C99 (:doc:`c`), one Fortran 2008 module (:doc:`fortran`)",
        "and one MATLAB/Octave file per function (:doc:`matlab`) -- same arguments in the same",
        "order, same documentation.  ``make test-languages`` compiles (or runs) each and compares",
        "it with NumPy at 1,000 points per function.  The functions do not check their domain:",
        "validate inputs as the Python API does.",
        "",
        f"{len(records)} functions, from ``generated/asymslip_gen/formulas.json``:",
        "",
        ".. list-table::",
        "   :header-rows: 1",
        "   :widths: 34 12 18 18 18",
        "",
        "   * - Python (``asymslip_gen``)",
        "     - paper",
        "     - C",
        "     - Fortran",
        "     - MATLAB/Octave",
    ]
    for record in records:
        cells = _row(record)
        lines.append(f"   * - {cells[0]}")
        lines += [f"     - {cell}" for cell in cells[1:]]
    lines += ["", ".. toctree::", "   :hidden:", "", "   c", "   fortran", "   matlab", ""]
    return "\n".join(lines)


def render_c() -> str:
    return "\n".join(
        [
            "C99: ``generated/c``",
            "====================",
            "",
            "``asymslip_gen.h`` declares ``double asymslip_<name>(double ...)`` for every formula;",
            "``asymslip_gen.c`` defines them (needs ``<math.h>`` only).  Build with, for example::",
            "",
            "   gcc -std=c99 -O2 -Igenerated/c program.c generated/c/asymslip_gen.c -lm",
            "",
            ".. rubric:: ``generated/c/asymslip_gen.h``",
            "",
            f".. literalinclude:: {UP}generated/c/asymslip_gen.h",
            "   :language: c",
            "",
        ]
    )


def render_fortran() -> str:
    return "\n".join(
        [
            "Fortran 2008: ``generated/fortran``",
            "===================================",
            "",
            "One module, ``asymslip_gen``: an elemental ``asymslip_<name>`` on ``real(c_double)``",
            "scalars or arrays for every formula, and a ``bind(C)`` twin of each with the C",
            "prototype.  Build with, for example::",
            "",
            "   gfortran -O2 generated/fortran/asymslip_gen.f90 program.f90",
            "",
            ".. rubric:: ``generated/fortran/asymslip_gen.f90``",
            "",
            f".. literalinclude:: {UP}generated/fortran/asymslip_gen.f90",
            "   :language: fortran",
            "",
        ]
    )


def render_matlab(records: tuple[FormulaRecord, ...]) -> str:
    lines = [
        "MATLAB/Octave: ``generated/matlab``",
        "===================================",
        "",
        "One vectorised function file per formula (element-wise on arrays); ``addpath`` the",
        "folder, and ``help asymslip_<name>`` prints the documentation below.",
        "",
    ]
    for record in records:
        path = MATLAB_FOLDER / f"asymslip_{record.name}.m"
        if "MATLAB/Octave" not in record.languages or not path.is_file():
            continue
        title = f"``asymslip_{record.name}.m``"
        lines += [f".. _matlab-{record.name}:", "", title, "-" * len(title), ""]
        lines += [
            f".. literalinclude:: {UP}generated/matlab/{path.name}",
            "   :language: matlab",
            "",
        ]
    return "\n".join(lines)


def write_pages(srcdir: Path) -> None:
    folder = srcdir / FOLDER
    records = formula_records()
    write_if_changed(folder / "index.rst", render_index(records))
    write_if_changed(folder / "c.rst", render_c())
    write_if_changed(folder / "fortran.rst", render_fortran())
    write_if_changed(folder / "matlab.rst", render_matlab(records))


def _builder_inited(app: Sphinx) -> None:
    write_pages(Path(app.srcdir))


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("builder-inited", _builder_inited)
    return {"parallel_read_safe": True}
