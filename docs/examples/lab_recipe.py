"""
From a blade root's pressure traces to a laboratory recipe
==========================================================

A dovetail blade root bears on its disc slot over a flank that is nearly flat with rounded
ends; in service the centrifugal load raises the normal load, the shear force and the bulk
tension in the blade neck together.  The fretting test that reproduces the flank's contact edge
is a cylindrical pad on a flat specimen with the right radius, loads and bulk tension.

This example goes the whole way: pressure traces as a finite-element model would export them
(here sampled from a rounded flat, so that the answer can be checked), the edge calibrated from
them (``asymslip calibrate``), the rig cycle designed (``asymslip match``), and both contacts
solved by the reference solver to check that the rig's edge is the blade's.
Units: N, mm, MPa (E* in N/mm^2, loads per unit length in N/mm).
"""

# %%
# The prototype: a rounded-flat flank under a proportional cycle
# ---------------------------------------------------------------
# Flat half-width 1 mm, corner radius 20 mm, titanium on titanium (E* = 63 GPa, mu = 0.5).
# From state 1 to state 2 the normal load grows by 4 %, the shear force and the bulk tension
# with it.
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from asymslip import FlatRoundedLaw, LoadCycle, slip_zone
from asymslip.calibration import Calibration, calibrate, read_traces
from asymslip.match import Available, Rig, SolverProblem, match, verify

E_STAR, MU = 63000.0, 0.5
flank = FlatRoundedLaw(c=1.0, R=20.0, E_star=E_STAR)
service = LoadCycle(P1=500.0, Q1=40.0, P2=520.0, Q2=60.0, sigma1=250.0, sigma2=290.0)

# %%
# Pressure traces, as exported from a finite-element model
# ---------------------------------------------------------
# Nodal contact pressures at six loads on a fixed mesh (one node every 5 micrometres).
folder = Path(tempfile.mkdtemp())
x = np.arange(-2.0, 2.0 + 1e-9, 0.005)
rows = ["P,x,p"]
for load in (470.0, 490.0, 500.0, 510.0, 520.0, 540.0):
    pressure = flank.pressure(x, load)
    rows += [f"{load!r},{float(xi)!r},{float(pi)!r}" for xi, pi in zip(x, pressure, strict=True)]
(folder / "traces.csv").write_text("\n".join(rows) + "\n")

calibration = calibrate(read_traces(folder / "traces.csv"))
calibration.save(folder / "flank.json")
blade = Calibration.load(folder / "flank.json").law()
edge = slip_zone(blade, service, MU)
print(f"calibrated right edge: a1 = {edge.a1:.5f} mm, a2 - a1 = {edge.a2 - edge.a1:.3e} mm")
print(f"  L_I1 = {edge.L_I1:.2f}, L_II1 = {edge.L_II1:.2f} N/mm^2.5; slip zone {edge.b:.5f} mm")

# %%
# The laboratory recipe
# ---------------------
# A cylinder-on-flat rig: pad radii from 5 to 200 mm, at most 5 kN/mm, 600 MPa of bulk tension.
rig = Rig(
    "hertz",
    E_STAR,
    radius=Available.between("rig_R", 5.0, 200.0),
    max_P=5000.0,
    max_sigma=600.0,
)
recipe = match(blade, service, MU, rig)
cycle = recipe.cycle
print(f"pad radius R = {recipe.geometry.R:.3f} mm ({recipe.order} order, exact: {recipe.exact})")
print(
    f"  state 1: P = {cycle.P1:.3f} N/mm, Q = {cycle.Q1:+.3f} N/mm, sigma = {cycle.sigma1:+.3f} MPa"
)
print(
    f"  state 2: P = {cycle.P2:.3f} N/mm, Q = {cycle.Q2:+.3f} N/mm, sigma = {cycle.sigma2:+.3f} MPa"
)
print(f"  margin against gross sliding {recipe.margin:.3f}")
for name, pair in recipe.matched.items():
    print(f"  {name:<16} blade {pair.prototype:12.6g}   rig {pair.rig:12.6g}")
print(f"  stated accuracy of the slip-zone width: {recipe.accuracy:.2e} mm")

# %%
# Checked by the reference solver
# -------------------------------
# The flank itself (its rounded-flat profile) and the rig, each solved to its steady state; the
# rig on elements of the flank's size.
check = verify(recipe, SolverProblem(flank, service), elements=4000)
print(
    f"solver slip-zone widths: blade {check.prototype.width:.5f}, rig {check.rig.width:.5f} mm "
    f"(difference {check.width_difference:+.2e}, allowed {check.width_allowed:.2e})"
)
print(
    f"largest difference over the slip zone: shear change {check.shear_change_difference:.2%}, "
    f"slip {check.slip_difference:.2%} of the blade's largest"
)
# The near-edge stress amplitude (state 2 - state 1) at 24 points about each edge, from the edge
# asymptotes and from the solvers' fields, against the two asymptotes' stated accuracy.
for item in check.stress:
    print(
        f"stress amplitude ({item.source}): largest difference {item.difference:.2%} of the "
        f"blade's largest component, stated accuracy {item.allowed:.2%}, within: "
        f"{item.within_stated_accuracy}"
    )

# %%
# The same on the command line
# ----------------------------
# ``asymslip match --verify`` with the calibration file and the flank's gap tabulated (as a
# drawing or the finite-element mesh would give it) prints the recipe and the verification:
# the slip-zone widths, the shear change and slip, and the near-edge stress amplitude -- with
# the amplitude's uniform sxx (half the tension change), which the edge match does not fix.
from asymslip.cli import main

gap_x = np.linspace(-3.0, 3.0, 6001)
gap_h = flank.profile(gap_x)
gap = "\n".join(f"{a!r},{h!r}" for a, h in zip(gap_x.tolist(), gap_h.tolist(), strict=True))
(folder / "flank_gap.csv").write_text("x,h\n" + gap + "\n")
command = [
    *f"match --law calibrated --calibration {folder / 'flank.json'} --mu {MU}".split(),
    *"--P1 500 --Q1 40 --sigma1 250 --P2 520 --Q2 60 --sigma2 290".split(),
    *f"--rig hertz --rig-E-star {E_STAR} --rig-R-range 5 200 --rig-max-P 5000".split(),
    *f"--rig-max-sigma 600 --verify --verify-E-star {E_STAR} --elements 4000".split(),
    *["--verify-profile-table", str(folder / "flank_gap.csv")],
]
print("$ asymslip " + " ".join(command))
status = main(command)

# %%
# The two edges side by side, in the edge's own coordinate
figure, (shear, slip) = plt.subplots(1, 2, figsize=(10, 4))
for solved, label, style in (
    (check.prototype, "blade (solver)", "-"),
    (check.rig, "rig (solver)", "--"),
):
    near = (solved.s > 0) & (solved.s < 3 * solved.reach)
    order = np.argsort(solved.s[near])
    shear.plot(solved.s[near][order], solved.q_diff[near][order], style, label=label)
    slip.plot(solved.s[near][order], 1e3 * solved.slip[near][order], style, label=label)
for axis in (shear, slip):
    axis.axvline(check.prototype.reach, color="grey", lw=0.8)
    axis.set_xlabel("distance from the state-2 edge, a2 - x [mm]")
    axis.legend()
shear.set_ylabel("q2 - q1 [MPa]")
slip.set_ylabel("slip on loading [micrometres]")
figure.suptitle(f"Blade flank and its Hertz rig (R = {recipe.geometry.R:.2f} mm)")
figure.tight_layout()
figure.savefig("lab_recipe.png", dpi=120)
