"""
A parameter study on a local Dask cluster
=========================================

A fretting rig's cylindrical pad (Hertz, R = 50 mm, E* = 63 GPa) runs a load spectrum: the
normal load rises by 1 to 8 % from 1000 N/mm each cycle while the shear force follows at
dQ/dP = lambda, and the coefficient of friction scatters from 0.3 to 0.6.  Which cycles slip
most at the contact edge, and can the asymptotes be trusted there?

The study is a table of cycles -- here 40,000, written as a partitioned Parquet dataset of
four files, as a larger study would be -- swept on a ``LocalCluster`` of two worker processes
(``asymslip sweep CASES/ --workers 2 --out RESULTS/`` on the command line), with a few of its
cycles solved by the reference solver on the same cluster (``asymslip solve-batch``) to check
the asymptotic slip zone against it.  Units: N, mm, MPa.

A script that starts worker processes keeps its work under ``if __name__ == "__main__":``:
each worker imports the script again, and must not run the study itself.
"""

# %%
# The cycles
# ----------
# A grid of load growth dP/P1, slope ratio lambda/mu (1.05 to 3: every cycle slips forward at
# the right edge) and friction coefficient; one row per cycle, with its own mu.
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

from asymslip import HertzLaw
from asymslip.batch import BatchSettings, Cluster, solve_batch
from asymslip.batch.cluster import connect
from asymslip.batch.sweep import sweep_study

R, E_STAR, P1 = 50.0, 63000.0, 1000.0
law = HertzLaw(R=R, E_star=E_STAR)


def cycles() -> pa.Table:
    growth, ratio, mu = np.meshgrid(
        np.linspace(0.01, 0.08, 40), np.linspace(1.05, 3.0, 50), np.linspace(0.3, 0.6, 20)
    )
    dP = P1 * growth.ravel()
    mu = mu.ravel()
    return pa.table(
        {
            "P1": np.full(dP.size, P1),
            "Q1": np.zeros(dP.size),
            "P2": P1 + dP,
            "Q2": ratio.ravel() * mu * dP,
            "mu": mu,
        }
    )


def write_dataset(table: pa.Table, folder: Path) -> None:
    folder.mkdir()
    for index, start in enumerate(range(0, table.num_rows, 10_000)):
        pq.write_table(table.slice(start, 10_000), folder / f"cycles-{index}.parquet")


# %%
# The study on two workers
# ------------------------
# One cluster for both steps.  The sweep runs in tasks of 5,000 rows, each reading its rows of
# the dataset and writing one part of the results; the output folder appears only when every
# part is written.  Then four cycles whose slip zones span 1 to 4 % of the contact (5 to 20
# elements of the solver's grid: smaller ones it cannot resolve) go to the reference solver
# (1,000 elements each).
def study(folder: Path) -> tuple[pa.Table, list[dict]]:
    write_dataset(cycles(), folder / "cycles")
    with connect(Cluster(workers=2)) as client:
        summary = sweep_study(
            folder / "cycles",
            law,
            f"{folder}/results/",
            rows_per_task=5000,
            edge="right",
            client=client,
            progress=False,
        )
        print(f"swept {summary.rows:,} cycles in {summary.seconds:.1f} s on 2 workers")
        results = pq.read_table(folder / "results")
        relative = np.asarray(results["slip_zone_width"]) / np.asarray(results["a1"])
        resolved = np.flatnonzero((relative > 0.01) & (relative < 0.04))
        order = resolved[np.argsort(relative[resolved])]
        picks = order[np.linspace(0, order.size - 1, 4).astype(int)]
        checked = results.take(picks).select(["P1", "Q1", "P2", "Q2", "mu"])
        pq.write_table(checked, folder / "check.parquet")
        settings = BatchSettings("hertz", (("R", R), ("E_star", E_STAR)), elements=1000)
        solve_batch(
            folder / "check.parquet",
            folder / "solved.parquet",
            settings,
            cases_per_task=1,
            client=client,
            progress=False,
        )
    solved = pq.read_table(folder / "solved.parquet").to_pylist()
    return results, [row for row in solved if row["edge"] == "right"]


# %%
# What it says
# ------------
# The map: the slip-zone width relative to the contact, a1 - b over a1, against the load growth
# and lambda/mu (at the middle friction coefficient): it grows with both, as (28) says, like
# (lambda/mu - 1) dP/P1.  The check: the headline b against the solver's, in elements.
def report(results: pa.Table, solved: list[dict]) -> None:
    width = np.asarray(results["slip_zone_width"]) / np.asarray(results["a1"])
    mu = np.asarray(results["mu"])
    ratio = np.asarray(results["Q2"]) / (mu * (np.asarray(results["P2"]) - P1))
    growth = (np.asarray(results["P2"]) - P1) / P1
    middle = np.isclose(mu, np.unique(mu)[10])
    print(f"relative slip-zone width: {width.min():.2e} to {width.max():.2e}")
    for row in solved:
        print(
            f"mu {row['mu']:.3f}, dP/P1 {(row['P2'] - P1) / P1:.3f}: slip zone "
            f"{(row['a1'] - row['b']) / row['solver_element_size']:.1f} elements, solver b = "
            f"{row['b']:.6f} +- {row['b_error']:.2g} mm, asymptote "
            f"{row['asymptote_b_elements']:+.2f} elements from it"
        )
    worst = max(abs(row["asymptote_b_elements"]) for row in solved)
    print(f"largest difference of the headline b from the solver: {worst:.2f} elements")
    figure, axes = plt.subplots(1, 2, figsize=(10, 4))
    shown = axes[0].tricontourf(growth[middle], ratio[middle], width[middle], levels=20)
    figure.colorbar(shown, ax=axes[0], label="(a1 - b) / a1")
    axes[0].set(xlabel="dP / P1", ylabel="lambda / mu", title=f"mu = {np.unique(mu)[10]:.3f}")
    axes[1].bar(range(len(solved)), [row["asymptote_b_elements"] for row in solved])
    axes[1].axhline(1, color="grey", lw=0.8)
    axes[1].axhline(-1, color="grey", lw=0.8)
    axes[1].set(xlabel="checked cycle", ylabel="b (asymptote) - b (solver) [elements]")
    figure.tight_layout()
    figure.savefig("parameter_study.png", dpi=120)


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as scratch:
        report(*study(Path(scratch)))
