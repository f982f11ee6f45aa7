"""The slip-zone core: one edge pipeline for one cycle on floats and for arrays of cycles.

One way through it: :mod:`.evaluation` (the cycle's rules and the law's state) calls
:mod:`.edge_state` (each edge's shear, checks and flags), which calls :mod:`.estimates` (the
generated kernels, once each); all three work through an :mod:`.operations` adapter (Python
floats or NumPy arrays), and :mod:`.flags` turns warnings into words.  The public API over it
is :mod:`asymslip.slip_zones`.

Examples
--------
>>> from asymslip import HertzLaw, LoadCycle
>>> from asymslip.core.evaluation import evaluate
>>> from asymslip.edge import Edge
>>> edges = evaluate(HertzLaw(1.0, 1.0), LoadCycle(100, 0, 105, 1), 0.1).edges
>>> edges[Edge.LEFT].slip_direction, round(edges[Edge.LEFT].b, 6)
(-1.0, 11.141863)
"""
