"""From a contact law to the crack-nucleation site
================================================

A rounded-flat pad on a specimen under bulk tension, the cycle of a fretting-fatigue test
(or of a blade root over a flight): where does the edge slip, what is the stress there over
the cycle, and where -- and how hard -- do cracks start?  Conventions of every number below:
``asymslip.stress`` (x from the contact centre, depth into the specimen that carries the
bulk tension, tension positive, plane strain).
"""

# %%
# The contact law and the cycle
# -----------------------------
# A flat punch of half-width c = 1 with rounded corners of radius R = 10 (any consistent
# units), E* = 1.  Between the two states of the cycle the normal load grows so that the
# contact half-width goes from 2 to 2.1, the shear force by 0.6 mu of the load change, and
# the bulk tension by pi eta a1 / (4 mu) = 0.5 of it.  The slip zone comes from the paper's
# edge asymptotes (the headline b is second order, with its stated accuracy).
import matplotlib.pyplot as plt
import numpy as np

from asymslip import FlatRoundedLaw, LoadCycle, slip_zone
from asymslip.nucleation import Criterion, Material, nucleation
from asymslip.solver import solve
from asymslip.stress.asymptote import edge_amplitude
from asymslip.stress.solver_source import solver_stress

law = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
mu = 0.3
P1, P2 = float(law.load(2.0)), float(law.load(2.1))
eta = 0.5 * 4 * mu / (np.pi * 2.0)
cycle = LoadCycle(P1, 0.0, P2, 0.6 * mu * (P2 - P1), 0.0, eta * (P2 - P1))
zone = slip_zone(law, cycle, mu, edge="both")
print(
    f"right edge: a1 = {zone.a1:.4f}, a2 = {zone.a2:.4f}, b = {zone.b:.4f} +- {zone.b_accuracy:.1e}"
)
print(f"left edge slips: {bool(zone.left.slip_direction)}")

# %%
# The stress amplitude at the slipping edge, from the asymptote
# --------------------------------------------------------------
# No solver: the field of the square-root loads (4) and (49), state 2 minus state 1, each
# value with a stated accuracy that grows with the distance from the edge.
x = np.linspace(zone.a2 - 0.15, zone.a2 + 0.05, 41)
depth = np.linspace(0.0, 0.1, 21)
X, Y = np.meshgrid(x, depth)
asymptote = edge_amplitude(law, cycle, mu, X.ravel(), Y.ravel())
amplitude = asymptote.amplitude.sxx.reshape(X.shape)
print(f"largest amplitude of sxx near the right edge: {np.abs(amplitude).max():.4f}")
print(f"largest stated accuracy there: {asymptote.accuracy.max():.2e}")

# %%
# Both extremes of the cycle, from the reference solver
# ------------------------------------------------------
# The criteria need the stress at each extreme (the locked-in shear of the history), which
# only the solver gives.  Its amplitude agrees with the asymptote within the stated accuracy.
result = solve(law, cycle, mu, elements=2000)
solver = solver_stress(result, X.ravel(), Y.ravel())
difference = np.abs(solver.amplitude.sxx - asymptote.amplitude.sxx)
print(f"solver b = {result.right.b:.4f} +- {result.right.b_error:.1e}")
print(
    "asymptote vs solver, sxx amplitude: largest difference "
    f"{difference.max():.2e}, within the stated accuracy at "
    f"{np.mean(difference <= asymptote.accuracy):.0%} of the points"
)

# %%
# Where cracks start
# ------------------
# Smith-Watson-Topper and Findley on the critical plane, searched over the planes through
# every point near both edges, and the theory of critical distances (L = 0.02) below the
# surface hot spot; E and nu of the specimen give the strains.
material = Material(E=2 * (1 - 0.3**2), nu=0.3, k_findley=0.3, L=0.02)
found = nucleation(result, material, [Criterion.SWT, Criterion.FINDLEY, Criterion.RUIZ])
for finding in found.findings:
    angle = "" if finding.angle is None else f", plane normal at {finding.angle:.1f} deg"
    print(
        f"{finding.edge:>5} {finding.criterion:>8} {finding.method:>15}: {finding.value:.4g} at "
        f"x = {finding.x:.4f}, depth {finding.depth:.4f}{angle}"
    )

# %%
# The picture
# -----------
figure, (left, right) = plt.subplots(1, 2, figsize=(10, 3.6))
image = left.contourf(x, depth, amplitude, levels=24, cmap="RdBu_r")
figure.colorbar(image, ax=left)
left.set_ylim(depth.max(), 0)
left.set_title("sxx amplitude near the right edge (asymptote)")
swt = next(m for m in found.maps if m.edge == "right" and m.criterion == "swt")
image = right.contourf(swt.x, swt.depth, swt.values, levels=24)
figure.colorbar(image, ax=right)
peak = found.find("right", "swt", "peak")
right.plot([peak.x], [peak.depth], "wx", markersize=10)
right.set_ylim(swt.depth.max(), 0)
right.set_title("SWT near the right edge (solver)", loc="left")
for axis in (left, right):
    axis.set_xlabel("x")
    axis.set_ylabel("depth")
figure.tight_layout()
figure.savefig("law_to_crack_site.png", dpi=100)
print("wrote law_to_crack_site.png")
