"""Where a study's tasks run: in this process (the default) or on a Dask cluster.

A study (a sweep, a batch of solves) is cut into tasks -- one partition of its cases each --
and :func:`run_tasks` maps one function over them.  In one process the tasks run in order,
here.  On a cluster (:class:`Cluster`: a ``LocalCluster`` of ``workers`` processes on this
machine, or an existing scheduler at ``scheduler``) they are submitted at once through
``distributed``; a task whose worker dies is re-run by the scheduler on another worker (up to
its ``allowed-failures``, 3 by default), a task that raises is re-run ``retries`` times, and
the results come back in the order of the tasks.  Progress is Dask's own: distributed's text
progress bar, drawn only when standard output is a terminal.

The function and its tasks must pickle (they travel to the workers); so must what it returns.
``dask`` and ``distributed`` are the optional ``dask`` extra; without them only the one-process
path exists, and asking for a cluster is one :class:`~asymslip.errors.InputError` naming the
extra.

Examples
--------
>>> from asymslip.batch.cluster import run_tasks
>>> run_tasks(abs, [-1, 2, -3])  # one process: the tasks in order, here
[1, 2, 3]
"""

from __future__ import annotations

import logging
import sys
import uuid
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, TypeVar

from ..errors import InputError

Task = TypeVar("Task")
Result = TypeVar("Result")

#: What to install for a cluster.
INSTALL = "pip install 'asymslip[dask]'"
#: Re-runs of a task that raised (a worker that dies is the scheduler's business: its
#: ``distributed.scheduler.allowed-failures``).
DEFAULT_RETRIES = 2
#: How long to try to reach a scheduler before giving up.
SCHEDULER_TIMEOUT = "20s"


class StudyError(RuntimeError):
    """A study that cannot finish: a task ended its worker process more often than the
    scheduler allows (a case that crashes the interpreter, a worker out of memory).  Nothing
    has been written."""


def dask_available() -> bool:
    """Whether ``dask.distributed`` can be imported (the ``dask`` extra)."""
    try:
        import distributed  # noqa: F401
    except ImportError:
        return False
    return True


def require_distributed(option: str) -> None:
    """Refuse a cluster when the ``dask`` extra is missing, naming the option and the extra."""
    if not dask_available():
        raise InputError(option, f"a Dask cluster needs dask and distributed: {INSTALL}")


@dataclass(frozen=True)
class Cluster:
    """A Dask cluster to run on: ``workers`` local processes, or the scheduler at an address.

    Attributes
    ----------
    workers
        Start a ``LocalCluster`` of this many worker processes (one thread each) on this
        machine, for the duration of the study.
    scheduler
        Connect to an existing scheduler (``tcp://host:8786``) instead; its workers must see
        the files the study reads and writes at the same paths (a shared file system).
    retries
        Re-runs of a task that raised an exception.
    """

    workers: int | None = None
    scheduler: str | None = None
    retries: int = DEFAULT_RETRIES

    def __post_init__(self) -> None:
        if (self.workers is None) == (self.scheduler is None):
            raise InputError("workers", "give either workers (a local cluster) or a scheduler")
        if self.workers is not None and (
            isinstance(self.workers, bool) or not isinstance(self.workers, int) or self.workers < 1
        ):
            raise InputError("workers", "must be a whole number >= 1", self.workers)
        if self.scheduler is not None and not str(self.scheduler).strip():
            raise InputError("scheduler", "must be an address such as tcp://host:8786")
        if isinstance(self.retries, bool) or not isinstance(self.retries, int) or self.retries < 0:
            raise InputError("retries", "must be a whole number >= 0", self.retries)

    @property
    def option(self) -> str:
        """The parameter that asked for this cluster (named in errors)."""
        return "workers" if self.workers is not None else "scheduler"


def cluster_from_options(
    workers: int | None, scheduler: str | None, retries: int = DEFAULT_RETRIES
) -> Cluster | None:
    """The cluster the options ask for, or None for one process; refuses both at once."""
    if workers is not None and scheduler is not None:
        raise InputError("scheduler", "give either --workers or --scheduler, not both")
    if workers is None and scheduler is None:
        return None
    cluster = Cluster(workers, scheduler, retries)
    require_distributed(cluster.option)
    return cluster


@contextmanager
def connect(cluster: Cluster) -> Iterator[Any]:
    """A ``distributed.Client`` on the cluster (a ``LocalCluster`` is started and stopped)."""
    require_distributed(cluster.option)
    from distributed import Client, LocalCluster

    quiet = logging.ERROR  # a restarted worker is reported by the result, not by log noise
    if cluster.scheduler is not None:
        try:
            client = Client(cluster.scheduler, timeout=SCHEDULER_TIMEOUT)
        except OSError as error:
            raise InputError(
                "scheduler", f"cannot reach the scheduler at {cluster.scheduler}: {error}"
            ) from None
        try:
            yield client
        finally:
            client.close()
        return
    local = LocalCluster(
        n_workers=cluster.workers,
        threads_per_worker=1,
        processes=True,
        dashboard_address=":0",  # the HTTP server on a free port: 8787 may be taken
        silence_logs=quiet,
    )
    try:
        with Client(local) as client:
            yield client
    finally:
        local.close()


def run_tasks(
    function: Callable[[Task], Result],
    tasks: Sequence[Task],
    cluster: Cluster | None = None,
    *,
    progress: bool | None = None,
    name: str = "task",
    client: Any = None,
) -> list[Result]:
    """``[function(task) for task in tasks]``, in this process or on a cluster.

    Parameters
    ----------
    function
        Run once per task; on a cluster it must not depend on this process's state.
    tasks
        The tasks, in order; the results come back in the same order.
    cluster
        None: here, one task after the other.  Else the cluster to submit them to.
    progress
        Draw distributed's progress bar (on a cluster); default: when standard output is a
        terminal.
    name
        The tasks' key prefix on the cluster (what the dashboard shows).
    client
        An open ``distributed.Client`` to use instead of connecting to ``cluster``.

    Raises
    ------
    StudyError
        A task's workers died more often than the scheduler allows.
    Exception
        Whatever a task raised on its last try.
    """
    if cluster is None and client is None:
        return [function(task) for task in tasks]
    if client is None:
        assert cluster is not None
        with connect(cluster) as opened:
            return run_tasks(function, tasks, cluster, progress=progress, name=name, client=opened)
    retries = cluster.retries if cluster is not None else DEFAULT_RETRIES
    # Keys unique to this call: the scheduler would hand back an earlier study's results for
    # keys it still holds.
    run = uuid.uuid4().hex[:12]
    keys = [f"{name}-{run}-{index}" for index in range(len(tasks))]
    futures = client.map(function, list(tasks), key=keys, retries=retries, pure=False)
    try:
        if progress is None:
            progress = sys.stdout.isatty()
        if progress and futures:
            from distributed import progress as dask_progress

            dask_progress(futures, multi=False)  # blocks until every task has finished
        return list(client.gather(futures))
    except Exception as error:
        from distributed.scheduler import KilledWorker

        if not isinstance(error, KilledWorker):
            raise
        index = keys.index(error.task) if error.task in keys else None
        which = f"task {index} of {len(keys)}" if index is not None else "a task"
        raise StudyError(
            f"{which} ended its worker process {error.allowed_failures} times (a crash of the "
            "interpreter, or a worker out of memory: try smaller tasks); the study was stopped "
            "and nothing was written"
        ) from None
    finally:
        client.cancel(futures)
