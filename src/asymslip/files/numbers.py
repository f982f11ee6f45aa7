"""Doubles as the shortest text that reads back to the same double, vectorised with NumPy.

The layout is the one ``pyarrow.csv.write_csv`` uses (Arrow formats with the
double-conversion library's ``ToShortest``): the shortest digit string that reads back to the
double, the closest to it when several are as short; fixed notation for decimal exponents
-6 <= E < 10 (``0.000001``, ``123.5``, ``1000000000``), otherwise ``d.ddde+XX``/``d.ddde-XX``
with no leading zeros in the exponent (``1e-7``, ``5e-324``, ``1.7976931348623157e+308``);
``0`` and ``-0``; ``inf`` and ``-inf``.  NaN is "no value" here and gives an empty field.  So
the NumPy writer and pyarrow's writer give the same bytes (tested on millions of doubles).

How the digits are found without a per-number Python call
---------------------------------------------------------
A positive double ``x = f 2^(e-1)`` (``1 <= f < 2``) is scaled by ``Q = 2^(e-1) 10^s``, ``s``
chosen from ``e`` alone so that ``X = x 10^s`` lies in ``[1e16, 2e17)``: at that scale an integer
has at least 17 digits, which always identify a double.  ``Q`` is kept as a double-double
(106 bits, correctly rounded from the exact rational), ``X`` and the ends of the rounding
interval of ``x`` (the midpoints to its neighbours, ``L`` and ``H``) are double-double products
and sums (Dekker's exact product), so they are known to about ``1e-14`` absolute.  A digit
string of ``17 - k`` significant digits is a multiple of ``10^k`` in ``[L, H]``; the largest such
``k`` gives the shortest string, and the multiple nearest to ``X`` the closest one.  Where an
end of the interval or a tie lies within ``1e-9`` of a decision (only when ``x`` has an exact
short decimal expansion, e.g. a power of two whose midpoint is a decimal; about 1 in 10^8 of
random doubles) the number is formatted by Python's ``repr`` instead, which is exact.

Examples
--------
>>> import numpy as np
>>> from asymslip.files.numbers import compress_rows, format_doubles
>>> values = np.array([0.1, 1 / 3, 123.5, 1e-7, 1e22, -0.0, np.nan])
>>> compress_rows(format_doubles(values))
[b'0.1', b'0.3333333333333333', b'123.5', b'1e-7', b'1e+22', b'-0', b'']
"""

from __future__ import annotations

from fractions import Fraction
from functools import cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

#: Decimal exponents written in fixed notation (Arrow's decimal_in_shortest_low/high).
FIXED_LOW, FIXED_HIGH = -6, 10
#: A decision closer than this (in units of the last of 17+ digits) is left to ``repr``.  The
#: double-double arithmetic is good to about 2e17 * 2^-104 = 1e-14 there.
_MARGIN = 1e-9
_SPLIT = 134217729.0  # 2^27 + 1, Dekker's splitter
_POW10 = np.array([10**k for k in range(19)], dtype=np.int64)
_FOUR_DIGITS = np.frombuffer("".join(f"{i:04d}" for i in range(10_000)).encode(), np.uint8).reshape(
    10_000, 4
)
_FOUR_DIGITS_U32 = _FOUR_DIGITS.copy().view(np.uint32).ravel()
_ZERO, _DOT, _MINUS, _PLUS, _E = (ord(c) for c in "0.-+e")


@cache
def _scales() -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]]:
    """Per binary exponent e of ``np.frexp``: ``Q = 2^(e-1) 10^s`` as a double-double, and s.

    ``s = 16 - floor((e - 1) log10 2)``, computed exactly, puts ``2^(e-1) 10^s`` in
    ``[1e16, 1e17)``; hi is the correctly rounded double of the exact rational, lo the
    correctly rounded remainder.
    """
    exponents = range(-1073, 1025)
    hi, lo, scale = [], [], []
    for e in exponents:
        power = Fraction(2) ** (e - 1)
        # floor(log10(2^(e-1))) exactly: start from the float estimate, correct by comparison.
        digits = int(np.floor((e - 1) * np.log10(2.0)))
        while Fraction(10) ** (digits + 1) <= power:
            digits += 1
        while Fraction(10) ** digits > power:
            digits -= 1
        s = 16 - digits
        exact = power * Fraction(10) ** s
        high = float(exact)
        hi.append(high)
        lo.append(float(exact - Fraction(high)))
        scale.append(s)
    return np.array(hi), np.array(lo), np.array(scale, dtype=np.int64)


def _two_sum(a: FloatArray, b: FloatArray) -> tuple[FloatArray, FloatArray]:
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _two_product(a: FloatArray, b: FloatArray) -> tuple[FloatArray, FloatArray]:
    p = a * b
    ca, cb = _SPLIT * a, _SPLIT * b
    ah = ca - (ca - a)
    bh = cb - (cb - b)
    al, bl = a - ah, b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _floor_split(hi: FloatArray, lo: FloatArray) -> tuple[NDArray[np.int64], FloatArray]:
    """floor(hi + lo) as int64 and the fraction, for hi an integer-valued double >= 2^53."""
    whole = np.floor(lo)
    return hi.astype(np.int64) + whole.astype(np.int64), lo - whole


def _shortest_digits(
    x: NDArray[np.float64],
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.bool_]]:
    """Digits (an integer without trailing zeros), decimal exponent of its last digit, and
    a mask of the numbers whose decision was too close to call (left to ``repr``)."""
    q_hi, q_lo, scales = _scales()
    fraction, exponent = np.frexp(x)
    index = exponent + 1073
    f = fraction * 2.0  # in [1, 2): x = f 2^(e-1), exactly
    Qh, Ql = q_hi[index], q_lo[index]
    p, error = _two_product(f, Qh)
    Xh, Xl = _two_sum(p, error + f * Ql)
    # Half the gap to each neighbour, in units of f: ulp 2^-52 for normal numbers (fewer bits
    # for subnormal ones); the gap below a power of two is half the gap above it.
    ulp = np.ldexp(1.0, np.maximum(-52, -1074 - (exponent - 1)))
    below = np.where((f == 1.0) & (exponent - 1 > -1022) & (ulp == 2.0**-52), ulp / 4, ulp / 2)
    up_h, up_l = (ulp / 2) * Qh, (ulp / 2) * Ql  # exact: powers of two
    down_h, down_l = below * Qh, below * Ql
    s, e = _two_sum(Xh, up_h)
    Hh, Hl = _two_sum(s, e + (Xl + up_l))
    s, e = _two_sum(Xh, -down_h)
    Lh, Ll = _two_sum(s, e + (Xl - down_l))
    X_floor, X_frac = _floor_split(Xh, Xl)
    L_floor, L_frac = _floor_split(Lh, Ll)
    H_floor, H_frac = _floor_split(Hh, Hl)
    unsure = (
        (L_frac < _MARGIN) | (L_frac > 1 - _MARGIN) | (H_frac < _MARGIN) | (H_frac > 1 - _MARGIN)
    )
    low = L_floor  # integers in (low, high] are strictly inside the interval
    high = H_floor
    # k: the most trailing zeros a number in (low, high] can have.  Most doubles need 16 or
    # 17 digits, so only the few still alive go on to the next power of ten.
    k = np.zeros(x.size, np.int64)
    alive = np.arange(x.size)
    for power in range(1, 19):
        t = _POW10[power]
        more = low[alive] // t < high[alive] // t
        alive = alive[more]
        k[alive] = power
        if not alive.size:
            break
    t = _POW10[k]
    base = X_floor.copy()
    for power in range(1, int(k.max(initial=0)) + 1):  # a scalar divisor is 10x faster
        where = np.flatnonzero(k == power)
        base[where] //= _POW10[power]
    remainder = X_floor - base * t
    # Nearest multiple of 10^k to X: below when 2 (remainder + frac) < t.
    twice = (2 * remainder - t).astype(np.float64) + 2 * X_frac
    unsure |= np.abs(twice) < 2 * _MARGIN
    digits = base + (twice > 0)
    # The nearest may lie outside the interval (the short side below a power of two).
    digits = np.where(digits * t <= low, digits + 1, digits)
    digits = np.where(digits * t > high, digits - 1, digits)
    return digits, k - scales[index], unsure


def _repr_digits(values: NDArray[np.float64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Digits and exponent of the last digit from Python's exact shortest ``repr``."""
    digits, exponents = [], []
    for value in values.tolist():
        mantissa, _, power = repr(abs(value)).partition("e")
        whole, _, part = mantissa.partition(".")
        text = (whole + part).lstrip("0")
        shift = int(power or 0) - len(part)
        stripped = text.rstrip("0")
        shift += len(text) - len(stripped)
        digits.append(int(stripped))
        exponents.append(shift)
    return np.array(digits, dtype=np.int64), np.array(exponents, dtype=np.int64)


def _digit_count(digits: NDArray[np.int64]) -> NDArray[np.int64]:
    return np.searchsorted(_POW10[1:], digits, side="right").astype(np.int64) + 1


#: Columns of one number in the layout below: sign, "0." and five zeros (fixed notation below
#: 1), the digits with a point slot after each of the first ten, then "e", sign, three digits.
_SIGN, _LEAD, _DIGITS, _EXP = 0, 1, 8, 35
WIDTH = 40


def format_doubles(
    values: ArrayLike, block_rows: int = 1 << 15, out: NDArray[np.uint8] | None = None
) -> NDArray[np.uint8]:
    """Each double as the shortest text that reads back to it, in pyarrow's layout.

    Parameters
    ----------
    values
        Any array of float64 (flattened, C order).
    block_rows
        Numbers formatted at once (small enough for the work to stay in cache).
    out
        Where to write: ``(n, WIDTH)`` zeros (a view is fine); a new array by default.

    Returns
    -------
    numpy.ndarray
        ``(n, WIDTH)`` ASCII bytes, one number per row, with NUL bytes wherever the number
        has no character (drop them to get the text, e.g. with :func:`compress_rows`);
        NaN gives an empty row (NaN means "no value" in the tool's tables).
    """
    x = np.ascontiguousarray(values, dtype=np.float64).ravel()
    if out is None:
        out = np.zeros((x.size, WIDTH), np.uint8)
    for start in range(0, x.size, block_rows):
        _format_block(x[start : start + block_rows], out[start : start + block_rows])
    return out


def _format_block(x: NDArray[np.float64], out: NDArray[np.uint8]) -> None:
    negative = np.signbit(x)
    regular = np.isfinite(x) & (x != 0)
    if regular.all():
        rows = None
        magnitude = np.abs(x)
    else:
        rows = np.flatnonzero(regular)
        magnitude = np.abs(x[rows])
        zero = x == 0
        out[zero, _DIGITS] = _ZERO
        out[zero & negative, _SIGN] = _MINUS
        infinite = np.isinf(x)
        out[infinite & negative, _SIGN] = _MINUS
        out[infinite, _DIGITS : _DIGITS + 3] = np.frombuffer(b"inf", np.uint8)
    if not magnitude.size:
        return
    digits, last, unsure = _shortest_digits(magnitude)
    if unsure.any():
        where = np.flatnonzero(unsure)
        digits[where], last[where] = _repr_digits(magnitude[where])
    target = out if rows is None else np.zeros((rows.size, WIDTH), np.uint8)
    _layout(target, negative if rows is None else negative[rows], digits, last)
    if rows is not None:
        out[rows] = target


def _layout(
    out: NDArray[np.uint8],
    negative: NDArray[np.bool_],
    digits: NDArray[np.int64],
    last: NDArray[np.int64],
) -> None:
    """Sign, digits, point and exponent of each number into its row of ``out``.

    Each column is one uint8 vector (masks multiplied, no ``np.where``, no ``%``: NumPy's
    integer modulo is ten times slower than its division by a scalar).
    """
    count = _digit_count(digits)
    first = last + count - 1  # decimal exponent of the leading digit
    fixed = (first >= FIXED_LOW) & (first < FIXED_HIGH)
    small = fixed & (first < 0)
    exponential = ~fixed
    out[:, _SIGN] = negative * np.uint8(_MINUS)
    # "0." and -first-1 zeros before the digits of 0.000ddd
    out[:, _LEAD] = small * np.uint8(_ZERO)
    out[:, _LEAD + 1] = small * np.uint8(_DOT)
    for zero in range(5):
        out[:, _LEAD + 2 + zero] = (small & (-first - 1 > zero)) * np.uint8(_ZERO)
    # The digits as 17 left-aligned characters: scale to exactly 17 digits, four at a time.
    full = digits * _POW10[17 - count]
    text = np.empty((digits.size, 5), np.uint32)
    for group in range(4, -1, -1):
        rest = full // 10_000
        text[:, group] = _FOUR_DIGITS_U32[full - rest * 10_000]
        full = rest
    characters = text.view(np.uint8)
    # Digits before the point in fixed notation (zeros beyond the digits up to the point).
    point = np.where(fixed & ~small, first + 1, 1)
    dot_after = np.where(~small & (count > point), point - 1, -1)
    column = _DIGITS
    for place in range(17):
        shown = place < count
        if place < 10:
            padding = (place < point) & ~shown
            out[:, column] = characters[:, 3 + place] * shown + padding * np.uint8(_ZERO)
            out[:, column + 1] = (dot_after == place) * np.uint8(_DOT)
            column += 2
        else:
            out[:, column] = characters[:, 3 + place] * shown
            column += 1
    size = np.abs(first)
    hundreds = size // 100
    tens = size // 10
    out[:, _EXP] = exponential * np.uint8(_E)
    out[:, _EXP + 1] = exponential * (np.uint8(_PLUS) + (first < 0) * np.uint8(_MINUS - _PLUS))
    out[:, _EXP + 2] = (hundreds > 0) * (_ZERO + hundreds).astype(np.uint8)
    out[:, _EXP + 3] = (exponential & (tens > 0)) * (_ZERO + tens - 10 * hundreds).astype(np.uint8)
    out[:, _EXP + 4] = exponential * (_ZERO + size - 10 * tens).astype(np.uint8)


def compress_rows(block: NDArray[np.uint8]) -> list[bytes]:
    """Each row of a NUL-padded block as bytes with the padding dropped."""
    kept = block != 0
    ends = np.cumsum(kept.sum(axis=1)).tolist()
    flat = block[kept].tobytes()
    return [flat[start:end] for start, end in zip([0, *ends[:-1]], ends, strict=True)]
