"""The blade-root-like example: where cracks start at both edges of a rounded flat under tension.

A flat punch with rounded corners (flat half-width c = 4 mm, corner radius R = 25 mm; titanium
on titanium, E = 115 GPa, nu = 0.3, so E* = E/(2 (1 - nu^2))), loaded as a dovetail root is
over a flight: the normal load grows by 6 % of the contact width, the shear force with it
(lambda = 0.8 mu) and the bulk tension of the lower body from 200 to 300 MPa.  The reference
solver (N = 4000) gives both extremes of the steady cycle; the Smith-Watson-Topper parameter
and Findley's are mapped near both edges, with the critical distance L = 0.05 mm.

``python -m asymslip.nucleation.blade_root --out generated/figures`` (``make
nucleation-figure``) writes ``nucleation_blade_root.png`` and ``nucleation_blade_root.csv``
(the findings); it takes about half a minute.

Examples
--------
>>> state = cycle()
>>> round(float(state.P1), 1), round(float(state.P2), 1), float(state.sigma2)
(1757.1, 3430.0, 300.0)
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..cycle import LoadCycle
from ..laws import FlatRoundedLaw
from ..solver import solve
from .assessment import NucleationResult, nucleation
from .criteria import Criterion, Material
from .output import draw, write_table

E, NU = 115e3, 0.3  # MPa
LAW = FlatRoundedLaw(c=4.0, R=25.0, E_star=E / (2 * (1 - NU**2)))
MU = 0.5
MATERIAL = Material(E=E, nu=NU, sigma_y=900.0, k_findley=0.3, L=0.05)
CRITERIA = (Criterion.RUIZ, Criterion.SWT, Criterion.FINDLEY)


def cycle() -> LoadCycle:
    """a1 = 4.5 mm, a2 = 4.77 mm; Q1 = 0.3 mu P1, Q2 - Q1 = 0.8 mu dP; sigma 200 -> 300 MPa."""
    P1, P2 = float(LAW.load(4.5)), float(LAW.load(4.5 * 1.06))
    Q1 = 0.3 * MU * P1
    return LoadCycle(P1, Q1, P2, Q1 + 0.8 * MU * (P2 - P1), 200.0, 300.0)


def assess(elements: int = 4000) -> NucleationResult:
    result = solve(LAW, cycle(), MU, elements=elements)
    return nucleation(result, MATERIAL, CRITERIA)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m asymslip.nucleation.blade_root")
    parser.add_argument("--out", type=Path, default=Path("generated/figures"))
    parser.add_argument("--elements", type=int, default=4000)
    args = parser.parse_args(argv)
    found = assess(args.elements)
    title = (
        "rounded flat (c = 4, R = 25 mm), Ti/Ti, mu = 0.5, bulk tension 200 -> 300 MPa: "
        "SWT [MPa] and Findley [MPa], L = 0.05 mm"
    )
    paths = [
        draw(found, args.out / "nucleation_blade_root.png", title),
        write_table(found, args.out / "nucleation_blade_root.csv"),
    ]
    for path in paths:
        print(f"wrote {path}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
