"""The CalculiX input deck of :class:`~asymslip.fe.model.CylinderOnBlock`, written as text.

What the deck holds (``*HEADING`` repeats the essentials):

* the mesh of :mod:`.mesh`: CPE4 elements, block ``BLOCK`` below y = 0 and cylinder ``CYL``
  above it, one linear elastic material (E, nu) for both;
* node-to-surface penalty contact, the block's surface the slave (its nodes are the traces'
  nodes), the cylinder's the master: a linear pressure-overclosure law of slope
  ``normal_penalty`` E/h, a small tension 1e-5 p0 at open nodes close to the master surface
  (CalculiX needs it; it shows as a slightly negative pressure just beyond the edge, which
  ``calibrate`` clips and counts), contact elements generated for every slave node of the
  fine zone; Coulomb friction with a stick slope ``stick_penalty`` E/h;
* the cylinder's top held rigid by equations (every top node moves with the reference node
  ``REF``, which carries the loads): no rotation, so the contact carries no moment;
* Q and sigma as ``slip-zone`` and ``solve`` take them, so that (38) holds with both positive
  at the right edge: Q is the shear force the block exerts on the cylinder through the
  contact (``REF`` is loaded by -Q), sigma the block's bulk tension;
* the block on rollers at its base (one node also held in x) and its ends loaded by the bulk
  tension: sigma - Q/(2 H) on the left end, sigma + Q/(2 H) on the right (H its depth), which
  balances the contact's -Q on the block symmetrically and leaves the mean bulk stress at the
  contact sigma;
* the steps of :func:`steps`: the cylinder seated by a small prescribed displacement, the
  normal load in steps to P1 (frictionless and Q = sigma = 0, the cylinder held in x: for
  similar bodies normal loading makes no shear), then the cycle: state 1, and ``cycles`` times
  state 2 and state 1, each step ramping the loads linearly (the paper's straight load path);
* output at the end of each step: contact pressures, shears, openings and slips at the slave
  nodes (``*CONTACT FILE`` to the .frd, ``*CONTACT PRINT`` to the .dat) and the reaction force
  of the base (``RF`` of node set ``BASE``: its total is the normal load P, which
  ``calibrate`` takes as each step's load).

Runtime needs NumPy only.

Examples
--------
>>> from asymslip.fe.model import CylinderOnBlock
>>> model = CylinderOnBlock(R=50.0, E_star=115384.6, mu=0.5, P1=1000.0, Q1=-100.0,
...                         P2=1100.0, Q2=150.0, sigma2=20.0)
>>> [(step.kind, step.P, step.sigma) for step in steps(model)][3:7]
[('preload', 1000.0, 0.0), ('state 1', 1000.0, 0.0), ('state 2', 1100.0, 20.0),
 ('state 1', 1000.0, 0.0)]
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from .mesh import Body, Grid, IntArray, block, cylinder
from .model import CylinderOnBlock

StepKind = Literal["seat", "preload", "state 1", "state 2"]
#: The node set whose reaction force is the normal load.
BASE = "BASE"
#: Tension at open slave nodes near the master, as a fraction of the peak pressure p0.
OPEN_TENSION = 1e-5
#: Friction during the normal loading (frictionless in effect; CalculiX needs it > 0).
NORMAL_LOADING_FRICTION = 1e-4


@dataclass(frozen=True)
class Step:
    """One analysis step: its kind and the loads at its end."""

    kind: StepKind
    P: float
    Q: float
    sigma: float


def steps(model: CylinderOnBlock) -> tuple[Step, ...]:
    """The deck's steps in order (CalculiX numbers them from 1)."""
    listed = [Step("seat", 0.0, 0.0, 0.0)]
    listed += [Step("preload", f * model.P1, 0.0, 0.0) for f in model.preload_fractions]
    listed.append(Step("state 1", model.P1, model.Q1, model.sigma1))
    for _ in range(model.cycles):
        listed.append(Step("state 2", model.P2, model.Q2, model.sigma2))
        listed.append(Step("state 1", model.P1, model.Q1, model.sigma1))
    return tuple(listed)


@dataclass(frozen=True)
class Mesh:
    """Both bodies on one grid."""

    grid: Grid
    block: Body
    cylinder: Body

    @classmethod
    def of(cls, model: CylinderOnBlock) -> Mesh:
        a2 = model.a2
        grid = Grid.build(
            h=model.element_size,
            fine=model.fine_zone * a2,
            extent=model.extent * a2,
            depth=model.extent * a2,
            growth=model.growth,
        )
        lower = block(grid)
        upper = cylinder(
            grid,
            model.R,
            first_node=int(lower.ids.max()) + 1,
            first_element=int(lower.element_numbers[-1]) + 1,
        )
        return cls(grid, lower, upper)

    @property
    def depth(self) -> float:
        return float(self.grid.depths[-1])

    @property
    def surface_nodes(self) -> IntArray:
        """The block's surface nodes (the slave nodes), left to right."""
        return np.asarray(self.block.ids[0], dtype=np.int64)


def _number(value: float) -> str:
    """A float as CalculiX reads it: at most 20 characters a field (14 significant digits)."""
    return f"{value:.14g}"


def _lines(values: IntArray | list[int], per_line: int = 8) -> list[str]:
    """Integers as CalculiX list lines (at most 16 entries a line; 8 is readable)."""
    flat = [str(int(v)) for v in np.ravel(values)]
    return [", ".join(flat[k : k + per_line]) + "," for k in range(0, len(flat), per_line)]


def write_deck(model: CylinderOnBlock, mesh: Mesh | None = None) -> str:
    """The whole deck as text (deterministic: the same model gives the same bytes)."""
    mesh = mesh or Mesh.of(model)
    h, E, a2 = model.element_size, model.E, model.a2
    p0 = 2 * model.P2 / (math.pi * a2)  # Hertz peak pressure at P2, (48)
    lower, upper = mesh.block, mesh.cylinder
    columns = mesh.grid.x.size - 1
    rows = mesh.grid.depths.size - 1
    top_row = upper.ids[-1]
    reference = int(top_row[top_row.size // 2])
    base_centre = int(lower.ids[-1][lower.ids.shape[1] // 2])
    # Contact elements for every slave node within the fine zone (clearance x^2 / 2R there).
    reach = model.fine_zone * a2
    clearance = 1.5 * reach * reach / (2 * model.R)
    # The seat: a rigid overlap of the profile over |x| < a1 / 2.
    seat = (0.5 * model.a1) ** 2 / (2 * model.R)
    out = [
        "*HEADING",
        "asymslip: plane-strain cylinder on block, the steady partial-slip cycle",
        "** Written by asymslip (asymslip.fe.deck): regenerate it, do not edit it.",
        f"** R = {model.R!r}, E* = {model.E_star!r}, nu = {model.nu!r}, mu = {model.mu!r}",
        f"** P {model.P1!r} -> {model.P2!r}, Q {model.Q1!r} -> {model.Q2!r}, "
        f"sigma {model.sigma1!r} -> {model.sigma2!r}",
        f"** element size {h!r} = a(P2)/{model.elements_per_half_width}",
        "*NODE",
    ]
    for body in (lower, upper):
        numbers = body.ids.ravel()
        out += [
            f"{int(n)}, {_number(x)}, {_number(y)}"
            for n, (x, y) in zip(numbers, body.coordinates.tolist(), strict=True)
        ]
    for name, body in (("BLOCK", lower), ("CYL", upper)):
        out.append(f"*ELEMENT, TYPE=CPE4, ELSET={name}")
        out += [
            f"{int(e)}, {a}, {b}, {c}, {d}"
            for e, (a, b, c, d) in zip(body.element_numbers, body.elements.tolist(), strict=True)
        ]
    out += ["*NSET, NSET=SURFACE", *_lines(mesh.surface_nodes)]
    out += [f"*NSET, NSET={BASE}", *_lines(lower.ids[-1])]
    out += ["*NSET, NSET=TOP", *_lines(top_row)]
    out += ["*NSET, NSET=BASEX", f"{base_centre},", "*NSET, NSET=REF", f"{reference},"]
    # Faces: block elements (n1, n2 deep; n3, n4 at the surface): S3 the top, S4 the left end,
    # S2 the right end; cylinder elements: S1 the bottom.
    out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    out += [f"{lower.element_number(0, c)}, S3" for c in range(columns)]
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out += [f"{upper.element_number(0, c)}, S1" for c in range(columns)]
    out.append("*ELSET, ELSET=LEFTEND")
    out += _lines([lower.element_number(r, 0) for r in range(rows)])
    out.append("*ELSET, ELSET=RIGHTEND")
    out += _lines([lower.element_number(r, columns - 1) for r in range(rows)])
    out += [
        "*MATERIAL, NAME=STEEL",
        "*ELASTIC",
        f"{_number(E)}, {_number(model.nu)}",
        "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL",
        "1.",
        "*SOLID SECTION, ELSET=CYL, MATERIAL=STEEL",
        "1.",
    ]
    for node in top_row:
        if int(node) != reference:
            for dof in (1, 2):
                out += ["*EQUATION", "2", f"{int(node)}, {dof}, 1., {reference}, {dof}, -1."]
    normal = model.normal_penalty * E / h
    stick = model.stick_penalty * E / h
    out += [
        "*SURFACE INTERACTION, NAME=CONTACT",
        "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
        f"{_number(normal)}, {_number(OPEN_TENSION * p0)}, {_number(clearance)}",
        "*FRICTION",
        f"{_number(NORMAL_LOADING_FRICTION)}, {_number(stick)}",
        "*CONTACT PAIR, INTERACTION=CONTACT, TYPE=NODE TO SURFACE",
        "SLAVE, MASTER",
        "*BOUNDARY",
        f"{BASE}, 2, 2, 0.",
        "BASEX, 1, 1, 0.",
    ]
    held = ["*BOUNDARY, OP=NEW", f"{BASE}, 2, 2, 0.", "BASEX, 1, 1, 0."]
    depth = mesh.depth
    for number, step in enumerate(steps(model), start=1):
        out += [f"** step {number}: {step.kind}", "*STEP, INC=1000", "*STATIC"]
        if step.kind == "seat":
            out += [
                "1., 1.",
                "*BOUNDARY",
                "REF, 1, 1, 0.",
                f"REF, 2, 2, {_number(-seat)}",
                "*END STEP",
            ]
            continue
        out.append("0.25, 1., 1e-05, 0.25")
        # More iterations before a cut-back than the defaults: stick-slip status changes
        # converge slowly; a force residual of 1 % of the mean nodal force is accepted.
        out += [
            "*CONTROLS, PARAMETERS=TIME INCREMENTATION",
            "8, 20, 9, 200, 10, 4, , 8",
            "*CONTROLS, PARAMETERS=FIELD",
            "0.01, 1., 0.02",
        ]
        if step.kind == "preload":
            out += [*held, "REF, 1, 1, 0."]
        elif number == len(model.preload_fractions) + 2:  # the first step of the cycle
            out += [*held, "*CHANGE FRICTION, INTERACTION=CONTACT", "*FRICTION"]
            out.append(f"{_number(model.mu)}, {_number(stick)}")
        # The block receives -Q from the cylinder: its ends balance it, half each.
        left = step.sigma - step.Q / (2 * depth)
        right = step.sigma + step.Q / (2 * depth)
        out += [
            "*CLOAD",
            f"REF, 1, {_number(-step.Q)}",
            f"REF, 2, {_number(-step.P)}",
            "*DLOAD",
            f"LEFTEND, P4, {_number(-left)}",
            f"RIGHTEND, P2, {_number(-right)}",
            f"*NODE FILE, NSET={BASE}, FREQUENCY=100000",
            "RF",
            "*CONTACT FILE, FREQUENCY=100000",
            "CDIS, CSTR",
            f"*NODE PRINT, NSET={BASE}, TOTALS=ONLY, FREQUENCY=100000",
            "RF",
            "*CONTACT PRINT, FREQUENCY=100000",
            "CDIS, CSTR",
            "*END STEP",
        ]
    return "\n".join(out) + "\n"
