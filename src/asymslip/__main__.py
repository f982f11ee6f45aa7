"""``python -m asymslip``: the same command line as the ``asymslip`` console script."""

import sys

from .cli import main

sys.exit(main())
