"""The paper's equations typed by hand from the PDF, in plain NumPy: the tests' oracle.

Nothing here imports SymPy, the derivations or the generated package.
"""
