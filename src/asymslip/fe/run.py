"""Write the deck of a :class:`~asymslip.fe.model.CylinderOnBlock` and run CalculiX on it.

``ccx`` (CalculiX 2.x; Debian's package ``calculix-ccx``) is looked up on PATH.  Without it the
deck is still written and :func:`run_model` says that it was not run.  A run that CalculiX
ends with an error (no convergence, a bad card) is one :class:`~asymslip.errors.InputError`
quoting CalculiX's own error line; its log stays in the folder.

Runtime needs NumPy only (and ccx to run).

Examples
--------
>>> import tempfile
>>> from asymslip.fe.model import CylinderOnBlock
>>> model = CylinderOnBlock(R=50.0, E_star=115384.6, mu=0.5, P1=1000.0, Q1=-100.0,
...                         P2=1100.0, Q2=150.0)
>>> write_model(model, tempfile.mkdtemp()).name
'cylinder_on_block.inp'
"""

from __future__ import annotations

import os
import resource
import shutil
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from .deck import write_deck
from .model import CylinderOnBlock
from .results import FeResult, read_result

#: The job name: the deck is <folder>/<JOB>.inp, the results <JOB>.frd and <JOB>.dat.
JOB = "cylinder_on_block"


def find_ccx() -> str | None:
    """The CalculiX solver on PATH (``ccx``), or None."""
    return shutil.which("ccx")


@dataclass(frozen=True)
class FeRun:
    """What a run left in its folder, and its stick boundaries (None when ccx was not run)."""

    deck: Path
    frd: Path | None
    dat: Path | None
    seconds: float | None  # wall clock of the ccx run
    cpu_seconds: float | None  # its CPU time (user + system): what a quiet machine would take
    result: FeResult | None


def write_model(model: CylinderOnBlock, folder: str | Path) -> Path:
    """Write the deck into ``folder`` (which must exist) and return its path."""
    folder = Path(folder)
    if not folder.is_dir():
        raise InputError("out", f"{folder} is not a folder")
    deck = folder / f"{JOB}.inp"
    deck.write_text(write_deck(model))
    return deck


def run_model(
    model: CylinderOnBlock, folder: str | Path, *, ccx: str | None = None, timeout: float = 3600
) -> FeRun:
    """Write the deck, run ccx on it if it is installed, and read the steady stick boundaries."""
    deck = write_model(model, folder)
    solver = ccx or find_ccx()
    if solver is None:
        return FeRun(deck, None, None, None, None, None)
    # One thread: the machine's other work, and results that do not depend on the thread count.
    environment = {**os.environ, "OMP_NUM_THREADS": "1", "CCX_NPROC_EQUATION_SOLVER": "1"}
    log = deck.with_suffix(".log")
    start = time.perf_counter()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with log.open("w") as handle:
        try:
            completed = subprocess.run(
                [solver, "-i", JOB],
                cwd=deck.parent,
                stdout=handle,
                stderr=subprocess.STDOUT,
                env=environment,
                timeout=timeout,
                check=False,
            )
        except subprocess.TimeoutExpired:
            raise InputError("ccx", f"did not finish within {timeout:g} s (log: {log})") from None
    seconds = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    text = log.read_text(errors="replace")
    errors = [line.strip() for line in text.splitlines() if "*ERROR" in line]
    if errors or completed.returncode != 0:
        reason = errors[0] if errors else f"exit status {completed.returncode}"
        raise InputError("ccx", f"CalculiX failed: {reason} (log: {log})")
    frd, dat = deck.with_suffix(".frd"), deck.with_suffix(".dat")
    return FeRun(deck, frd, dat, seconds, cpu, read_result(frd, model))
