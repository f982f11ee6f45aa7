"""The contact laws are immutable records: checked once when built, never changed after.

Issue 21: no frozen object is mutated (a law's parameters are checked and made floats before
its frozen record is built, its derived constants cached beside it), and a law stays what
solve-batch ships to its workers: picklable, equal and hashable by its parameters.
"""

from __future__ import annotations

import dataclasses
import inspect
import pickle

import numpy as np
import pytest

from asymslip import FlatRoundedLaw, HertzLaw, PowerLaw
from asymslip.errors import InputError

#: Each law built from ints and NumPy scalars, with the floats it must hold.
LAWS = [
    (HertzLaw, (1, np.float64(2.5)), (1.0, 2.5)),
    (PowerLaw, (np.int64(1), 2, 3), (1.0, 2.0, 3.0)),
    (FlatRoundedLaw, (np.float32(0.5), 10, 1), (0.5, 10.0, 1.0)),
]
IDS = [kind.__name__ for kind, _, _ in LAWS]


@pytest.mark.parametrize(("kind", "given", "held"), LAWS, ids=IDS)
def test_parameters_are_python_floats(kind: type, given: tuple, held: tuple) -> None:
    law = kind(*given)
    values = tuple(getattr(law, field.name) for field in dataclasses.fields(law))
    assert values == held
    assert all(type(value) is float for value in values)


@pytest.mark.parametrize(("kind", "given", "held"), LAWS, ids=IDS)
def test_equal_and_hashed_by_parameters(kind: type, given: tuple, held: tuple) -> None:
    assert kind(*given) == kind(*held)
    assert hash(kind(*given)) == hash(kind(*held))
    other = kind(*(value * 2 for value in held))
    assert other != kind(*held)


@pytest.mark.parametrize(("kind", "given", "held"), LAWS, ids=IDS)
def test_frozen(kind: type, given: tuple, held: tuple) -> None:
    law = kind(*given)
    first = dataclasses.fields(law)[0].name
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(law, first, 7.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        law.anything = 1.0  # type: ignore[attr-defined]
    assert getattr(law, first) == held[0]


@pytest.mark.parametrize(("kind", "given", "held"), LAWS, ids=IDS)
def test_pickles_to_an_equal_law(kind: type, given: tuple, held: tuple) -> None:
    law = kind(*given)
    law.half_width(np.array([2.0, 3.0]))  # derived constants cached (PowerLaw's K(n))
    copy = pickle.loads(pickle.dumps(law))
    assert copy == law and hash(copy) == hash(law)
    np.testing.assert_array_equal(copy.half_width(np.array([2.0, 3.0])), law.half_width([2.0, 3.0]))


@pytest.mark.parametrize(("kind", "given", "held"), LAWS, ids=IDS)
def test_replace_checks_again(kind: type, given: tuple, held: tuple) -> None:
    law = kind(*given)
    name = dataclasses.fields(law)[-1].name  # E_star: > 0
    assert getattr(dataclasses.replace(law, **{name: 4}), name) == 4.0
    with pytest.raises(InputError, match=name):
        dataclasses.replace(law, **{name: -1.0})


@pytest.mark.parametrize("kind", [HertzLaw, PowerLaw, FlatRoundedLaw], ids=IDS)
def test_no_frozen_field_set_behind_the_record(kind: type) -> None:
    # object.__setattr__ on a frozen record is what issue 21 removed; the dataclass's own
    # constructor is the one place a field is set.
    assert "object.__setattr__" not in inspect.getsource(inspect.getmodule(kind))


def test_power_law_constant_computed_once() -> None:
    law = PowerLaw(0.5, 2.0, 1.0)
    assert law.shape_factor is law.shape_factor  # cached, not recomputed per call
    assert law._parameters is law._parameters
    # K(2) = pi/2: P = (pi/2) E* A a^2 is the cylinder (29) with A = 1/(2R).
    assert law.shape_factor == pytest.approx(np.pi / 2, rel=1e-15)
