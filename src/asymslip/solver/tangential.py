"""One load step of the tangential problem: stick, slip and the shear tractions.

Conventions (:mod:`asymslip.solver.conventions`, derived in ``derivations/solver_influence.py``
for a body 1 carrying q and a body 2 carrying -q, here the indenter and the lower body): q(x)
is the shear traction the lower body exerts on the indenter, along +x, Q = int q dx;
s = u_x(lower body) - u_x(indenter) is their relative tangential displacement (minus the
reported slip delta, which :mod:`.steady` accumulates); sigma is the lower body's bulk tension
minus the indenter's (the sign of the paper's (38)).  Then

    s_i = (S q)_i + sigma x_i/(2 E*) + c,

with S = -W the generated slip influence matrix and c a rigid shift.  Over one load step,
with the pressure p of the step's end, Coulomb's law on every element in contact reads

    stick:  Delta s_i = 0,          |q_i| <= mu p_i,
    slip:   q_i = +-mu p_i,         Delta s_i of the same sign as q_i (Delta delta_i opposite),

with sum q_i h_el = Q.  These are the optimality conditions of the strictly convex programme

    minimise 1/2 q.(-S).q - ((-S) q_old + Delta f).q   over |q_i| <= mu p_i, sum q_i h_el = Q,

(Delta f the step's change of the tension displacement; the multiplier of the force balance is
-Delta c, and Delta s = -gradient), solved by :func:`~asymslip.solver.qp.solve_box_qp` warm-
started from the previous step's stick/slip sets.  Elements out of contact carry no traction.

An element that comes into contact during a step is held, if it sticks, from the step's start;
with K steps per segment this misplaces its traction history by at most one step's motion
(the stick boundary at the ends of a monotone segment does not depend on it: every element of
the final stick zone is in contact throughout).  Its slip is counted only for the fraction of
the step it spends in contact, and likewise for an element leaving the contact
(:func:`contact_fractions`).  Measured on the Fig. 5 cycle (N = 1000): against 80 steps per
segment, the largest slip range is 0.8 % high with 20 steps and 1.7 % with 10, the frictional
energy within 0.3 % and 1 % of its peak at every point, the stick boundary identical.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from asymslip_gen.solver_influence import tension_relative_displacement

from .grid import Grid, InfluenceOperators
from .normal import NormalState
from .qp import BoxQP, Iterate, Workspace, solve_box_qp
from .toeplitz import FloatArray, Runs

Int8Array = NDArray[np.int8]

#: A slip zone's front is predicted to advance by at most this many times its last step's
#: advance (:func:`predict_slip`) ...
PREDICTION_REACH = 2
#: ... plus this many elements.
PREDICTION_MARGIN = 2


@dataclass(frozen=True)
class TangentialState:
    """The shear state at the end of a load step."""

    shear: FloatArray  # q on every element (0 out of contact)
    slip_sign: Int8Array  # +1 / -1 where slipping (q = +-mu p), 0 where stuck or out of contact
    slip_increment: FloatArray  # Delta s over the step (0 where stuck or out of contact)
    sigma: float
    iterations: int  # active-set solves
    cg_iterations: int
    fallback: bool  # the monotone fallback was needed
    image: FloatArray | None = None  # (-S) q, the slip stiffness times q; None: not kept

    @property
    def stick(self) -> NDArray[np.bool_]:
        return np.equal(self.slip_sign, 0)


class TangentialSolver:
    """Advances the tangential state by one load step."""

    def __init__(self, grid: Grid, operators: InfluenceOperators, mu: float) -> None:
        self.grid = grid
        self.operators = operators
        self.mu = mu
        self._rows = np.full((1, grid.count), grid.width)
        self._workspace = Workspace()

    def initial(self) -> TangentialState:
        """No shear: the state after normal loading alone (elastically similar bodies)."""
        zeros = np.zeros(self.grid.count)
        return TangentialState(
            zeros, np.zeros(self.grid.count, dtype=np.int8), zeros, 0.0, 0, 0, False, zeros
        )

    def refreshed(self, state: TangentialState) -> TangentialState:
        """The state with its image (-S) q recomputed by one product, and made the start of
        the next solve: the image is otherwise carried along by updates, whose rounding this
        keeps from accumulating over many periods."""
        image = self.operators.slip_stiffness.apply(state.shear)
        self._workspace.last = Iterate(state.shear, image)
        return replace(state, image=image)

    def step(
        self,
        old: TangentialState,
        normal: NormalState,
        Q: float,
        sigma: float,
        predicted: Int8Array | None = None,
        previous: NormalState | None = None,
        guess: FloatArray | None = None,
        settle: bool = False,
    ) -> TangentialState:
        """The state at the end of a step to shear force Q and tension sigma.

        ``predicted`` is a guess of the new slip signs (+1, -1, 0), e.g. from
        :func:`predict_slip`; the active-set iteration starts from it.  Without it the
        iteration starts from the previous step's slip zones.  The guess only affects the
        work, never the solution.  ``previous`` is the normal state at the step's start: with
        it, elements that come into or leave the contact during the step count only the part
        of their slip made while in contact (see :func:`contact_fractions`).  ``guess`` is a
        guess of the new shear tractions to start the iteration from (default: the old ones);
        like ``predicted`` it affects only the work.  ``settle`` moves the predicted stick
        zone's ends first (:func:`~asymslip.solver.qp.settle_ends`), for a prediction that is
        not an extrapolation (a segment's first step).
        """
        contact = normal.contact
        capacity = self.mu * normal.pressure
        stiffness = self.operators.slip_stiffness
        tension_change = tension_relative_displacement(
            self.grid.centres, sigma - old.sigma, self.operators.E_star
        )
        qp = BoxQP(
            operator=stiffness,
            domain=contact,
            lower=-capacity,
            upper=capacity,
            # The old tractions' term is the image (-S) q_old the last solve kept, when kept.
            linear=(stiffness.apply(old.shear) if old.image is None else old.image)
            + tension_change,
            rows=self._rows,
            targets=np.array([Q], dtype=np.float64),
        )
        guess_sign = old.slip_sign if predicted is None else predicted
        at_upper = contact & (guess_sign > 0)
        at_lower = contact & (guess_sign < 0)
        solution = solve_box_qp(
            qp,
            at_lower,
            at_upper,
            workspace=self._workspace,
            feasible_start=lambda inside: self._feasible(inside, capacity, contact, Q),
            guess=guess,
            settle=settle,
        )
        # An element at its friction limit slips only if it moves: one held at the limit by
        # a locked-in traction, with no slip increment, sticks.
        moving = np.abs(solution.gradient) > solution.gradient_tolerance
        sign = np.zeros(self.grid.count, dtype=np.int8)
        sign[solution.at_upper & moving] = 1
        sign[solution.at_lower & moving] = -1
        increment = np.where(sign != 0, -solution.gradient, 0.0)
        if previous is not None:
            entering, leaving = contact_fractions(previous, normal, self.operators.gap.diagonal())
            increment = increment * np.where(entering > 0, entering, 1.0)
            # An element that was slipping when it left the contact slipped until it left.
            left_slipping = (leaving > 0) & (old.slip_sign != 0)
            left_slipping &= np.sign(-solution.gradient) == old.slip_sign
            increment = np.where(left_slipping, -solution.gradient * leaving, increment)
        return TangentialState(
            shear=np.where(contact, solution.y, 0.0),
            slip_sign=sign,
            slip_increment=increment,
            sigma=float(sigma),
            iterations=solution.iterations,
            cg_iterations=solution.cg_iterations,
            fallback=solution.method != "primal-dual",
            image=solution.image,
        )

    def _feasible(
        self, guess: FloatArray, capacity: FloatArray, contact: NDArray[np.bool_], Q: float
    ) -> FloatArray:
        """A point in the box with sum q h = Q (exists because |Q| < mu P)."""
        width = self.grid.width
        deficit = Q / width - float(np.sum(guess))
        room = np.where(contact, (capacity - guess) if deficit > 0 else (guess + capacity), 0.0)
        total = float(np.sum(room))
        if total <= 0:
            return guess
        share = min(1.0, abs(deficit) / total)
        moved: FloatArray = guess + np.sign(deficit) * share * room
        return moved


def predict_slip(
    mu: float,
    before: tuple[NormalState, TangentialState],
    now: tuple[NormalState, TangentialState],
    upcoming: NormalState,
) -> Int8Array:
    """Guess the slip signs of the next step of a segment from its last two steps.

    Slip zones grow steadily within a segment and the friction reserve r = mu p -+ q of a
    stuck element vanishes like a square root of its distance from the moving slip zone, so
    r^2 falls about linearly in time: extrapolated, r^2 -> 2 r_now^2 - r_before^2 <= 0 marks
    the elements expected to slip next.  Elements slipping now are expected to go on, and
    elements coming into contact to do what the contact's edge element does now.

    Where a slip zone of a sign already existed a step ago, its front is expected to advance
    by at most ``PREDICTION_REACH`` times its last advance plus ``PREDICTION_MARGIN``
    elements (the steps of a segment are equal): the extrapolation also marks elements whose
    reserve falls without vanishing.  Measured on the paper's Fig. 5 cycle, at the end of the
    reloading it marked bands that stay stuck (at N = 10^5, 31 elements a side at the last
    step), and the active-set iteration then walked them back: 13 and 9 equality-constrained
    solves for the last two steps at N = 10^6 (as counted before this bound), 7 and 5 at 10^5,
    4 and 2 at 10^4; with the reach bounded, 1 and 8 at 10^6, 1 and 5 at 10^5, 1 and 2 at
    10^4.  Like any guess, this affects only the work, never the solution.
    """
    (normal_before, state_before), (normal_now, state_now) = before, now
    guess = state_now.slip_sign.copy()
    entering = upcoming.contact & ~normal_now.contact
    if entering.any():
        first, last = normal_now.first, normal_now.last
        left_side = np.arange(guess.size) < first
        guess[entering & left_side] = state_now.slip_sign[first]
        guess[entering & ~left_side] = state_now.slip_sign[last]
    both = normal_now.contact & normal_before.contact
    stuck = both & (guess == 0)
    for sign in (1, -1):
        reserve_now = mu * normal_now.pressure - sign * state_now.shear
        reserve_before = mu * normal_before.pressure - sign * state_before.shear
        closing = stuck & (reserve_now < reserve_before)
        expected = closing & (2 * reserve_now**2 <= reserve_before**2)
        if expected.any() and (state_before.slip_sign == sign).any():
            slipping = state_now.slip_sign == sign
            newly = both & slipping & (state_before.slip_sign != sign)
            advance = max(Runs.of(newly).lengths, default=0)
            reach = PREDICTION_REACH * advance + PREDICTION_MARGIN
            expected &= distance_to(slipping) <= reach
        guess[expected] = sign
    return guess


def distance_to(mask: NDArray[np.bool_]) -> NDArray[np.intp]:
    """Each element's distance, in elements, to the nearest element of ``mask`` (at least
    twice the grid's length where ``mask`` is empty)."""
    index = np.arange(mask.size)
    far = 2 * mask.size
    left = np.maximum.accumulate(np.where(mask, index, -far))
    right = np.minimum.accumulate(np.where(mask, index, 3 * far)[::-1])[::-1]
    distance: NDArray[np.intp] = np.minimum(index - left, right - index)
    return distance


def contact_fractions(
    before: NormalState, after: NormalState, compliance: float
) -> tuple[FloatArray, FloatArray]:
    """Fractions of a step spent in contact by elements that enter, or leave, the contact.

    The gap of an element is taken to close linearly over the step: from its gap g0 at the
    start to the overlap W_ii p1 its end pressure p1 would cause were it not in contact (W_ii
    the gap opening per unit pressure on itself).  An entering element touches at
    t = g0/(g0 + W_ii p1) and is in contact for 1 - t; a leaving one, symmetrically, for
    W_ii p0/(W_ii p0 + g1).  Zero for every other element.
    """
    entering = after.contact & ~before.contact
    leaving = before.contact & ~after.contact
    overlap_after = compliance * after.pressure
    overlap_before = compliance * before.pressure
    with np.errstate(divide="ignore", invalid="ignore"):
        enter = np.where(entering, overlap_after / (before.gap + overlap_after), 0.0)
        leave = np.where(leaving, overlap_before / (overlap_before + after.gap), 0.0)
    return np.nan_to_num(enter), np.nan_to_num(leave)
