"""Parameter studies: ``sweep`` and ``solve-batch`` over partitions, in one process or on Dask.

- :mod:`.cluster`: where tasks run -- this process (the default) or a Dask cluster
  (:class:`Cluster`: a ``LocalCluster`` of ``workers`` processes, or a ``scheduler`` address),
  with Dask's retries and progress bar; ``dask`` and ``distributed`` are the ``dask`` extra.
- :mod:`.dataset`: partitioned Parquet datasets in (a partition read at a time) and out (parts
  written into a hidden folder, renamed into place when complete).
- :mod:`.study`: read -> evaluate -> write mapped over the partitions; one implementation for
  every place the tasks run.
- :mod:`.cases`, :mod:`.solving`, :mod:`.solve_batch`: ``solve-batch``, the reference solver
  (:func:`asymslip.solver.solve`) per case, two result rows per case.
- :mod:`.sweep`: the sweep (:mod:`asymslip.sweep`'s chunk evaluation) over partitions.

Nothing here computes physics: the tasks call the same functions as one process does.

Examples
--------
>>> from asymslip.batch import Cluster, run_tasks
>>> Cluster(workers=2).option, Cluster(scheduler="tcp://127.0.0.1:8786").option
('workers', 'scheduler')
>>> run_tasks(len, ["one", "three"])  # no cluster: here, in order
[3, 5]
"""

from .cases import BatchSettings
from .cluster import Cluster, cluster_from_options, run_tasks
from .solve_batch import BatchSummary, solve_batch

__all__ = [
    "BatchSettings",
    "BatchSummary",
    "Cluster",
    "cluster_from_options",
    "run_tasks",
    "solve_batch",
]
