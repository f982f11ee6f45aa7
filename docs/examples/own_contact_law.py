"""
Your own contact law
====================

The asymptotic slip zone needs only the contact law a(P) and its edge multiplier L_I (19).
``asymslip derive`` (Python: :func:`asymslip.codegen.law_module.write_law_module`) takes a law
typed as P(a), derives dP/da and L_I with SymPy from the same formula record as the package's
own (19), establishes where the law is a valid incomplete-contact law (positive and
increasing), and writes a NumPy module that ``--law module`` (Python:
:class:`asymslip.ModuleLaw`) then uses like any built-in law.

On the command line::

    asymslip derive --P-of-a "pi*E_star*a**2/(4*R)" --params "R E_star" --name mylaw --out mylaw.py
    asymslip slip-zone --law module --module mylaw.py --param R=1 --param E_star=1 \\
        --mu 0.1 --P1 100 --Q1 0 --P2 105 --Q2 1
"""

# %%
# Hertz, typed by hand, against the built-in law
# ----------------------------------------------
import tempfile
from pathlib import Path

from asymslip import HertzLaw, LoadCycle, ModuleLaw, slip_zone
from asymslip.codegen.law_module import write_law_module

folder = Path(tempfile.mkdtemp(prefix="asymslip-law-"))
written = write_law_module(
    "pi*E_star*a**2/(4*R)", ["R", "E_star"], "typed_hertz", folder / "typed_hertz.py"
)
print(written.range_summary)

typed = ModuleLaw.from_file(written.path, R=1.0, E_star=1.0)
cycle = LoadCycle(P1=100.0, Q1=0.0, P2=105.0, Q2=1.0)
mine = slip_zone(typed, cycle, mu=0.1)
builtin = slip_zone(HertzLaw(R=1.0, E_star=1.0), cycle, mu=0.1)
print(f"typed law: b = {mine.b:.12f}, a1 = {mine.a1:.12f}")
print(f"built-in : b = {builtin.b:.12f}, a1 = {builtin.a1:.12f}")
print(f"difference in b: {abs(mine.b - builtin.b):.1e}")

# %%
# A law valid only on part of the half-widths
# -------------------------------------------
# P = E* a^2 - k a^3 increases only for a < 2 E*/(3 k); SymPy finds that range, the module
# records it, and a load beyond its top is refused with the reason instead of answered.
from asymslip import InputError

softening = write_law_module(
    "E_star*a**2 - k*a**3", ["E_star", "k"], "softening", folder / "softening.py"
)
print(softening.range_summary)
law = ModuleLaw.from_file(softening.path, E_star=1.0, k=0.01)
result = slip_zone(law, LoadCycle(P1=100.0, Q1=0.0, P2=105.0, Q2=1.0), mu=0.1)
print(f"P 100 -> 105: a1 = {result.a1:.4f}, b = {result.b:.4f}, width {result.slip_zone_width:.4f}")
try:
    slip_zone(law, LoadCycle(P1=1400.0, Q1=0.0, P2=1600.0, Q2=1.0), mu=0.1)
except InputError as error:
    print("refused:", error)

# %%
# The two laws side by side
# -------------------------
import matplotlib.pyplot as plt
import numpy as np

a = np.linspace(0.5, 60.0, 300)
fig, ax = plt.subplots(figsize=(6.5, 3.8))
ax.plot(a, typed.load(a), label="pi E* a^2/(4R) (Hertz, R = E* = 1)")
ax.plot(a, law.load(a), label="E* a^2 - k a^3 (E* = 1, k = 0.01)")
ax.axvline(2 / (3 * 0.01), color="0.5", ls=":", label="top of the valid range, a = 2E*/(3k)")
ax.set_xlabel("half-width a")
ax.set_ylabel("load P")
ax.legend()
fig.tight_layout()
