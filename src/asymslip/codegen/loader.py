"""Load the ``derivations/`` folder as a package, without touching ``sys.path``.

The derivation scripts form one package, registered under the fixed name
:data:`DERIVATIONS_PACKAGE` from wherever the folder is; its submodules are found through the
package's own ``__path__`` (``submodule_search_locations``), never through ``sys.path``.  So a
script imports its neighbours **relatively**::

    from ._glossary import a, dP_da                 # shared symbols
    from .section2_calibrations import normal_multiplier  # another script's building block

and the project's own code reaches a script only through this module::

    from asymslip.codegen.loader import import_derivation
    calibrations = import_derivation(Path("derivations"), "section2_calibrations")

A plain ``import section2_calibrations`` (the style before) fails with "attempted relative
import with no known parent package": that is intended, it is the ``sys.path`` reach-across
this module replaces.
"""

from __future__ import annotations

import importlib
import importlib.machinery
import importlib.util
import sys
from pathlib import Path
from types import ModuleType

#: The name the derivations folder is imported under (whatever the folder is called).
DERIVATIONS_PACKAGE = "asymslip_derivations"


def _forget_package() -> None:
    """Drop a previously loaded derivations package and its submodules from ``sys.modules``."""
    prefix = DERIVATIONS_PACKAGE + "."
    for name in [n for n in sys.modules if n == DERIVATIONS_PACKAGE or n.startswith(prefix)]:
        del sys.modules[name]


def load_derivations_package(directory: Path) -> ModuleType:
    """Import ``directory`` as the package :data:`DERIVATIONS_PACKAGE` and return it.

    Loading the same folder again returns the package already imported (its scripts' caches
    stay warm); loading another folder replaces it.  An ``__init__.py`` in the folder is run
    as the package's body; without one the package is empty.
    """
    directory = Path(directory).resolve()
    if not directory.is_dir():
        raise FileNotFoundError(f"no derivations folder at {directory}")
    loaded = sys.modules.get(DERIVATIONS_PACKAGE)
    if loaded is not None:
        if list(getattr(loaded, "__path__", [])) == [str(directory)]:
            return loaded
        _forget_package()
    init = directory / "__init__.py"
    if init.is_file():
        spec = importlib.util.spec_from_file_location(
            DERIVATIONS_PACKAGE, init, submodule_search_locations=[str(directory)]
        )
    else:
        spec = importlib.machinery.ModuleSpec(DERIVATIONS_PACKAGE, None, is_package=True)
        spec.submodule_search_locations = [str(directory)]
    if spec is None:  # pragma: no cover - spec_from_file_location of an existing .py file
        raise ImportError(f"cannot load {directory} as a package")
    package = importlib.util.module_from_spec(spec)
    sys.modules[DERIVATIONS_PACKAGE] = package
    try:
        if spec.loader is not None:
            spec.loader.exec_module(package)
    except BaseException:
        _forget_package()
        raise
    return package


def import_derivation(directory: Path, script: str) -> ModuleType:
    """Import one derivation script (``"section2_calibrations"``) of the folder ``directory``."""
    load_derivations_package(directory)
    return importlib.import_module(f"{DERIVATIONS_PACKAGE}.{script}")
