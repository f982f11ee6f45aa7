"""A real finite-element model of the paper's problem: a plane-strain cylinder on a block.

:class:`CylinderOnBlock` (:mod:`.model`) describes it -- the Hertz law's R and E*, the cycle
as for ``slip-zone``, the mesh; :func:`write_deck` (:mod:`.deck`) writes its CalculiX deck;
:func:`run_model` (:mod:`.run`) writes and runs it with ``ccx`` where installed; and
:func:`read_result` (:mod:`.results`) reads the steady stick boundaries and contact edges of
both edges from the run.  The run's .frd and .dat are what ``asymslip calibrate`` reads.

Runtime needs NumPy only (and CalculiX's ``ccx`` to run a deck).
"""

from .deck import write_deck
from .model import CylinderOnBlock
from .results import FeEdge, FeResult, read_result
from .run import FeRun, find_ccx, run_model, write_model

__all__ = [
    "CylinderOnBlock",
    "FeEdge",
    "FeResult",
    "FeRun",
    "find_ccx",
    "read_result",
    "run_model",
    "write_deck",
    "write_model",
]
