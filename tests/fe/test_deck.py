"""The CalculiX deck of the cylinder-on-block model, without running it (fast)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asymslip import InputError
from asymslip.fe import CylinderOnBlock, write_deck
from asymslip.fe.deck import Mesh, steps

E_STAR = 210000.0 / (2 * (1 - 0.3**2))
MODEL = CylinderOnBlock(R=50.0, E_star=E_STAR, mu=0.5, P1=1000.0, Q1=-100.0, P2=1100.0, Q2=150.0)


def test_the_deck_is_the_same_bytes_every_time():
    assert write_deck(MODEL) == write_deck(MODEL)


def test_the_steps_seat_preload_and_cycle_twice():
    kinds = [step.kind for step in steps(MODEL)]
    assert (
        kinds == ["seat", "preload", "preload", "preload", "state 1"] + ["state 2", "state 1"] * 2
    )
    assert [step.P for step in steps(MODEL)][1:4] == [600.0, 800.0, 1000.0]


def test_the_mesh_is_uniform_over_the_contact_with_no_node_on_the_hertz_edge():
    mesh = Mesh.of(MODEL)
    x = mesh.grid.x
    fine = x[np.abs(x) <= 1.3 * MODEL.a2]
    assert np.allclose(np.diff(fine), MODEL.element_size)
    a2 = math.sqrt(4 * 1100.0 * 50.0 / (math.pi * E_STAR))  # (29)
    assert np.min(np.abs(x - a2)) == pytest.approx(MODEL.element_size / 2)
    assert x[-1] >= 10 * a2 and mesh.depth >= 10 * a2


def test_the_block_carries_the_tension_and_balances_Q_at_its_ends():
    deck = write_deck(CylinderOnBlock(**{**MODEL.__dict__, "sigma2": 150.0}))
    depth = Mesh.of(MODEL).depth
    # The first state-2 step: Q (the block's force on the cylinder, as slip-zone's) = 150, so
    # the cylinder's top is loaded by -150 and the block receives -150 through the contact,
    # which its ends balance: left sigma - Q/(2H), right sigma + Q/(2H), as tension.
    step = deck.split("** step 6: state 2")[1].split("*END STEP")[0]
    left = float(step.split("LEFTEND, P4, ")[1].split()[0])
    right = float(step.split("RIGHTEND, P2, ")[1].split()[0])
    assert left == pytest.approx(-(150.0 - 150.0 / (2 * depth)), rel=1e-12)
    assert right == pytest.approx(-(150.0 + 150.0 / (2 * depth)), rel=1e-12)
    assert "REF, 1, -150" in step and "REF, 2, -1100" in step


@pytest.mark.parametrize(
    ("change", "words"),
    [
        ({"Q2": 600.0}, "Q2: gross sliding at state 2"),
        ({"P2": 900.0}, "P2: must exceed P1"),
        ({"R": 0.5}, "R: the contact half-width"),
        ({"nu": 0.5}, "nu: must be in"),
        ({"elements_per_half_width": 4}, "elements_per_half_width: must be an integer >= 8"),
    ],
)
def test_a_model_outside_its_range_is_refused_by_name(change, words):
    with pytest.raises(InputError, match=words):
        CylinderOnBlock(**{**MODEL.__dict__, **change})


def test_fe_model_deck_only_writes_the_deck_and_says_it_was_not_run(tmp_path, capsys):
    from asymslip.cli import main

    status = main(
        [
            "fe-model",
            "--R",
            "50",
            "--E-star",
            repr(E_STAR),
            "--mu",
            "0.5",
            "--P1",
            "1000",
            "--Q1",
            "-100",
            "--P2",
            "1100",
            "--Q2",
            "150",
            "--out",
            str(tmp_path / "run"),
            "--deck-only",
            "--json",
        ]
    )
    captured = capsys.readouterr()
    assert status == 0
    assert "not run" in captured.err
    deck = tmp_path / "run" / "cylinder_on_block.inp"
    assert deck.read_text() == write_deck(MODEL)
    assert f'"deck": "{deck}"' in captured.out
