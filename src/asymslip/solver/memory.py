"""How much memory a solve needs, checked before anything is allocated.

A solve keeps, per element of the grid: one period of shear tractions (8 bytes per load step,
:class:`~asymslip.solver.period.PeriodWindow`), a normal solution per distinct load of the path
(pressure, contact flag and gap: 17 bytes, :class:`~asymslip.solver.period.NormalCache`), and a
working set of vectors, FFT buffers and circulant spectra that does not grow with the steps
(``WORKING_BYTES``).  The slip of each step is kept only where an element moved (the slip
zones), a few per cent of the contact, and is not counted.  Measured peak resident memory of
the Fig. 5 cycle (20 steps per segment, 21 distinct loads): see ``WORKING_BYTES``; the estimate
lies above every measurement (``tests/solver/test_memory.py``).

A grid that would not fit in the memory the machine has available is refused with the figure
(an :class:`~asymslip.errors.InputError` naming ``elements``) instead of allocating until the
machine gives up.

Examples
--------
The paper's cycle with 20 steps per segment keeps 40 steps' tractions and 21 normal solutions:

>>> from asymslip import LoadCycle
>>> from asymslip.solver.memory import check_memory, estimate, readable
>>> from asymslip.solver.path import LoadPath
>>> path = LoadPath.from_cycle(LoadCycle(100, 0, 105, 1))
>>> need = estimate(10**6, 20, path)
>>> need.steps_kept, need.loads_kept, readable(need.total)
(40, 21, '1.38 GB')
>>> check_memory(10**9, 20, path, available=16 * 10**9)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
asymslip.errors.InputError: elements: 1,000,000,000 elements need about 1.28 TB of memory ...
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from .path import LoadPath

#: Bytes per element of everything that does not grow with the steps or the loads: the
#: operators' columns and spectra, the active-set iteration's vectors, the FFT buffers, the
#: preconditioners' spectra and the result's arrays, and above 2^18 elements the 2-D transforms'
#: arrays (``toeplitz.CrtLayout``), fitted to the measured peak with margin: the Fig. 5 cycle at
#: N = 10^6 peaked at 1.32 GB (1,213 bytes per element beyond ``BASE_BYTES``; 1.22 GB before
#: the 2-D transforms, above the 1.18 GB that 400 bytes here estimated).
WORKING_BYTES = 600
#: Bytes per element of one normal solution: pressure (8), contact flag (1), gap (8).
NORMAL_BYTES = 17
#: Bytes per element of one step's shear tractions kept for the steady period.
STEP_BYTES = 8
#: Bytes of the interpreter, NumPy and the package before any grid exists.
BASE_BYTES = 100 * 2**20


@dataclass(frozen=True)
class MemoryEstimate:
    """The bytes a solve needs: its parts and their total."""

    elements: int
    steps_kept: int  # load steps of one period
    loads_kept: int  # distinct loads of the path's steps (each a normal solution)

    @property
    def per_element(self) -> int:
        return WORKING_BYTES + STEP_BYTES * self.steps_kept + NORMAL_BYTES * self.loads_kept

    @property
    def total(self) -> int:
        return BASE_BYTES + self.elements * self.per_element

    def elements_within(self, available: int) -> int:
        """The most elements whose estimate fits in ``available`` bytes."""
        return max(0, (available - BASE_BYTES) // self.per_element)


def estimate(elements: int, steps: int, path: LoadPath) -> MemoryEstimate:
    """The memory a solve of ``path`` on ``elements`` elements with ``steps`` per segment needs."""
    loads = np.concatenate(
        [path.points[:1, [0, 3]], *(s[:, [0, 3]] for s in path.segment_loads(steps))]
    )
    distinct = len({row.tobytes() for row in np.ascontiguousarray(loads)})
    return MemoryEstimate(elements, steps * path.count, distinct)


def available_memory() -> int | None:
    """Bytes the system could give this process now (Linux ``MemAvailable``), or None."""
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return None


def readable(size: float) -> str:
    """A byte count in words: 1.2 GB, 640 MB."""
    for unit, scale in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6)):
        if size >= scale:
            return f"{size / scale:.3g} {unit}"
    return f"{size / 1e3:.3g} kB"


def check_memory(
    elements: int,
    steps: int,
    path: LoadPath,
    available: int | None = None,
    subject: str | None = None,
) -> None:
    """Refuse a solve that needs more memory than is available (``available``: measured now).

    ``subject`` names the grid in the message, with its verb (default: "N elements need").

    Raises
    ------
    InputError
        (``elements``) with the estimate, the memory available and the most elements that fit.
    """
    needed = estimate(elements, steps, path)
    if available is None:
        available = available_memory()
    if available is None or needed.total <= available:
        return
    raise InputError(
        "elements",
        f"{subject or f'{elements:,} elements need'} about {readable(needed.total)} of memory "
        f"({needed.per_element} bytes per element with {needed.steps_kept} load steps per "
        f"period), more than the {readable(available)} available: give at most about "
        f"{needed.elements_within(available):,} elements, or fewer steps",
    )
