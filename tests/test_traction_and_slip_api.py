"""traction and slip as issue 17 asked: the headline b by default, points of the other edge
flagged, the law's own modulus kept."""

from __future__ import annotations

import numpy as np
import pytest

from asymslip import HertzLaw, InputError, LoadCycle, TableLaw, slip_zone
from asymslip.tractions import slip_displacement, traction_difference

LAW = HertzLaw(1.0, 1.0)
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0)  # Fig. 5
MU = 0.1


def test_the_traction_uses_the_headline_b_by_default():
    edge = slip_zone(LAW, CYCLE, MU)
    default = traction_difference(LAW, CYCLE, MU, [10.0])
    assert default.stick_boundary == "headline" and default.b == edge.b
    consistent = traction_difference(LAW, CYCLE, MU, [10.0], stick_boundary="consistent")
    assert consistent.b == edge.b_paper != edge.b


def test_the_slip_uses_the_headline_b_by_default_and_says_when_it_does_not():
    edge = slip_zone(LAW, CYCLE, MU)
    default = slip_displacement(LAW, CYCLE, MU, [11.2])
    assert (default.stick_boundary, default.b) == ("headline", edge.b)
    assert not any("not at the headline b" in text for text in default.warnings)
    consistent = slip_displacement(LAW, CYCLE, MU, [11.2], stick_boundary="consistent")
    assert consistent.b == edge.b_paper != edge.b
    assert any("not at the headline b" in text for text in consistent.warnings)


@pytest.mark.parametrize("edge, x", [("left", 11.2), ("right", -11.2)])
def test_a_point_on_the_other_edges_half_is_flagged_not_answered_silently(edge, x):
    slip = slip_displacement(LAW, CYCLE, MU, [x], edge=edge)
    assert slip.slip == [0.0]  # this edge's stick zone: a 0 that is no answer for that point
    other = "right" if edge == "left" else "left"
    assert any(f"on the {other} half of the contact" in text for text in slip.warnings)
    traction = traction_difference(LAW, CYCLE, MU, [x], edge=edge)
    assert any(f"belong to the {other} edge" in text for text in traction.warnings)
    same_side = slip_displacement(LAW, CYCLE, MU, [-x], edge=edge)
    assert not any("half of the contact" in text for text in same_side.warnings)


def test_a_law_with_its_own_modulus_refuses_another():
    with pytest.raises(InputError, match=r"^E_star: the hertz law already has its modulus E\* = 1"):
        slip_displacement(LAW, CYCLE, MU, [11.2], E_star=2.0)
    # the same value is no conflict, and a law without a modulus takes it
    assert slip_displacement(LAW, CYCLE, MU, [11.2], E_star=1.0).slip == (
        slip_displacement(LAW, CYCLE, MU, [11.2]).slip
    )
    loads = np.geomspace(50.0, 200.0, 12)
    table = TableLaw(loads, LAW.half_width(loads))
    with_modulus = slip_displacement(table, CYCLE, MU, [11.2], E_star=2.0).slip[0]
    assert with_modulus == pytest.approx(
        slip_displacement(LAW, CYCLE, MU, [11.2]).slip[0] / 2, rel=1e-3
    )
