"""Vectorised draws of valid inputs: every corner of the input box, then random points inside.

One call draws arrays that cover what thousands of scalar Hypothesis examples did, and the
generated kernels (which broadcast) evaluate them in one pass.  Each range is sampled
uniformly, or log-uniformly when it spans decades; a range containing 0 also gets 0 itself in
a share of the samples.  The 2^m corners of the box come first, so the ends of every range are
met in every combination.

The draw is reproducible: seed ``SEED`` (set ``ASYMSLIP_TEST_SEED`` to explore others),
mixed with the names of the box.  A failing check names the worst sample and its inputs, as
Hypothesis names its falsifying example.
"""

from __future__ import annotations

import math
import os
import zlib
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

SEED = int(os.environ.get("ASYMSLIP_TEST_SEED", "20220625"))
SAMPLES = 50_000  # random points per box, after its corners
MAX_DIMENSIONS = 12  # 4096 corners
SPECIAL_SHARE = 1 / 64  # share of the random points set to a range's special values


@dataclass(frozen=True)
class Range:
    """A closed interval [low, high] of one input, sampled uniformly or log-uniformly."""

    low: float
    high: float
    log: bool = False

    def __post_init__(self) -> None:
        if not self.low <= self.high or (self.log and self.low <= 0):
            raise ValueError(f"bad range [{self.low}, {self.high}] (log={self.log})")

    @property
    def specials(self) -> tuple[float, ...]:
        """Values inside the range worth meeting exactly: 0 when the range has both signs."""
        return (0.0,) if self.low < 0 < self.high else ()

    def sample(self, rng: np.random.Generator, size: int) -> np.ndarray:
        u = rng.random(size)
        if self.log:
            low, high = math.log(self.low), math.log(self.high)
            values = np.exp(low + u * (high - low))
        else:
            values = self.low + u * (self.high - self.low)
        # exp and the affine map can round one ulp outside the interval.
        values = np.clip(values, self.low, self.high)
        for special in self.specials:
            values[rng.random(size) < SPECIAL_SHARE] = special
        return values


def uniform(low: float, high: float) -> Range:
    return Range(low, high)


def log_uniform(low: float, high: float) -> Range:
    return Range(low, high, log=True)


def draw(samples: int = SAMPLES, seed: int = SEED, **ranges: Range) -> dict[str, np.ndarray]:
    """Arrays of 2^m + ``samples`` points of the box spanned by the m ``ranges``.

    The first 2^m points are the corners (point k takes the high end of range j where bit j of
    k is set); the rest are independent random draws.
    """
    names = list(ranges)
    if len(names) > MAX_DIMENSIONS:
        raise ValueError(f"{len(names)} ranges: at most {MAX_DIMENSIONS} (2^m corners)")
    rng = np.random.default_rng([seed, zlib.crc32(",".join(names).encode())])
    corner_bits = (np.arange(2 ** len(names))[:, None] >> np.arange(len(names))) & 1
    return {
        name: np.concatenate(
            [
                np.where(corner_bits[:, j] == 1, ranges[name].high, ranges[name].low),
                ranges[name].sample(rng, samples),
            ]
        )
        for j, name in enumerate(names)
    }


def select(values: Mapping[str, np.ndarray], keep: np.ndarray) -> dict[str, np.ndarray]:
    """The samples where ``keep`` is true (a filter, as Hypothesis's ``assume``)."""
    return {name: np.asarray(value)[keep] for name, value in values.items()}


def assert_within(
    actual,
    expected,
    *,
    rtol: float = 0.0,
    atol=0.0,
    inputs: Mapping[str, np.ndarray],
    what: str = "",
) -> None:
    """|actual - expected| <= atol + rtol |expected| at every sample (NaN never passes).

    On failure the message gives the number of failing samples and the worst one (largest
    excess over its allowance) with every input at that sample.
    """
    actual, expected, atol = np.broadcast_arrays(
        np.asarray(actual, dtype=float),
        np.asarray(expected, dtype=float),
        np.asarray(atol, dtype=float),
    )
    if actual.size == 0:
        raise AssertionError(f"{what}: no samples to check")
    allowance = atol + rtol * np.abs(expected)
    with np.errstate(invalid="ignore", divide="ignore"):
        difference = np.abs(actual - expected)
        good = difference <= allowance
        excess = np.where(np.isnan(difference), np.inf, difference / allowance)
    if good.all():
        return
    worst = int(np.argmax(np.where(good, -np.inf, excess)))
    shown = {
        name: float(np.broadcast_to(value, actual.shape)[worst]) for name, value in inputs.items()
    }
    raise AssertionError(
        f"{what}: {np.count_nonzero(~good)} of {actual.size} samples out of tolerance "
        f"(seed {SEED}); worst, sample {worst}: got {float(actual[worst])!r}, expected "
        f"{float(expected[worst])!r}, |difference| {difference[worst]:.3e} > allowance "
        f"{allowance[worst]:.3e}; inputs {shown}"
    )
