"""The warnings of one edge's result: bit flags per element, turned into words when asked.

10^6 cycles carry 10^6 small integers, not 10^6 lists of strings; :func:`warning_texts`
gives one element's words.  The keys of a result (:data:`NUMBER_KEYS`, :data:`MEASURE_KEYS`)
live here too: the sweep's columns and the API's fields are the same list.

Examples
--------
>>> from asymslip.core.flags import NO_SLIP, MEASURE_FLAGS, warning_texts
>>> from asymslip.laws.hertz import HertzLaw
>>> [text[:24] for text in warning_texts(NO_SLIP | MEASURE_FLAGS["eq24"], HertzLaw(1, 1))]
['no slip at this edge: |L', 'eq24 > 0.1: contact grow']
"""

from __future__ import annotations

from ..laws.base import ContactLaw

#: A validity measure above this is reported in ``warnings`` ("<< 1" made concrete).
VALIDITY_THRESHOLD = 0.1

VALIDITY_MEANING = {
    "eq24": "contact growth dP a'(P)/a1",
    "eq25": "slip-zone size |b - a1|/a1",
    "eq26": "edge-multiplier growth dP |L_I'(P)|/L_I1",
    "eq27": "necessary condition dP a'(P)/a1 |1 - lam/mu - pi eta a1/(4 mu)| (0 where the edge "
    "does not slip)",
}

#: The numeric fields of one edge's result, in JSON order (validity measures flattened).
NUMBER_KEYS = (
    "a1",
    "a2",
    "lam",
    "eta",
    "L_I1",
    "L_I2",
    "L_II1",
    "L_II2",
    "b",
    "slip_zone_width",
    "b_accuracy",
    "b_paper",
    "b_first_order",
    "b_exact",
    "b_corrective_stick",
    "slip_direction",
)
MEASURE_KEYS = tuple(VALIDITY_MEANING)

# --- warnings as flags --------------------------------------------------------------------------
NO_SLIP = 1 << 0
MEASURE_FLAGS = {key: 1 << (1 + i) for i, key in enumerate(MEASURE_KEYS)}
EXTRAPOLATED_P1 = 1 << 5
EXTRAPOLATED_P2 = 1 << 6
DISAGREE_PAPER = 1 << 7
DISAGREE_FIRST_ORDER = 1 << 8
DISAGREE_CORRECTIVE_STICK = 1 << 9
DISAGREE_EXACT = 1 << 10
OTHER_EDGE_STICKS = 1 << 11
#: The other estimates of b, left out (null) where they fall outside the contact (0, a2]: a
#: stick boundary there is no answer, and printing it would pass it off as one.  Each with its
#: equation and the disagreement flag it then replaces.
ESTIMATES_CHECKED = {
    "b_paper": ("(22)", DISAGREE_PAPER),
    "b_first_order": ("(28)", DISAGREE_FIRST_ORDER),
    "b_corrective_stick": ("(40)", DISAGREE_CORRECTIVE_STICK),
}
OUTSIDE_FLAGS = {key: 1 << (12 + i) for i, key in enumerate(ESTIMATES_CHECKED)}
#: The cycle's bulk tension changes (eta != 0): the context of a (22) disagreement.
WITH_TENSION = 1 << 15
#: An estimate beyond a1 (a negative slip-zone width) at an edge that slips on loading.
BEYOND_A1 = {
    key: 1 << (16 + i)
    for i, key in enumerate(("b", "b_paper", "b_first_order", "b_corrective_stick", "b_exact"))
}
#: Bulk tension at an edge with its own multipliers (a calibrated contact), where b is (17).
OWN_MULTIPLIERS_TENSION = 1 << 21
_DISAGREEMENT_TEXT = {
    DISAGREE_PAPER: "(22) (b_paper) differs from b by more than their stated accuracies; take b",
    DISAGREE_FIRST_ORDER: "the first-order (28) (b_first_order) differs from b by more than "
    "their stated accuracies: the load change is too large for a first-order estimate",
    DISAGREE_CORRECTIVE_STICK: "the corrective-stick (40) (b_corrective_stick) differs from b "
    "by more than their stated accuracies",
    DISAGREE_EXACT: "b differs from the exact a(P_K) by more than its stated accuracy: the load "
    "change is too large for the second-order estimate; take b_exact",
    OTHER_EDGE_STICKS: "the other edge does not slip: b uses the second-order branch that joins "
    "continuously where the other edge starts to slip (checked against the reference solver, "
    "not derived)",
}

#: Why (22) may differ from b, with and without bulk tension (README, "How far to trust b").
_PAPER_WHY = {
    True: " (with bulk tension (22) carries a spurious dP^2 term, erratum 22-T)",
    False: " (without bulk tension (22)'s dP^2 term is exact only for a law whose a^2 is affine "
    "in P, such as Hertz: for other laws it errs by (1 - lam^2/mu^2)(a'' + a'^2/a) dP^2/8)",
}

_OWN_MULTIPLIERS_TENSION_TEXT = (
    "bulk tension at an edge with its own multipliers (a calibrated contact): b is (17) in the "
    "edge's multipliers, whose dP^2 term with tension is the one erratum 22-T finds spurious "
    "for symmetric contacts and is not corrected here; against the reference solver its error "
    "reached 10 % of the slip-zone width, so trust b only to its stated first-order accuracy "
    "b_accuracy = 2 (da/a1) |a1 - b|"
)

_NO_SLIP_TEXT = (
    "no slip at this edge: |L_II2| <= mu L_I2 (|lam + pi eta a2/4| <= mu), so the edge sticks "
    "wherever it is in contact; b = a1 and the slip-zone width is 0"
)


def warning_texts(flags: int, law: ContactLaw) -> list[str]:
    """The warnings of one element, in words, from its flags."""
    texts = []
    if flags & NO_SLIP:
        texts.append(_NO_SLIP_TEXT)
    for key, bit in MEASURE_FLAGS.items():
        if flags & bit:
            texts.append(
                f"{key} > {VALIDITY_THRESHOLD}: {VALIDITY_MEANING[key]} is not small, so "
                "the asymptotic solution is doubtful"
            )
    for bit, label in ((EXTRAPOLATED_P1, "P1"), (EXTRAPOLATED_P2, "P2")):
        if flags & bit:
            texts.append(law.extrapolation_note(label))
    for bit, text in _DISAGREEMENT_TEXT.items():
        if flags & bit:
            texts.append(
                text + (_PAPER_WHY[bool(flags & WITH_TENSION)] if bit == DISAGREE_PAPER else "")
            )
    for key, bit in BEYOND_A1.items():
        if flags & bit:
            texts.append(
                f"{key} lies beyond a1 (a negative slip-zone width) although the edge slips on "
                "loading: the asymptote predicts no slip zone inside a1 (the edge slips only "
                "where it advances, a1 < x < a2, which the edge asymptote does not resolve), so "
                f"{key} is no stick boundary inside the state-1 contact"
            )
    if flags & OWN_MULTIPLIERS_TENSION:
        texts.append(_OWN_MULTIPLIERS_TENSION_TEXT)
    for key, bit in OUTSIDE_FLAGS.items():
        if flags & bit:
            texts.append(
                f"{key}: the estimate {ESTIMATES_CHECKED[key][0]} puts the stick "
                "boundary outside the contact (0, a2], so it is no answer for this "
                "cycle and is left out (null)"
            )
    return texts
