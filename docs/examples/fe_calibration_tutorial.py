"""From a CalculiX run to the slip zone
======================================

**Needs CalculiX** (``ccx``; Debian: ``apt-get install calculix-ccx``, or ``make toolchains``):
without it this script stops with that message.  It runs one small model: about a minute of
CPU time (several minutes of wall clock on a busy machine).

A cylinder pressed on a block of the same steel (plane strain) is loaded by the paper's cycle
in a finite-element model; ``asymslip calibrate`` reads the contact pressures straight from
the run's ``.frd``, fits each edge's half-width a(P) and multiplier L_I(P) with their errors,
and the calibrated law gives the slip zone -- which we set beside the FE model's own steady
stick boundary and beside the Hertz law's.  The mesh here is deliberately coarse (a(P2)/16 at
the contact) so that it runs quickly; the tests use a(P2)/30, a study would use 100 or more.
"""

# %%
# The model: the Hertz law's R and E*, the cycle as for ``slip-zone``.
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from asymslip import HertzLaw, LoadCycle, slip_zone
from asymslip.calibration import calibrate, read_traces
from asymslip.fe import CylinderOnBlock, find_ccx, run_model

if find_ccx() is None:
    raise SystemExit("this tutorial needs CalculiX's ccx (Debian: apt-get install calculix-ccx)")

E_STAR = 210000.0 / (2 * (1 - 0.3**2))  # steel on steel, plane strain [MPa]
R, MU = 50.0, 0.5  # cylinder radius [mm], friction
CYCLE = dict(P1=1000.0, Q1=-150.0, P2=1200.0, Q2=350.0)  # [N/mm]; lambda/mu = 5
model = CylinderOnBlock(R=R, E_star=E_STAR, mu=MU, **CYCLE, elements_per_half_width=16)

# %%
# Run CalculiX (the deck is written into a scratch folder, never kept by hand).
folder = Path(tempfile.mkdtemp(prefix="asymslip-fe-"))
run = run_model(model, folder)
print(f"ccx: {run.seconds:.0f} s, element size {model.element_size:.4f} mm")

# %%
# ``calibrate`` reads the .frd: each step's CPRESS at the block's surface nodes, the load from
# the base's reaction force, negative pressures beyond the edge clipped (and counted).  Each
# fitted edge is compared with the FE model's own: Hertz's a about the FE contact's centre,
# the line of action of its resultant, which moves with Q (the FE cylinder bends under the
# shear it carries from its top and tilts its contact, about a tenth of an element here).
traces = read_traces(run.frd)
for note in traces.notes[:2]:
    print("read:", note)
calibration = calibrate(traces, origin=0.0)
hertz = HertzLaw(R=R, E_star=E_STAR)
centres = {
    trace.P: float(np.sum(trace.x * np.clip(trace.p, 0, None)) / np.sum(np.clip(trace.p, 0, None)))
    for trace in traces.traces
}
for fit in calibration.right:
    a, L_I = float(hertz.half_width(fit.P)), float(hertz.normal_multiplier(fit.P))
    centre = centres[fit.P]
    print(
        f"P = {fit.P:6.0f}: x_edge = {fit.x_edge:.4f} +- {fit.a_error:.4f} (FE: centre "
        f"{centre:+.4f} + Hertz's a {a:.4f} = {centre + a:.4f}), "
        f"L_I = {fit.L_I:7.1f} +- {fit.L_I_error:5.1f} (Hertz {L_I:7.1f})"
    )

# %%
# The slip zone from the calibrated law (with the error its data propagate to it), from Hertz,
# and the FE model's own.  On this coarse mesh each edge is known to half an element (0.025
# mm) while it moves 0.06 mm from P1 to P2: the slope a'(P) that (17) needs through L_II is
# barely resolved, and the calibrated b comes with an error to match (about 1 mm here).  The
# tests' mesh (a(P2)/30) halves the error of a; a study's (a(P2)/100 or finer) is what the
# calibrated slip zone needs.
cycle = LoadCycle(**CYCLE)
law = calibration.law()
from_data = slip_zone(law, cycle, MU, edge="both")
error = float(law.error_of(lambda fitted: slip_zone(fitted, cycle, MU, edge="right").b))
from_hertz = slip_zone(hertz, cycle, MU, edge="both")
fe = run.result
print(
    f"stick boundary b (right edge): calibrated {from_data.b:.4f} +- {error:.4f}, "
    f"Hertz {from_hertz.b:.4f}, FE {fe.right.b:.4f} +- {fe.right.resolution:.4f}"
)

# %%
# The figure: the FE pressure near the right edge at P2 and the calibrated edge asymptote.
trace = traces.traces[-1]
fit = calibration.right[-1]
near = trace.x > 0.3
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.plot(trace.x[near], trace.p[near], "o", label=f"FE nodes, P = {trace.P:.0f}")
x = np.linspace(0.3, fit.x_edge, 200)
d = fit.x_edge - x
ax.plot(x, fit.L_I * np.sqrt(d) + fit.c * d**1.5, "-", label="fitted edge expansion")
ax.axvline(fe.right.b, color="k", ls=":", label="FE stick boundary")
ax.axvline(from_data.b, color="r", ls="--", label="b from the calibration")
ax.set_xlabel("x [mm]")
ax.set_ylabel("p [MPa]")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(folder / "fe_calibration.png", dpi=120)
print(f"figure: {folder / 'fe_calibration.png'}")
