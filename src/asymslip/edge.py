"""The two edges of a contact, each with its sign in the global frame.

x is measured from the contact centre: the right edge is at +a, the left at -a.  The paper
analyses the right edge; the left edge is the right edge of the mirrored cycle
(``derivations/edge_symmetry.py``: lambda -> -lambda, eta kept), so a length measured along the
edge's outward direction is ``edge.sign * x`` and a traction or displacement along +x seen from
the edge's own frame is ``edge.sign`` times its global value.

An :class:`Edge` is a ``str`` (``Edge.RIGHT == "right"``), so the strings the API and the
command line have always taken keep working.

Examples
--------
>>> Edge("left").sign, Edge.RIGHT.other, Edge.LEFT == "left"
(-1.0, <Edge.LEFT: 'left'>, True)
"""

from __future__ import annotations

from enum import StrEnum

from .errors import InputError


class Edge(StrEnum):
    """A contact edge: ``RIGHT`` (x = +a, the paper's) or ``LEFT`` (x = -a)."""

    RIGHT = "right"
    LEFT = "left"

    @property
    def sign(self) -> float:
        """+1 for the right edge, -1 for the left: the global direction of the edge's outward
        normal, and the factor from the edge's own frame to the global one."""
        return 1.0 if self is Edge.RIGHT else -1.0

    @property
    def other(self) -> Edge:
        """The edge at the other end of the contact."""
        return Edge.LEFT if self is Edge.RIGHT else Edge.RIGHT

    @classmethod
    def named(cls, value: object, parameter: str = "edge") -> Edge:
        """The edge called ``value`` ('right' or 'left'), or an :class:`InputError` naming
        ``parameter``."""
        if isinstance(value, Edge):
            return value
        if isinstance(value, str) and value in ("right", "left"):
            return cls(value)
        raise InputError(parameter, "must be 'right' or 'left'", value)


#: Both edges, the paper's first.
EDGES: tuple[Edge, Edge] = (Edge.RIGHT, Edge.LEFT)
#: :attr:`Edge.RIGHT` as a module name, for code timed per cycle: on CPython 3.11 a member
#: looked up on its enum class costs about 90 ns (measured), a module name a tenth of that,
#: and one cycle is timed in microseconds.
RIGHT: Edge = Edge.RIGHT
#: :attr:`Edge.LEFT` as a module name (see :data:`RIGHT`).
LEFT: Edge = Edge.LEFT
