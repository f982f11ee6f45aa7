"""``python -m asymslip``: the same command line as the ``asymslip`` console script."""

import sys

from .cli import main

# Guarded: the worker processes of a local Dask cluster (--workers) are started by
# multiprocessing's spawn, which imports this module again under another name.
if __name__ == "__main__":
    sys.exit(main())
