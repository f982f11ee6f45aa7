"""The warning flags and result keys of an edge: kept under their old name for importers.

They live in :mod:`asymslip.core.flags`.
"""

from .core.flags import (
    DISAGREE_CORRECTIVE_STICK,
    DISAGREE_EXACT,
    DISAGREE_FIRST_ORDER,
    DISAGREE_PAPER,
    ESTIMATES_CHECKED,
    EXTRAPOLATED_P1,
    EXTRAPOLATED_P2,
    MEASURE_FLAGS,
    MEASURE_KEYS,
    NO_SLIP,
    NUMBER_KEYS,
    OTHER_EDGE_STICKS,
    OUTSIDE_FLAGS,
    VALIDITY_MEANING,
    VALIDITY_THRESHOLD,
    warning_texts,
)

__all__ = [
    "DISAGREE_CORRECTIVE_STICK",
    "DISAGREE_EXACT",
    "DISAGREE_FIRST_ORDER",
    "DISAGREE_PAPER",
    "ESTIMATES_CHECKED",
    "EXTRAPOLATED_P1",
    "EXTRAPOLATED_P2",
    "MEASURE_FLAGS",
    "MEASURE_KEYS",
    "NO_SLIP",
    "NUMBER_KEYS",
    "OTHER_EDGE_STICKS",
    "OUTSIDE_FLAGS",
    "VALIDITY_MEANING",
    "VALIDITY_THRESHOLD",
    "warning_texts",
]
