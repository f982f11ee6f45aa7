"""
The reference solver on a general load path
===========================================

The asymptotes assume the paper's proportional cycle: a straight line between two load
states.  The reference solver (``asymslip solve``, Python: :func:`asymslip.solver.solve`) takes
any closed, piecewise-linear path of (P, Q, sigma, M) points -- here a four-point loop in which
the normal load, the shear force and the bulk tension change out of phase -- and runs it period
after period until the tractions repeat.  It is the project's independent truth where no exact
solution exists.

On the command line the path is a CSV file with columns ``P,Q,sigma,M``::

    asymslip solve --law hertz --R 1 --E-star 1 --mu 0.3 --path PATH.csv --out DIR
"""

# %%
# The path and the steady state
# -----------------------------
import numpy as np

from asymslip import HertzLaw
from asymslip.solver import LoadPath, solve

law = HertzLaw(R=1.0, E_star=1.0)
path = LoadPath(
    np.array(
        [
            # P      Q     sigma
            [100.0, 0.0, 0.0],
            [110.0, 8.0, 0.01],
            [105.0, 12.0, 0.03],
            [95.0, 4.0, 0.02],
        ]
    ),
    labels=("A", "B", "C", "D"),
)
result = solve(law, path, mu=0.3, elements=2000)
print(f"steady after {result.cycles} periods: {result.steady} ({result.seconds:.2f} s)")
for side in ("right", "left"):
    edge = result.edge(side)
    print(f"{side:5s} edge: permanent stick zone ends at b = {edge.b:.4f} +- {edge.b_error:.4f}")
print(f"largest slip range (peak to peak): {result.slip_range.max():.3e}")
print(f"frictional energy per period: {np.trapezoid(result.energy, result.x):.3e}")
print(*result.warnings, sep="\n")

# %%
# Tractions at the four points of the path
# ----------------------------------------
import matplotlib.pyplot as plt

fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
for state in result.states:
    top.plot(result.x, state.shear, label=f"q at {state.label} (P = {state.P:g}, Q = {state.Q:g})")
    top.plot(result.x, 0.3 * state.pressure, color="0.8", lw=0.8)
top.fill_between(
    result.x,
    0,
    1,
    where=result.permanent_stick,
    color="tab:green",
    alpha=0.15,
    transform=top.get_xaxis_transform(),
    label="permanent stick",
)
top.set_ylabel("shear traction q (grey: mu p)")
top.legend(fontsize=8)
bottom.plot(result.x, result.slip_range, color="k")
bottom.set_ylabel("slip range per period")
bottom.set_xlabel("x (from the contact centre)")
fig.tight_layout()
