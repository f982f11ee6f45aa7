"""
A contact law from a finite-element (P, a) table
================================================

For a real geometry the contact law a(P) comes from a model: a table of normal loads and
contact half-widths.  :class:`asymslip.TableLaw` (``--law table --table FILE.csv`` on the
command line, header ``P,a``) fits a monotone cubic to log a against log P, takes L_I from
(19), and says how far the fit can be trusted from leave-one-out refits.

Here the "FE model" is the exact law of a flat punch with rounded corners (c = 1, R = 10,
E* = 1) sampled at 12 loads, so the fitted slip zone can be checked against the exact one.
"""

# %%
# The table and the fitted law
# ----------------------------
import numpy as np

from asymslip import FlatRoundedLaw, LoadCycle, TableLaw, slip_zone

exact_law = FlatRoundedLaw(c=1.0, R=10.0, E_star=1.0)
P_table = np.geomspace(0.05, 0.5, 12)
a_table = exact_law.half_width(P_table)
table_law = TableLaw(P_table, a_table, source="12-point table")
print(table_law)
for P in (0.1, 0.2, 0.3):
    error = table_law.error_estimate(P)
    print(
        f"P = {P}: a = {float(table_law.half_width(P)):.6f} "
        f"(exact {float(exact_law.half_width(P)):.6f}, stated error {float(error['a']):.1e}), "
        f"L_I stated error {float(error['L_I']):.1e}"
    )

# %%
# The slip zone from the table, with its error
# --------------------------------------------
# ``error_of`` propagates the fit's error to any result: here the headline stick boundary.
mu = 0.3
cycle = LoadCycle(P1=0.2, Q1=0.0, P2=0.21, Q2=0.006)
fitted = slip_zone(table_law, cycle, mu)
exact = slip_zone(exact_law, cycle, mu)
stated = float(table_law.error_of(lambda law: slip_zone(law, cycle, mu).b))
print(f"table law: b = {fitted.b:.7f} +- {stated:.1e} (fit), width {fitted.slip_zone_width:.3e}")
print(f"exact law: b = {exact.b:.7f}, a(P_K) = {exact.b_exact:.7f}")
print(f"true error of the fitted b: {abs(fitted.b - exact.b):.1e} (stated {stated:.1e})")

# %%
# Loads outside the table are flagged, not silently extrapolated
# --------------------------------------------------------------
outside = slip_zone(table_law, LoadCycle(P1=0.45, Q1=0.0, P2=0.6, Q2=0.05), mu)
print(*outside.warnings, sep="\n")

# %%
# The fit and its stated error across the table
# ---------------------------------------------
import matplotlib.pyplot as plt

P = np.geomspace(0.05, 0.5, 400)
stated_a = table_law.error_estimate(P)["a"]
true_a = np.abs(table_law.half_width(P) - exact_law.half_width(P))
fig, ax = plt.subplots(figsize=(6.5, 3.8))
ax.loglog(P, stated_a, label="stated error of a (leave-one-out)")
ax.loglog(P, np.maximum(true_a, 1e-17), label="true error of a")
ax.plot(P_table, np.full_like(P_table, 1e-16), "k|", ms=12, label="table points")
ax.set_xlabel("P")
ax.set_ylabel("error of the fitted half-width")
ax.legend()
fig.tight_layout()
