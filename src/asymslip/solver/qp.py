"""Box-constrained quadratic programmes with a Toeplitz Hessian: the contact problems' core.

Both contact problems of the solver are strictly convex quadratic programmes over the grid
elements of a domain D (the others are fixed at zero)::

    minimise  1/2 y.H.y - g.y   subject to  lower <= y <= upper  and  A y = c,

with H a positive definite Toeplitz influence matrix (``toeplitz.ToeplitzOperator``) and one
or two equality rows A (the total force, and for the normal problem the moment).  The
optimality conditions are the contact conditions: with the gradient
``G = H y - g + A^T lambda``, G = 0 where lower < y < upper (stick, or contact), G >= 0 where
y = lower and G <= 0 where y = upper (slip in the direction of the traction, or a gap).

:func:`solve_box_qp` uses the primal-dual active-set method (Hintermueller, Ito & Kunisch
2002; a semismooth Newton method): guess which elements sit at a bound, solve the equality-
constrained problem on the rest, move every element whose value leaves its box or whose
gradient has the wrong sign, repeat.  Warm-started from the previous load step it needs 2-3
solves.  It is not guaranteed to converge for a matrix that is not an M-matrix, so it watches
for a repeated guess (a cycle) and, if one occurs or the iterations run out, switches to a
primal active-set method (Nocedal & Wright, Algorithm 16.3), which decreases the objective at
every step and ends in finitely many (one bound changes per step; slower, never wrong).  If
that too runs out, :class:`~asymslip.solver.toeplitz.SolverError` is raised: no unconverged
answer is ever returned.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from .inner_products import combination, norm, row_products
from .toeplitz import (
    CG_TOLERANCE,
    Checkpoint,
    FloatArray,
    Runs,
    SolverError,
    ToeplitzOperator,
    onto_constraints,
    pack,
    projected_cg,
)

BoolArray = NDArray[np.bool_]
Method = Literal["primal-dual", "primal (fallback)"]

#: Relative tolerance of the bound and sign decisions (the linear solves reach 1e-11).
DECISION_TOLERANCE = 1e-9
#: Relative residual of the solves made while the stick/slip sets are still moving.
LOOSE_TOLERANCE = 1e-6
#: Grids of up to this many elements settle ends with solves at ``LOOSE_TOLERANCE``; finer
#: ones at a tolerance falling like N^-3/2 (:func:`settling_tolerance`).
SETTLING_REFERENCE = 10_000
#: Moves of the sets after which the solves are loose until the sets settle.
EXACT_MOVES = 2
#: Loose solves at most by which :func:`settle_ends` moves the ends of a free run.
SETTLING_SOLVES = 8
#: The first solve of a programme asks at this many times its target residual whether its
#: guessed sets hold, and stops there if they do not (:func:`solve_box_qp`).
CHECKPOINT_FACTOR = 1e3
#: Primal-dual iterations before the monotone fallback takes over.
MAX_PRIMAL_DUAL = 40
#: Iterations of the monotone fallback before giving up (each changes one bound).
MAX_PRIMAL = 20_000


@dataclass(frozen=True)
class BoxQP:
    """One problem: minimise 1/2 y.H.y - g.y, lower <= y <= upper, A y = c, y = 0 off D."""

    operator: ToeplitzOperator
    domain: BoolArray
    lower: FloatArray
    upper: FloatArray
    linear: FloatArray
    rows: FloatArray  # (m, N)
    targets: FloatArray  # (m,)


@dataclass(frozen=True)
class QPSolution:
    """The minimiser, its multipliers and how it was found."""

    y: FloatArray
    multipliers: FloatArray  # lambda of the equality rows
    gradient: FloatArray  # H y - g + A^T lambda on every element (0 strictly inside the box)
    at_lower: BoolArray
    at_upper: BoolArray
    iterations: int  # equality-constrained solves
    cg_iterations: int
    method: Method
    gradient_tolerance: float  # |G| below this counts as zero (e.g. no slip at the bound)
    image: FloatArray  # H y on every element (what the next problem's linear term may need)


@dataclass(frozen=True)
class Iterate:
    """A point y on the whole grid and its image H y."""

    y: FloatArray
    image: FloatArray


class Workspace:
    """Solves the equality-constrained problems of a sequence of similar programmes.

    It keeps the last solution y and its image H y on the whole grid.  The next solve starts
    from y (or from a guess) on its free elements: only the difference from the last solution
    needs a product, and the conjugate gradients then keep the image up to date, so that the
    gradient on every element comes without another product.  Successive active-set
    iterations, and successive load steps, differ little.  A solver keeps one workspace for
    its life.
    """

    def __init__(self) -> None:
        self.cg_iterations = 0
        self.last: Iterate | None = None
        self.abandoned = False  # the last solve stopped at its checkpoint (not converged)

    def solve(
        self,
        qp: BoxQP,
        at_lower: BoolArray,
        at_upper: BoolArray,
        guess: FloatArray | None = None,
        tolerance: float = CG_TOLERANCE,
        sets_hold: Callable[[FloatArray, FloatArray], bool] | None = None,
    ) -> tuple[FloatArray, FloatArray, FloatArray]:
        """y, lambda and the gradient for this split of the domain.

        ``guess`` gives the start's values on the free elements (default: the last
        solution's); the elements at a bound start at it.  ``sets_hold(y, gradient)``, if
        given, is asked once, at ``CHECKPOINT_FACTOR`` times the target residual; if it
        answers False the solve stops there and ``abandoned`` is set.
        """
        free = qp.domain & ~at_lower & ~at_upper
        runs = Runs.of(free)
        rows = qp.rows
        if runs.count < rows.shape[0]:
            raise SolverError(
                f"only {runs.count} element(s) free for {rows.shape[0]} equilibrium "
                "condition(s): the grid is too coarse for this contact"
            )
        count = free.size
        last = self.last or Iterate(np.zeros(count), np.zeros(count))
        start = np.where(at_lower, qp.lower, 0.0) + np.where(at_upper, qp.upper, 0.0)
        start = np.where(qp.domain, start, 0.0)
        packed_rows = pack(rows, runs)
        fixed_share = row_products(rows, start)  # A y over the bound elements (start is 0 on
        # the free ones here); the free part is moved (least change) to meet the rows.
        remaining = qp.targets - fixed_share
        where = runs.selector()
        start[where] = onto_constraints(
            pack(last.y if guess is None else guess, runs), packed_rows, remaining
        )
        change = start - last.y
        image = last.image + qp.operator.apply(change) if change.any() else last.image.copy()
        linear = pack(qp.linear, runs)
        scale = max(norm(linear), norm(pack(image, runs)), 1e-300)
        checkpoint = None
        if sets_hold is not None:
            ask = sets_hold

            def go_on(step: FloatArray, multipliers: FloatArray) -> bool:
                # The image is the CG's, kept up to date in place: no product is needed.
                y = start.copy()
                y[where] += step
                return ask(y, image - qp.linear + combination(multipliers, rows))

            checkpoint = Checkpoint(CHECKPOINT_FACTOR * tolerance * scale, go_on)
        found = projected_cg(
            qp.operator,
            runs,
            pack(image, runs) - linear,
            packed_rows,
            target=tolerance * scale,
            image=image,
            checkpoint=checkpoint,
        )
        self.abandoned = found.abandoned
        self.cg_iterations += found.iterations
        y = start
        y[where] += found.step
        # Rounding drifts from A y = c by ~1e-16 relative; the image is not corrected for a
        # change that small.
        y[where] = onto_constraints(y[where], packed_rows, remaining)
        self.last = Iterate(y, image)
        # On every element, the domain's and beyond (e.g. the gap outside the contact).
        gradient = image - qp.linear + combination(found.multipliers, rows)
        return y, found.multipliers, gradient


def _largest(values: FloatArray, where: BoolArray) -> float:
    """max |values| over ``where`` (0 where nothing is selected)."""
    return float(np.max(np.abs(values), where=where, initial=0.0))


def _scales(qp: BoxQP, y: FloatArray) -> tuple[float, float]:
    """Sizes against which 'at the bound' and 'zero gradient' are decided."""
    value_scale = max(
        _largest(qp.lower, qp.domain & np.isfinite(qp.lower)),
        _largest(qp.upper, qp.domain & np.isfinite(qp.upper)),
        _largest(y, qp.domain),
        1e-300,
    )
    gradient_scale = max(
        _largest(qp.linear, qp.domain),
        qp.operator.diagonal() * value_scale,
        1e-300,
    )
    return DECISION_TOLERANCE * value_scale, DECISION_TOLERANCE * gradient_scale


def _band(flags: BoolArray, start: int, step: int) -> int:
    """How many consecutive ``flags`` are set from ``start`` on, going by ``step``."""
    count, index = 0, start
    while 0 <= index < flags.size and flags[index]:
        count += 1
        index += step
    return count


def settling_tolerance(count: int) -> float:
    """The relative residual of :func:`settle_ends`'s solves on a grid of ``count`` elements.

    An end is moved by the bands where the solution crosses its bound or the gradient has the
    wrong sign, and near a square-root edge both are of order d^(3/2) at d elements from it, in
    units of the element size h: one element's worth shrinks like h^(3/2) ~ N^-3/2 against the
    whole solution, which sets the residual's scale.  At ``LOOSE_TOLERANCE`` the bands of a
    fine grid are lost in the solves' error: measured at N = 10^6 (the paper's Fig. 5 cycle),
    the solves after the first stopped at once (0 conjugate-gradient iterations) and the ends
    crept one element a solve, leaving the exact solves that followed 6 elements to walk one or
    two at a time (14 solves for the first step after the reversal, against 3 at N = 10^5).
    So from ``SETTLING_REFERENCE`` elements on, the tolerance falls like N^-3/2: 4 solves for
    that step at 10^6, and 3 (unchanged) at 10^5.
    """
    finer: float = (SETTLING_REFERENCE / count) ** 1.5  # float ** float: typed Any
    return LOOSE_TOLERANCE * min(1.0, finer)


def settle_ends(
    qp: BoxQP,
    at_lower: BoolArray,
    at_upper: BoolArray,
    workspace: Workspace,
    guess: FloatArray | None = None,
) -> tuple[BoolArray, BoolArray, int]:
    """Move the ends of a one-run free set to where a square-root edge puts them.

    Both contact problems have free sets (the contact, the stick zone) whose ends are
    square-root edges: the multiplier (pressure, friction reserve) vanishes like sqrt(d) inside
    and the gap (slip) grows like d^(3/2) outside.  Solved with an end that is short by d, the
    solution overlaps its bound on a band of about 3 d/2 elements beyond it; with an end that is
    long by d, it crosses its bound on a band of about d/2 elements inside it (measured on the
    normal problem of a Hertz contact, 300,000 elements, an end 169 elements short: a band of
    253; then 84 long: a band of 42).  The primal-dual iteration, which moves every violating
    element, overshoots and then halves its way back -- a number of iterations that grows
    with the grid.  Here each end is moved by 2/3 of an outside band or twice an inside band,
    from loose solves, until no end moves (at most ``SETTLING_SOLVES``).  Like any guess it
    affects only the work: :func:`solve_box_qp` then confirms the sets.

    Returns the sets and the number of solves made.
    """
    free = qp.domain & ~at_lower & ~at_upper
    runs = Runs.of(free)
    if len(runs.starts) != 1:
        return at_lower, at_upper, 0
    first, last = runs.starts[0], runs.stops[0] - 1
    lower, upper = at_lower & qp.domain, at_upper & qp.domain & ~at_lower
    solves = 0
    for solve in range(SETTLING_SOLVES):
        solves += 1
        y, _, gradient = workspace.solve(
            qp, lower, upper, guess if solve == 0 else None, settling_tolerance(qp.domain.size)
        )
        value_tol, gradient_tol = _scales(qp, y)
        outside_wrong = (lower & (gradient < -gradient_tol)) | (upper & (gradient > gradient_tol))
        below, above = y < qp.lower - value_tol, y > qp.upper + value_tol
        lower, upper = lower.copy(), upper.copy()
        moved = False
        for end, step in ((first, -1), (last, 1)):
            band = _band(outside_wrong, end + step, step)
            if band:  # short: free the inner 2/3 of the band
                reach = max(1, (2 * band) // 3)
                chosen = slice(end + 1, end + 1 + reach) if step > 0 else slice(end - reach, end)
                lower[chosen] = upper[chosen] = False
                moved = True
                continue
            crossed = above if above[end] else below
            band = _band(crossed, end, -step)
            if band:  # long: bind twice the band, at the bound it crossed
                reach = min(2 * band, (last - first) // 4)
                chosen = slice(end - reach + 1, end + 1) if step > 0 else slice(end, end + reach)
                (upper if crossed is above else lower)[chosen] = True
                moved = True
        if not moved:
            break
        lower &= qp.domain
        upper &= qp.domain & ~lower
        runs = Runs.of(qp.domain & ~lower & ~upper)
        if len(runs.starts) != 1:
            break
        first, last = runs.starts[0], runs.stops[0] - 1
    return lower, upper, solves


def solve_box_qp(
    qp: BoxQP,
    at_lower: BoolArray,
    at_upper: BoolArray,
    *,
    workspace: Workspace | None = None,
    feasible_start: FloatArray | Callable[[FloatArray], FloatArray] | None = None,
    guess: FloatArray | None = None,
    settle: bool = False,
) -> QPSolution:
    """Minimise the box-constrained problem from a guess of the elements at their bounds.

    Parameters
    ----------
    qp
        The problem.
    at_lower, at_upper
        Initial guess of the elements at their lower and upper bounds (inside the domain).
    workspace
        Cached solutions from earlier programmes with the same operator and rows.
    feasible_start
        A point satisfying the bounds and the equality rows, for the monotone fallback, or a
        function making one from a point inside the bounds (it is given the last primal-dual
        iterate clipped into the box, so that the fallback starts near the solution and needs
        few of its one-bound-at-a-time steps); without it the fallback is unavailable and a
        cycling primal-dual iteration raises.
    guess
        Values to start the first solve from on its free elements (default: the workspace's
        last solution).  Like the sets, it affects only the work, never the solution.
    settle
        First move the ends of the guessed free set (:func:`settle_ends`): for a guess that is
        not an extrapolation to this problem.

    Raises
    ------
    SolverError
        When neither method converges.
    """
    equality = Workspace() if workspace is None else workspace
    cg_before = equality.cg_iterations
    settling = 0
    if settle:
        at_lower, at_upper, settling = settle_ends(qp, at_lower, at_upper, equality, guess)
        guess = None
    lower_set = at_lower & qp.domain
    upper_set = at_upper & qp.domain & ~lower_set
    # The first two solves are exact (the guess is usually right, or one correction away);
    # once the sets have moved twice, the next solves only need to be good enough to move them
    # on (LOOSE_TOLERANCE), until they stay put; from then on every solve is exact, and a set
    # met twice among the exact solves is a cycle.
    seen: set[bytes] = set()  # sets solved exactly
    seen_loose: set[bytes] = set()
    phase = "exact"  # "exact" (the first solves), "loose", "final" (exact to the end)
    moves = 0
    iteration = 0
    for iteration in range(1, MAX_PRIMAL_DUAL + 1):
        signature = np.packbits(lower_set).tobytes() + np.packbits(upper_set).tobytes()
        if phase == "loose" and signature in seen_loose:
            phase = "final"  # loose solves can cycle by their own error
        if phase != "loose" and signature in seen:
            break  # a cycle: the primal-dual iteration will not converge from here
        if np.count_nonzero(qp.domain & ~lower_set & ~upper_set) < qp.rows.shape[0]:
            break  # a guess with too few free elements to meet the equalities: go monotone
        (seen_loose if phase == "loose" else seen).add(signature)
        # The first solve asks on the way whether its guessed sets hold: a guess off by a few
        # elements is seen long before the solve converges, and the rest of it is saved.
        hold = _sets_hold(qp, lower_set, upper_set) if iteration == 1 and phase == "exact" else None
        y, multipliers, gradient = equality.solve(
            qp,
            lower_set,
            upper_set,
            guess if iteration == 1 else None,
            LOOSE_TOLERANCE if phase == "loose" else CG_TOLERANCE,
            sets_hold=hold,
        )
        if equality.abandoned:  # not an exact solve of these sets: no evidence of a cycle
            seen.discard(signature)
            seen_loose.add(signature)
        new_lower, new_upper, gradient_tol = _next_sets(qp, y, gradient, lower_set, upper_set)
        if np.array_equal(new_lower, lower_set) and np.array_equal(new_upper, upper_set):
            if phase == "loose" or equality.abandoned:
                phase = "final"
                continue
            return QPSolution(
                y,
                multipliers,
                gradient,
                lower_set,
                upper_set,
                settling + iteration,
                equality.cg_iterations - cg_before,
                "primal-dual",
                gradient_tol,
                _image(equality),
            )
        moves += 1
        if phase == "exact" and moves >= EXACT_MOVES:
            phase = "loose"
        lower_set, upper_set = new_lower, new_upper & ~new_lower
    if feasible_start is None:
        raise SolverError(
            f"the active-set iteration did not settle in {iteration} iterations (it cycles "
            "between stick/slip guesses) and no feasible starting point was given"
        )
    if callable(feasible_start):
        last = equality.last.y if equality.last is not None else np.zeros(qp.domain.size)
        clipped = np.where(qp.domain, np.clip(last, qp.lower, qp.upper), 0.0)
        feasible_start = feasible_start(clipped)
    return _primal_active_set(qp, feasible_start, equality, settling + iteration, cg_before)


def _next_sets(
    qp: BoxQP, y: FloatArray, gradient: FloatArray, lower_set: BoolArray, upper_set: BoolArray
) -> tuple[BoolArray, BoolArray, float]:
    """The primal-dual iteration's next sets from a solve's y and gradient, and the gradient's
    tolerance."""
    value_tol, gradient_tol = _scales(qp, y)
    free = qp.domain & ~lower_set & ~upper_set
    # An element leaves its bound only when its gradient clearly has the wrong sign
    # (G >= 0 at the lower bound, G <= 0 at the upper, up to the tolerance).
    new_lower = (free & (y < qp.lower - value_tol)) | (lower_set & (gradient > -gradient_tol))
    new_upper = (free & (y > qp.upper + value_tol)) | (upper_set & (gradient < gradient_tol))
    return new_lower, new_upper, gradient_tol


def _sets_hold(
    qp: BoxQP, lower_set: BoolArray, upper_set: BoolArray
) -> Callable[[FloatArray, FloatArray], bool]:
    """Whether an iterate (y, gradient) leaves the sets where they are."""

    def hold(y: FloatArray, gradient: FloatArray) -> bool:
        new_lower, new_upper, _ = _next_sets(qp, y, gradient, lower_set, upper_set)
        return bool(np.array_equal(new_lower, lower_set) and np.array_equal(new_upper, upper_set))

    return hold


def _image(workspace: Workspace) -> FloatArray:
    """H y of the workspace's last solution (the one just returned)."""
    assert workspace.last is not None
    return workspace.last.image


def _primal_active_set(
    qp: BoxQP, start: FloatArray, equality: Workspace, spent: int, cg_before: int
) -> QPSolution:
    """Nocedal & Wright's primal active-set method from a feasible point (monotone, finite)."""
    y = np.where(qp.domain, start, 0.0)
    value_tol, gradient_tol = _scales(qp, y)
    if np.any(qp.domain & ((y < qp.lower - value_tol) | (y > qp.upper + value_tol))):
        raise SolverError("the fallback's starting point violates the bounds")
    at_lower = qp.domain & (y <= qp.lower + value_tol)
    at_upper = qp.domain & (y >= qp.upper - value_tol) & ~at_lower
    for iteration in range(1, MAX_PRIMAL + 1):
        candidate, multipliers, gradient = equality.solve(qp, at_lower, at_upper)
        free = qp.domain & ~at_lower & ~at_upper
        step = np.where(free, candidate - y, 0.0)
        if np.max(np.abs(step)) <= value_tol:
            wrong = np.where(at_lower, -gradient, 0.0) + np.where(at_upper, gradient, 0.0)
            worst = int(np.argmax(wrong))
            if wrong[worst] <= gradient_tol:
                return QPSolution(
                    candidate,
                    multipliers,
                    gradient,
                    at_lower,
                    at_upper,
                    spent + iteration,
                    equality.cg_iterations - cg_before,
                    "primal (fallback)",
                    gradient_tol,
                    _image(equality),
                )
            at_lower[worst] = at_upper[worst] = False
            y = candidate
            continue
        with np.errstate(divide="ignore", invalid="ignore"):
            to_lower = np.where(free & (step < 0), (qp.lower - y) / step, np.inf)
            to_upper = np.where(free & (step > 0), (qp.upper - y) / step, np.inf)
        blocking = np.minimum(to_lower, to_upper)
        index = int(np.argmin(blocking))
        alpha = min(1.0, max(0.0, float(blocking[index])))
        y = y + alpha * step
        if alpha < 1.0:
            if to_lower[index] <= to_upper[index]:
                at_lower[index], y[index] = True, qp.lower[index]
            else:
                at_upper[index], y[index] = True, qp.upper[index]
    raise SolverError(
        f"the stick/slip iteration did not converge: {MAX_PRIMAL_DUAL} primal-dual and "
        f"{MAX_PRIMAL} monotone active-set iterations"
    )
