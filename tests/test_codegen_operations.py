"""The code generator prints the fewest array operations it can without changing the formula.

A rational coefficient outside a sum whose terms carry its inverse -- (22) as SymPy keeps it,
(1/4) L_I1 (pi a1 eta + 4 lam + 4 mu) -- costs whole-array multiplications that the same
formula written L_I1 (pi a1 eta / 4 + lam + mu) does not.
"""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy

from asymslip.codegen.cse import reduce_formula
from asymslip.codegen.operations import array_operations, fewer_operations, reduction_cost
from asymslip.codegen.records import packaged_formulas
from asymslip_gen.corrective_slip import slip_zone_width, stick_boundary_proportional

L, a, eta, lam, mu, x, y, z = sympy.symbols("L a eta lam mu x y z", positive=True)
QUARTER = sympy.Rational(1, 4)


@cache
def records():  # noqa: ANN201
    return packaged_formulas()


def test_operations_are_counted_as_numpy_performs_them():
    # (1/4)*L*(pi*a*eta + 4*lam + 4*mu): (1/4)*L, *(...), pi*a, *eta, 4*lam, 4*mu, two adds.
    assert array_operations(QUARTER * L * (sympy.pi * a * eta + 4 * lam + 4 * mu)) == 8
    # L*((1/4)*pi*a*eta + lam + mu): (1/4)*pi folds to one float; ((1/4)*pi)*a, *eta, two
    # adds, L*(...).
    assert array_operations(L * (QUARTER * sympy.pi * a * eta + lam + mu)) == 5
    assert array_operations(x / y) == 1
    assert array_operations(1 / y) == 1
    assert array_operations(sympy.sqrt(x - y)) == 2


def test_a_rational_coefficient_moves_into_the_sum_it_scales():
    scaled = QUARTER * L * (sympy.pi * a * eta + 4 * lam + 4 * mu)
    assert fewer_operations(scaled) == L * (sympy.pi * a * eta / 4 + lam + mu)


def test_a_negative_coefficient_leaves_its_sign_outside_the_sum():
    scaled = -QUARTER * L * (sympy.pi * a * eta + 4 * lam - 4 * mu)
    rewritten = fewer_operations(scaled)
    assert rewritten == -L * (sympy.pi * a * eta / 4 + lam - mu)
    assert rewritten.as_coeff_Mul()[0] == -1


def test_a_coefficient_stays_outside_where_moving_it_costs_operations():
    # (1/3) z (x + y): 3 operations; z (x/3 + y/3) would need 4.
    expr = sympy.Rational(1, 3) * z * (x + y)
    assert fewer_operations(expr) == expr


def test_coefficients_inside_function_arguments_move_too():
    expr = sympy.exp(QUARTER * L * (4 * x + sympy.pi * y)) * z
    rewritten = fewer_operations(expr)
    assert rewritten == sympy.exp(L * (x + sympy.pi * y / 4)) * z
    assert array_operations(rewritten) == array_operations(expr) - 2


def test_the_stick_boundary_kernel_needs_14_operations_instead_of_18():
    # tmp0 = (1/4)*pi*eta (1); tmp1 = L_I1*(a1*tmp0 + lam + mu) (4); the same for tmp2 (4);
    # (a1*tmp1 - a2*tmp2)/(tmp1 - tmp2) (5).  The derivation's form needed 18 after CSE.
    formula = records()["stick_boundary_proportional"]
    reduced = reduce_formula(formula)
    assert reduction_cost((list(reduced.temporaries), reduced.result)) == 14


def test_the_slip_zone_width_kernel_needs_12_operations_instead_of_16():
    # tmp0 = (1/4)*pi*eta (1); tmp1 = a1*tmp0 + lam (2); tmp2 = L_I2*(da*tmp0 - mu + tmp1) (4);
    # da*tmp2/(L_I1*(mu + tmp1) - tmp2) (5).
    formula = records()["slip_zone_width"]
    reduced = reduce_formula(formula)
    assert reduction_cost((list(reduced.temporaries), reduced.result)) == 12


def test_the_record_keeps_the_derivation_form_and_the_rewrite_is_the_same_formula():
    for name in (
        "stick_boundary_proportional",
        "slip_zone_width",
        "stick_boundary_denominator",
        "slip_zone_width_first_order",
    ):
        formula = records()[name]
        reduced = reduce_formula(formula)
        assert reduced.formula.expr == formula.expr
        rebuilt = reduced.result.subs(list(reversed(reduced.temporaries)))
        assert sympy.cancel(rebuilt - formula.expr) == 0, name


def test_scaling_by_powers_of_two_gives_the_same_bits_as_the_derivation_form():
    # Moving 1/4 and 4 is exact in binary floating point: the emitted kernels agree bit for bit
    # with SymPy's own CSE'd printing of the derivation's expression (the kernels before).
    rng = np.random.default_rng(7)
    count = 10_000
    mu_, lam_, eta_ = (
        rng.uniform(0.05, 1.5, count),
        rng.uniform(-2, 2, count),
        rng.uniform(-0.5, 0.5, count),
    )
    a1 = rng.uniform(0.5, 2.0, count)
    da = a1 * 10.0 ** rng.uniform(-8, -1, count)
    L_I1 = rng.uniform(0.5, 2.0, count)
    L_I2 = L_I1 * (1 + da / a1 / 4)
    for kernel, second in ((stick_boundary_proportional, a1 + da), (slip_zone_width, da)):
        formula = records()[kernel.__name__]
        derivation_form = sympy.lambdify(
            [arg.symbol for arg in formula.args], formula.expr, modules="numpy", cse=True
        )
        arguments = (mu_, lam_, eta_, a1, second, L_I1, L_I2)
        assert np.array_equal(kernel(*arguments), derivation_form(*arguments)), kernel.__name__
