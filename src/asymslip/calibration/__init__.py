"""Contact edges calibrated from pressure data: each edge's a(P) and L_I(P) of (4).

The paper's method needs, per edge, the contact law a(P) and the multiplier L_I of the edge
asymptote (4); for real geometries both "will have been found numerically".  This package takes
the nodal contact pressures of a finite-element model at several loads (:func:`read_traces`,
:func:`read_fe_report`, :meth:`Traces.from_arrays`), fits each edge at each load
(:func:`fit_edge`) and collects the results (:func:`calibrate` -> :class:`Calibration`), from
which :class:`~asymslip.laws.calibrated.CalibratedLaw` builds each edge's law.

Runtime needs NumPy only.
"""

from .calibration import Calibration, calibrate
from .edge_fit import EdgeFit, fit_edge
from .traces import Trace, Traces, read_fe_report, read_traces

__all__ = [
    "Calibration",
    "EdgeFit",
    "Trace",
    "Traces",
    "calibrate",
    "fit_edge",
    "read_fe_report",
    "read_traces",
]
