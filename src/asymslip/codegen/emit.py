"""Render :class:`Formula` records as formatted, deterministic NumPy modules."""

from __future__ import annotations

import subprocess
import sys
import tempfile
import textwrap
from collections.abc import Mapping, Sequence
from pathlib import Path

from .cse import Reduced, reduce_formula
from .documentation import PAPER, banner_lines, commented, wrap
from .formula import Formula
from .printer import GeneratedCodePrinter


def banner(
    sources: Sequence[str], command: str = "make generate", edit: str = "the derivation"
) -> str:
    """Header comment of a generated file: where it comes from, and not to edit it.

    No timestamps or tool versions, so that regeneration is byte-identical.
    """
    return commented(banner_lines(sources, command, edit), "#")


def _equation_refs(equations: Sequence[str]) -> str:
    return ", ".join(f"({number})" for number in equations)


def docstring(
    formula: Formula,
    kind: str = "array_like",
    returns_kind: str = "ndarray or float64",
    note: str = "",
) -> str:
    """The NumPy-style docstring of a generated function (``kind``: how arguments are typed)."""
    paragraph = textwrap.fill(formula.doc + (f"  {note}" if note else ""), width=92)
    parameters = "\n".join(
        f"{arg.name} : {kind}\n{textwrap.indent(textwrap.fill(arg.meaning, 88), '    ')}"
        for arg in formula.args
    )
    returns = textwrap.indent(textwrap.fill(formula.returns, 88), "    ")
    label = "Eq." if len(formula.equations) == 1 else "Eqs."
    provenance = textwrap.fill(
        f"Implements {label} {_equation_refs(formula.equations)} of the paper; derived in "
        f"``{formula.source}``."
        if formula.equations
        else f"Not a numbered equation of the paper; derived in ``{formula.source}``.",
        width=92,
    )
    body = (
        f"{formula.summary}\n\n{paragraph}\n\n{provenance}\n\n"
        f"Parameters\n----------\n{parameters}\n\n"
        f"Returns\n-------\n{returns_kind}\n{returns}\n"
    )
    return '"""' + body + '"""'


def render_function(formula: Formula | Reduced, printer: GeneratedCodePrinter) -> str:
    """One ``def`` with a CSE'd body whose temporaries are named ``tmp0, tmp1, ...``."""
    reduced = formula if isinstance(formula, Reduced) else reduce_formula(formula)
    formula = reduced.formula
    signature = ", ".join(f"{arg.name}: ArrayLike" for arg in formula.args)
    lines = [f"def {formula.name}({signature}) -> FloatArray:"]
    lines.append(textwrap.indent(docstring(formula), "    "))
    for temporary, value in reduced.temporaries:
        lines.append(f"    {temporary} = {printer.doprint(value)}")
    lines.append(f"    return {printer.doprint(reduced.result)}")
    return "\n".join(lines) + "\n"


def render_module(
    module: str,
    doc: str,
    formulas: Sequence[Formula | Reduced],
    *,
    header: str | None = None,
    preamble: str = "",
) -> str:
    """Source text of one generated module, before formatting.

    ``header`` replaces the ``make generate`` banner (a law module written by ``asymslip
    derive`` says so); ``preamble`` is module-level code placed after ``__all__``.
    """
    printer = GeneratedCodePrinter()
    reduced = [f if isinstance(f, Reduced) else reduce_formula(f) for f in formulas]
    names = [item.formula.name for item in reduced]
    if len(set(names)) != len(names):
        raise ValueError(f"module {module}: duplicate function names {names}")
    functions = "\n\n".join(render_function(item, printer) for item in reduced)
    exported = "\n".join(f'    "{name}",' for name in names)
    if header is None:
        header = banner([item.formula.source for item in reduced])
    docstring = "\n".join(wrap(doc, 92))
    return (
        header + f'"""{docstring}\n\nSee {PAPER}.\n"""\n\n'
        "from __future__ import annotations\n\n"
        "import numpy\n"
        "from numpy.typing import ArrayLike, NDArray\n\n"
        "FloatArray = NDArray[numpy.float64] | numpy.float64\n\n"
        f"__all__ = [\n{exported}\n]\n\n" + (f"{preamble}\n" if preamble else "") + f"\n{functions}"
    )


def render_package_init(modules: Mapping[str, Sequence[Formula]]) -> str:
    """``asymslip_gen/__init__.py``: every generated function, each module loaded on first use.

    PEP 562 (as SciPy does): ``from asymslip_gen.hertz import ...`` or one ``asymslip_gen.name``
    loads only that module, which keeps ``from asymslip import slip_zone`` near NumPy's own
    import time (``make bench``, section imports).
    """
    where = {formula.name: module for module in modules for formula in modules[module]}
    sources = [formula.source for formulas in modules.values() for formula in formulas]
    table = "\n".join(f'    "{name}": "{where[name]}",' for name in sorted(where))
    return (
        banner(sources) + '"""Generated NumPy kernels for asymptotic partial-slip contacts.\n\n'
        "Runtime needs NumPy only.  The hand-written, validating API is the ``asymslip`` package.\n"
        '"""\n\n'
        "import importlib\n"
        "from typing import Any\n\n"
        "#: The module of each generated function; a module loads when one of its functions is\n"
        "#: first asked for.\n"
        f"_MODULES = {{\n{table}\n}}\n\n"
        "__all__ = sorted(_MODULES)\n\n\n"
        "def __getattr__(name: str) -> Any:\n"
        "    if name not in _MODULES:\n"
        "        raise AttributeError(f\"module 'asymslip_gen' has no attribute {name!r}\")\n"
        '    value = getattr(importlib.import_module(f"{__name__}.{_MODULES[name]}"), name)\n'
        "    globals()[name] = value\n"
        "    return value\n\n\n"
        "def __dir__() -> list[str]:\n"
        "    return sorted([*globals(), *_MODULES])\n"
    )


def format_sources(sources: Mapping[str, str]) -> dict[str, str]:
    """Format several modules with one run of the pinned ruff (one process, not one each)."""
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        for name, source in sources.items():
            (folder / name).write_text(source, encoding="utf-8")
        completed = subprocess.run(
            [
                sys.executable,
                "-m",
                "ruff",
                "format",
                "--isolated",
                "--quiet",
                "--line-length",
                "100",
                "--target-version",
                "py311",
                str(folder),
            ],
            capture_output=True,
            text=True,
            check=False,
        )
        if completed.returncode != 0:
            raise RuntimeError(f"ruff format failed:\n{completed.stderr}")
        return {name: (folder / name).read_text(encoding="utf-8") for name in sources}


def format_source(source: str) -> str:
    """Format with the pinned ruff, isolated from any user configuration."""
    completed = subprocess.run(
        [
            sys.executable,
            "-m",
            "ruff",
            "format",
            "--isolated",
            "--line-length",
            "100",
            "--target-version",
            "py311",
            "--stdin-filename",
            "generated.py",
            "-",
        ],
        input=source,
        capture_output=True,
        text=True,
        check=False,
    )
    if completed.returncode != 0:
        raise RuntimeError(f"ruff format failed:\n{completed.stderr}\n--- source ---\n{source}")
    return completed.stdout
