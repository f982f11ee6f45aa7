"""The derivation scripts, loaded by the code generator as one package (see README.md here).

``asymslip.codegen.loader`` imports this folder as the package ``asymslip_derivations``
without touching ``sys.path``; scripts import each other relatively
(``from ._glossary import a``, ``from .section2_calibrations import normal_multiplier``).

``PAPER_EQUATIONS`` (the paper's printed equations, for display in the derivation report) is
handed to the code generator with the run's records.
"""

from ._paper_equations import PAPER_EQUATIONS

__all__ = ["PAPER_EQUATIONS"]
