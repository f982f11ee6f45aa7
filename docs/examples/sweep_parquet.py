"""
Sweeps to Parquet and pandas
============================

A study of many cycles is one CSV file of cases in and one table out: ``asymslip sweep``
(Python: :func:`asymslip.sweep.sweep_file`) evaluates everything ``slip-zone`` reports for both
edges, whole chunks of rows at once, and writes one row per case.  Written as Parquet it reads
straight into pandas (or polars) with its types.  An invalid row is kept, with its reason in the
``error`` column, and the others go on.

On the command line::

    asymslip sweep CASES.csv --law hertz --R 1 --E-star 1 --mu 0.3 --out RESULTS.parquet
"""

# %%
# A grid of cycles
# ----------------
# 600 Hertzian cycles: ten load ranges dP/P1 from 1 % to 10 % and sixty slopes lambda/mu
# from 1.05 to 4, plus one row that slides as a whole (abs(Q2) > mu P2), to show how an invalid
# row is reported.
import tempfile
from pathlib import Path

import numpy as np

mu, P1 = 0.3, 100.0
lines = ["case,ratio,P1,Q1,P2,Q2"]
for dP in np.linspace(1.0, 10.0, 10).tolist():
    for ratio in np.linspace(1.05, 4.0, 60).tolist():
        lines.append(f"grid,{ratio!r},{P1!r},0,{P1 + dP!r},{ratio * mu * dP!r}")
lines.append("slides,0,100,0,110,40")
folder = Path(tempfile.mkdtemp(prefix="asymslip-sweep-"))
cases = folder / "cases.csv"
cases.write_text("\n".join(lines) + "\n")

# %%
# The sweep
# ---------
from asymslip import HertzLaw
from asymslip.sweep import sweep_file

law = HertzLaw(R=1.0, E_star=1.0)
summary = sweep_file(cases, law, folder / "results.parquet", mu=mu, progress=False)
print(summary.report())

# %%
# Into pandas
# -----------
import pandas as pd

table = pd.read_parquet(folder / "results.parquet")
print(f"{len(table)} rows, {len(table.columns)} columns; first ones: {list(table.columns[:12])}")
# The input columns come back as they were typed (text); the computed ones are numbers.
for column in ("ratio", "P1", "Q1", "P2", "Q2"):
    table[column] = pd.to_numeric(table[column])
print(table.loc[table["error"].notna(), ["case", "P2", "Q2", "error"]].to_string(index=False))

valid = table[table["error"].isna()].copy()
valid["width_over_a1"] = valid["slip_zone_width"] / valid["a1"]
valid["dP_over_P1"] = ((valid["P2"] - valid["P1"]) / valid["P1"]).round(4)
valid["paper_minus_b_in_accuracies"] = (valid["b_paper"] - valid["b"]) / valid["b_accuracy"]
print(
    valid.groupby("dP_over_P1")[["width_over_a1", "paper_minus_b_in_accuracies"]]
    .max()
    .round(4)
    .head(5)
    .to_string()
)

# %%
# The slip-zone width over the grid
# ---------------------------------
import matplotlib.pyplot as plt

fig, ax = plt.subplots(figsize=(6.5, 3.8))
for dP_over_P1, group in valid.groupby("dP_over_P1"):
    if round(dP_over_P1 * 100) % 3 == 1:
        ax.plot(group["ratio"], group["width_over_a1"], label=f"dP/P1 = {dP_over_P1:.0%}")
ax.set_xlabel("lambda / mu")
ax.set_ylabel("(a1 - b) / a1")
ax.set_title("Hertz, mu = 0.3: the slip-zone width from the sweep")
ax.legend()
fig.tight_layout()
