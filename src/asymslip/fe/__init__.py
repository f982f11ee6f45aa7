"""A real finite-element model of the paper's problem: a plane-strain cylinder on a block.

:class:`CylinderOnBlock` (:mod:`.model`) describes it -- the Hertz law's R and E*, the cycle
as for ``slip-zone``, the mesh; :func:`write_deck` (:mod:`.deck`) writes its CalculiX deck;
:func:`run_model` (:mod:`.run`) writes and runs it with ``ccx`` where installed; and
:func:`read_result` (:mod:`.results`) reads the steady stick boundaries and contact edges of
both edges from the run.  The run's .frd and .dat are what ``asymslip calibrate`` reads.

Runtime needs NumPy only (and CalculiX's ``ccx`` to run a deck).

Examples
--------
>>> model = CylinderOnBlock(R=50.0, E_star=115384.6, mu=0.5, P1=1000.0, Q1=-100.0,
...                         P2=1100.0, Q2=150.0)
>>> deck = write_deck(model)
>>> deck.splitlines()[1], deck.count("*STEP")
('asymslip: plane-strain cylinder on block, the steady partial-slip cycle', 9)
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
