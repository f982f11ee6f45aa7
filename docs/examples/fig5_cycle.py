"""
The paper's Fig. 5 cycle
========================

The paper's worked example (Section 3.4, Fig. 5): a Hertzian contact, R = E* = 1, mu = 0.1,
loaded from P1 = 100 to P2 = 105 with lambda = dQ/dP = 0.2 (Q 0 -> 1) and no bulk tension.
We compute the slip zone at both edges, compare every estimate with the exact
Jaeger-Ciavarella stick boundary a(P_K), and draw the shear-traction difference q2 - q1: the
exact (47) against the asymptotic (49).
"""

# %%
# The slip zone
# -------------
# ``slip_zone`` returns the right-hand edge at the top level and the left-hand edge under
# ``left``.  Without bulk tension a symmetric contact has the same slip zone at both edges.
from asymslip import HertzLaw, LoadCycle, slip_zone

law = HertzLaw(R=1.0, E_star=1.0)
cycle = LoadCycle(P1=100.0, Q1=0.0, P2=105.0, Q2=1.0)
result = slip_zone(law, cycle, mu=0.1, edge="both")

print(f"a1 = {result.a1:.6f}, a2 = {result.a2:.6f}")
print(f"b (headline, second order)  = {result.b:.6f} +- {result.b_accuracy:.1e}")
print(f"b_paper (22)                = {result.b_paper:.6f}")
print(f"b_first_order (28)          = {result.b_first_order:.6f}")
print(f"b_corrective_stick (40)     = {result.b_corrective_stick:.6f}")
print(f"b_exact = a(P_K)            = {result.b_exact:.6f}")
print(f"slip-zone width a1 - b      = {result.slip_zone_width:.6f}")
print(f"left edge: b = {result.left.b:.6f} (same as the right: no bulk tension)")

# %%
# Each estimate minus the exact a(P_K).  For Hertz
# (22) agrees with a(P_K) through second order in dP/P1 (a result beyond the paper, which
# claims only the first).
for name in ("b", "b_paper", "b_first_order", "b_corrective_stick"):
    error = getattr(result, name) - result.b_exact
    print(f"{name:20s} - a(P_K) = {error:+.2e}")

# %%
# q2 - q1 across the contact
# --------------------------
# The exact (47) follows from the law's pressures; the asymptote (49) is evaluated in closed
# form.  ``stick_boundary="exact"`` builds (49) with b = a(P_K), as the paper did for its figure
# (see the errata: the density (15) solves (12) only for b from (17), ``"consistent"``).
import matplotlib.pyplot as plt
import numpy as np

from asymslip.tractions import traction_difference

x = np.linspace(0.0, result.a2, 400, endpoint=False)
paper = traction_difference(law, cycle, 0.1, x, stick_boundary="exact")
consistent = traction_difference(law, cycle, 0.1, x, stick_boundary="consistent")

fig, ax = plt.subplots(figsize=(7, 4))
ax.plot(x, paper.q_diff_exact, color="tab:blue", label="exact (47)")
ax.plot(x, paper.q_diff, "--", color="tab:red", label="asymptotic (49), b from (35)")
ax.plot(x, consistent.q_diff, ":", color="k", label="asymptotic (49), b from (17)")
ax.set_xlabel("x (from the contact centre)")
ax.set_ylabel("q2 - q1")
ax.set_title("Fig. 5: R = E* = 1, mu = 0.1, lambda = 0.2, P1 = 100, dP = 5")
ax.legend()
fig.tight_layout()

# %%
# How good is the asymptote?
# --------------------------
# The paper says the error is "only about 0.004 at 10 % of the distance in from the edge" and
# "about 0.01 at the centre"; its conclusion's "less than 0.01 %" is an erratum (the errors
# are absolute; relative, they are 5.7 % and 40 %).
check = traction_difference(law, cycle, 0.1, [0.9 * result.a2, 0.0], stick_boundary="exact")
for where, asymptotic, exact in zip(
    ("x = 0.9 a2", "x = 0"), check.q_diff, check.q_diff_exact, strict=True
):
    print(
        f"{where:10s}: (49) {asymptotic:.5f}, (47) {exact:.5f}, "
        f"error {abs(asymptotic - exact):.5f} ({abs(asymptotic - exact) / abs(exact):.1%})"
    )
