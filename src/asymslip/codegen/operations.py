"""Fewer array operations: numeric coefficients moved into the sums they scale, where it pays.

A derivation's expression often carries a rational coefficient outside a sum whose terms carry
its inverse, e.g. (22) as SymPy keeps it::

    (1/4) L_I1 (pi a1 eta + 4 lam + 4 mu)

Printed for NumPy that costs 8 array operations (``(1/4)*L_I1`` and ``4*lam`` are whole-array
multiplications); the same quantity written ``L_I1 (pi a1 eta/4 + lam + mu)`` costs 5, because
``(1/4)*numpy.pi`` is folded to one float before any array is touched.  Over 10^7 elements
each array operation is one pass over memory: measured (CPU time, best of 7 interleaved
rounds), the kernels of (22) ran 1.7 times as long as careful hand-written NumPy with ``out=``
buffers before this rewrite and 1.2 times after it, with the same bits out.  The rest is
allocation, which the generated code cannot avoid: its arguments are any array_like (floats,
integer arrays, arrays broadcasting to a larger shape, dask arrays), so it cannot update a
temporary in place (``make bench`` shows the hand-written code allocating is as slow).

:func:`fewer_operations` moves a rational coefficient of a product into one of its sum
factors, bottom-up, wherever that lowers :func:`array_operations`, and
:func:`cheapest_reduction` keeps it only if the whole function, after CSE, needs fewer
operations (distributing may hide a subexpression CSE would otherwise share).  Only the scale
of terms changes, so no difference of nearly equal numbers is introduced; multiplying by a
power of two (the 1/4 and 4 above) is exact, so such kernels give the same bits as before.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import sympy


def _is_constant(factor: sympy.Expr) -> bool:
    """Numbers and number symbols (pi, E): folded into one float when printed first."""
    return bool(factor.is_number)


def array_operations(expr: sympy.Expr) -> int:
    """Element-wise operations NumPy performs for ``expr`` as the generated code prints it.

    A model, not a measurement: a sum of k terms costs k - 1, a product of k non-constant
    factors k - 1 plus one for a constant coefficient other than +-1 (the printer puts the
    constants first, so they fold into one float), a function call one, a power one (a
    reciprocal inside a product is a division, counted with the product).
    """
    if expr.is_Atom or _is_constant(expr):
        return 0
    if expr.is_Add:
        return len(expr.args) - 1 + sum(array_operations(term) for term in expr.args)
    if expr.is_Mul:
        constants = [factor for factor in expr.args if _is_constant(factor)]
        others = [factor for factor in expr.args if not _is_constant(factor)]
        cost = len(others) - 1
        coefficient = sympy.Mul(*constants)
        if coefficient not in (sympy.S.One, sympy.S.NegativeOne):
            cost += 1
        for factor in others:
            if factor.is_Pow and factor.exp == -1:
                cost += array_operations(factor.base)  # printed as a division
            else:
                cost += array_operations(factor)
        return cost
    if expr.is_Pow and expr.exp == -1:
        return 1 + array_operations(expr.base)
    return 1 + sum(array_operations(arg) for arg in expr.args)


def _distributed_candidates(product: sympy.Mul) -> Iterable[sympy.Expr]:
    """``product`` with its rational coefficient moved into each of its sum factors in turn.

    The sign stays outside (a negative term of a sum is a subtraction, free), so that the
    scaled sum keeps the same form wherever else it occurs.
    """
    coefficient, rest = product.as_coeff_Mul()
    if not coefficient.is_Rational or coefficient in (sympy.S.One, sympy.S.NegativeOne):
        return
    sign = sympy.S.NegativeOne if coefficient.is_negative else sympy.S.One
    factors = sympy.Mul.make_args(rest)
    for index, factor in enumerate(factors):
        if factor.is_Add:
            # A two-argument product of a number and a sum distributes by SymPy's own rules.
            scaled = abs(coefficient) * factor
            others = factors[:index] + factors[index + 1 :]
            yield sympy.Mul(sign, scaled, *others)


def fewer_operations(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` with rational coefficients moved into sums wherever that saves operations."""
    if expr.is_Atom or not expr.args:
        return expr
    rebuilt = expr.func(*(fewer_operations(arg) for arg in expr.args))
    if not rebuilt.is_Mul:
        return rebuilt
    best, best_cost = rebuilt, array_operations(rebuilt)
    for candidate in _distributed_candidates(rebuilt):
        cost = array_operations(candidate)
        if cost < best_cost:
            best, best_cost = candidate, cost
    return best


Reduction = tuple[list[tuple[sympy.Symbol, sympy.Expr]], sympy.Expr]


def reduction_cost(reduction: Reduction) -> int:
    """Array operations of a CSE'd function: its temporaries and its result."""
    temporaries, result = reduction
    return sum(array_operations(value) for _, value in temporaries) + array_operations(result)


def cheapest_reduction(expr: sympy.Expr, reduce: Callable[[sympy.Expr], Reduction]) -> Reduction:
    """``reduce`` (the code generator's CSE) of ``expr`` or of :func:`fewer_operations` of it,
    whichever needs fewer array operations; ``expr`` on a tie.
    """
    original = reduce(expr)
    rewritten = fewer_operations(expr)
    if rewritten == expr:
        return original
    candidate = reduce(rewritten)
    return candidate if reduction_cost(candidate) < reduction_cost(original) else original
