"""
Bulk tension, and why the headline is not (22)
===============================================

When the differential bulk tension sigma changes along the cycle (eta = dsigma/dP != 0), the
paper's closed form (22) carries a spurious term of second order in dP (erratum 22-T): it
weights the tension at the moving contact edge, where the tension acts at the field point.
asymslip's headline ``b`` is therefore the second-order b2 derived in
``derivations/second_order_slip_zone.py``; (22) is kept as ``b_paper``.

Here the independent reference solver settles it on one cycle: a Hertzian contact with
lambda/mu = 2 and pi eta a1/(4 mu) = 0.2, a1 = 2, the contact growing by a2/a1 = 1.10 (one
of the cycles of the README's table "How far to trust b").
"""

# %%
# The cycle
# ---------
import math

from asymslip import HertzLaw, LoadCycle, slip_zone

law = HertzLaw(R=1.0, E_star=1.0)
mu = 0.3
P1 = math.pi  # a1 = 2 (Hertz: P = pi E* a^2 / (4 R))
P2 = P1 * 1.10**2  # a grows as sqrt(P): a2/a1 = 1.10
a1 = float(law.half_width(P1))
lam = 2 * mu  # lambda/mu = 2
eta = 0.2 * 4 * mu / (math.pi * a1)  # pi eta a1 / (4 mu) = 0.2
cycle = LoadCycle(P1=P1, Q1=0.0, P2=P2, Q2=lam * (P2 - P1), sigma1=0.0, sigma2=eta * (P2 - P1))
estimates = slip_zone(law, cycle, mu, edge="both")
print(f"a1 = {a1:.4f}, a2/a1 = {estimates.a2 / a1:.4f}, eta = {eta:.5f}")
for side, edge in (("right", estimates), ("left", estimates.left)):
    print(
        f"{side:5s}: b = {edge.b:.4f} (+- {edge.b_accuracy:.1e}), (22) {edge.b_paper:.4f}, "
        f"(28) {edge.b_first_order:.4f}, (40) {edge.b_corrective_stick:.4f}"
    )
print("warnings:", *estimates.warnings, sep="\n  ")

# %%
# The reference solver
# --------------------
# Incremental half-plane contact with Coulomb friction, run period after period to its
# steady state; each stick boundary comes with an error bound of about one element.  It never
# imports the asymptotes: ``with_asymptotes`` only sets them side by side.
from asymslip.solver import solve
from asymslip.solver.compare import with_asymptotes

solved = with_asymptotes(solve(law, cycle, mu, elements=4000), law, cycle, mu)
print(f"solver: {solved.grid.count} elements of {solved.element_size:.4f}, steady: {solved.steady}")
for side in ("right", "left"):
    edge = solved.edge(side)
    print(f"{side:5s}: solver b = {edge.b:.4f} +- {edge.b_error:.4f}")
    for name in ("b", "b_paper", "b_first_order", "b_corrective_stick"):
        entry = edge.asymptotes[name]
        print(f"    {name:20s} off by {entry['elements']:+7.2f} elements")

# %%
# Each estimate's error, in solver elements
# -----------------------------------------
# (22) is off by several times the solver's bound, with opposite signs at the two edges (the
# spurious term changes sign with the edge); the first-order (28) and (40) are off by their
# first-order error; b2 is within the solver's own bound at both edges.  At a2/a1 = 1.10 the
# validity measures already warn (eq24, eq27 above 0.1), and still b2 holds.
import matplotlib.pyplot as plt
import numpy as np

names = ["b", "b_paper", "b_first_order", "b_corrective_stick"]
labels = ["b (b2)", "(22) b_paper", "(28)", "(40)"]
right = [solved.right.asymptotes[name]["elements"] for name in names]
left = [solved.left.asymptotes[name]["elements"] for name in names]
position = np.arange(len(names))
fig, ax = plt.subplots(figsize=(7, 3.8))
ax.bar(position - 0.2, right, 0.4, label="right edge")
ax.bar(position + 0.2, left, 0.4, label="left edge")
ax.axhspan(-1, 1, color="0.85", zorder=0, label="solver bound (about 1 element)")
ax.set_xticks(position, labels)
ax.set_ylabel("estimate - solver (elements)")
ax.set_title("Hertz, lambda/mu = 2, pi eta a1/(4 mu) = 0.2, a2/a1 = 1.10")
ax.legend()
fig.tight_layout()
