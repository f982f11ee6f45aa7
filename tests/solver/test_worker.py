"""One solve is a self-contained job: picklable in and out, the same answer in a worker process.

A batch runner (``solve-batch``, one process or a Dask cluster) maps ``asymslip.solver.solve``
over cases in worker processes.  Nothing global is set up or left behind by a solve (no thread
pool: it calls no BLAS and NumPy's FFT uses one thread), so a fresh process gives the same
numbers as this one.
"""

from __future__ import annotations

import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np

from asymslip import HertzLaw, LoadCycle
from asymslip.solver import LoadPath, SolverResult, solve

LAW = HertzLaw(R=1.0, E_star=1.0)
CYCLE = LoadCycle(100.0, 0.0, 105.0, 1.0, 0.0, 0.05)


def _job(arguments: tuple[object, object, float, int]) -> SolverResult:
    law, loading, mu, elements = arguments
    return solve(law, loading, mu, elements=elements, steps=4)


def test_inputs_and_results_pickle_and_come_back_equal():
    result = solve(LAW, CYCLE, 0.1, elements=300, steps=4)
    again = pickle.loads(pickle.dumps(result))
    assert again.right.b == result.right.b and again.left.b == result.left.b
    assert np.array_equal(again.states[1].shear, result.states[1].shear)
    assert again.to_dict() == result.to_dict()
    for value in (LAW, CYCLE, LoadPath([[100.0, 0.0], [105.0, 1.0]])):
        assert pickle.loads(pickle.dumps(value)) is not None


def test_a_solve_in_a_fresh_worker_process_gives_the_same_numbers():
    here = _job((LAW, CYCLE, 0.1, 300))
    context = multiprocessing.get_context("spawn")  # a fresh interpreter, as a cluster's
    with ProcessPoolExecutor(max_workers=1, mp_context=context) as pool:
        there = pool.submit(_job, (LAW, CYCLE, 0.1, 300)).result()
    assert (there.right.b, there.left.b) == (here.right.b, here.left.b)
    assert np.array_equal(there.states[0].shear, here.states[0].shear)
    assert np.array_equal(there.energy, here.energy)
