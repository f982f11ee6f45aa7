"""
Calibration from pressure traces
================================

For a real geometry the paper's method needs each edge's law a(P) and multiplier L_I,
"found numerically".  ``asymslip calibrate TRACES.csv`` (Python:
:func:`asymslip.calibration.calibrate`) reads nodal contact pressures at several loads, fits
each edge with p = L_I sqrt(a - x) + c (a - x)^(3/2) over a window the data choose, states the
error of every a and L_I, and builds each edge's law.

The "finite-element export" here is Hertz's exact pressure (48) sampled at 120 nodes across
the contact at six loads, so every fitted number can be checked against the exact one.
"""

# %%
# Pressure traces, written as an FE export would be
# -------------------------------------------------
import tempfile
from pathlib import Path

import numpy as np

from asymslip_gen.hertz import hertz_half_width, hertz_normal_edge_multiplier
from asymslip_gen.tractions import hertz_pressure

R, E_star = 1.0, 1.0
loads = np.array([80.0, 90.0, 100.0, 110.0, 120.0, 130.0])
nodes = np.linspace(-14.0, 14.0, 121)
rows = [(float(P), float(x), float(hertz_pressure(x, P, R, E_star))) for P in loads for x in nodes]
folder = Path(tempfile.mkdtemp(prefix="asymslip-traces-"))
traces_csv = folder / "traces.csv"
traces_csv.write_text("P,x,p\n" + "".join(f"{P!r},{x!r},{p!r}\n" for P, x, p in rows))
print(f"{len(rows)} rows written to {traces_csv.name}")

# %%
# Fitting every edge at every load
# --------------------------------
from asymslip.calibration import calibrate, read_traces

calibration = calibrate(read_traces(traces_csv))
right = calibration.columns("right")
exact_a = hertz_half_width(right["P"], R, E_star)
exact_L = hertz_normal_edge_multiplier(right["P"], R, E_star)
print("   P      a (fit)  +- error   true error   L_I (fit)  +- error   true error")
for P, a, a_err, a_true, L, L_err, L_true in zip(
    right["P"],
    right["a"],
    right["a_error"],
    exact_a,
    right["L_I"],
    right["L_I_error"],
    exact_L,
    strict=True,
):
    print(
        f"{P:5.0f}  {a:9.5f}  {a_err:8.1e}  {abs(a - a_true):9.1e}"
        f"   {L:9.5f}  {L_err:8.1e}  {abs(L - L_true):9.1e}"
    )

# %%
# The slip zone from the calibrated edges
# ---------------------------------------
# Each edge uses its own law and multipliers (an asymmetric contact gets two different slip
# zones); the error of any result follows from the calibration's with ``error_of``.
from asymslip import HertzLaw, LoadCycle, slip_zone

law = calibration.law()
cycle = LoadCycle(P1=100.0, Q1=0.0, P2=105.0, Q2=1.0)
calibrated = slip_zone(law, cycle, mu=0.1)
stated = float(law.error_of(lambda law: slip_zone(law, cycle, mu=0.1).b))
hertz = slip_zone(HertzLaw(R=R, E_star=E_star), cycle, mu=0.1)
print(
    f"calibrated: b = {calibrated.b:.5f} +- {stated:.1e}; "
    f"Hertz, (17) with (19), (21): {hertz.b_paper:.5f}"
)
print(f"calibrated b minus Hertz (17): {abs(calibrated.b - hertz.b_paper):.1e}")

# %%
# One trace and its fitted edge asymptote
# ---------------------------------------
import matplotlib.pyplot as plt

fit = calibration.right[2]  # P = 100
x = nodes[nodes > 0]
p = hertz_pressure(x, fit.P, R, E_star)
near = np.linspace(fit.window[0], fit.x_edge, 100)
fig, ax = plt.subplots(figsize=(6.5, 3.8))
ax.plot(x, p, "o", ms=3, label=f"nodal pressures, P = {fit.P:g}")
ax.plot(
    near,
    fit.L_I * np.sqrt(fit.x_edge - near) + fit.c * (fit.x_edge - near) ** 1.5,
    lw=2,
    label="fit: L_I sqrt(a - x) + c (a - x)^(3/2)",
)
ax.axvline(fit.x_edge, color="0.5", ls=":", label=f"fitted edge a = {fit.x_edge:.4f}")
ax.set_xlabel("x")
ax.set_ylabel("p")
ax.legend()
fig.tight_layout()
