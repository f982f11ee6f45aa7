"""Independent references for the stress tests: McEwen's closed form and Flamant quadrature.

``mcewen`` is McEwen's (1949) field of the Hertz line contact, as given by Johnson (Contact
Mechanics, 1985, Sec. 7.2), transcribed by hand: a pressure p0 sqrt(1 - x^2/a^2) and a shear
traction q0 sqrt(1 - x^2/a^2) on z >= 0, with

    m^2 = ((A^2 + 4 x^2 z^2)^(1/2) + A)/2,   n^2 = ((A^2 + 4 x^2 z^2)^(1/2) - A)/2,
    A = a^2 - x^2 + z^2,  m >= 0 (z >= 0), n with the sign of x.

The shear traction here is the traction exerted on the body along +x (the convention of
``asymslip.stress``), which fixes the signs of the shear terms; they are checked against
Flamant's point-force fields, integrated by mpmath (``flamant_quadrature``), in
``test_mcewen_transcription_matches_flamant_quadrature``.
"""

from __future__ import annotations

import mpmath
import numpy as np


def mcewen(
    x: np.ndarray, z: np.ndarray, a: float, p0: float, q0: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(sxx, szz, sxz) under the Hertz pressure (p0) and the sliding shear (q0), tension +."""
    x, z = np.broadcast_arrays(np.asarray(x, float), np.asarray(z, float))
    A = a * a - x * x + z * z
    root = np.sqrt(A * A + 4 * x * x * z * z)
    m = np.sqrt(np.maximum(root + A, 0) / 2)
    n = np.sign(x) * np.sqrt(np.maximum(root - A, 0) / 2)
    D = m * m + n * n
    sx_p = -(p0 / a) * (m * (1 + (z * z + n * n) / D) - 2 * z)
    sz_p = -(p0 / a) * m * (1 - (z * z + n * n) / D)
    txz_p = -(p0 / a) * n * (m * m - z * z) / D
    sx_q = (q0 / a) * (n * (2 - (z * z - m * m) / D) - 2 * x)
    sz_q = -(q0 / a) * n * (m * m - z * z) / D
    txz_q = -(q0 / a) * (m * (1 + (z * z + n * n) / D) - 2 * z)
    return sx_p + sx_q, sz_p + sz_q, txz_p + txz_q


def flamant_quadrature(
    pressure, shear, ends: tuple[float, float], x: float, z: float, digits: int = 25
) -> tuple[mpmath.mpf, mpmath.mpf, mpmath.mpf]:
    """(sxx, szz, sxz) at (x, z) by mpmath quadrature of Flamant's point-force fields
    (Johnson, Sec. 2.2) over the loads ``pressure(t)`` and ``shear(t)`` on ``ends``."""
    with mpmath.workdps(digits):
        X, Z = mpmath.mpf(x), mpmath.mpf(z)
        lo, hi = (mpmath.mpf(e) for e in ends)

        def component(index: int):
            def integrand(t):
                u = X - t
                r4 = (u * u + Z * Z) ** 2
                p, q = pressure(t), shear(t)
                kernels = (
                    p * Z * u * u + q * u**3,
                    p * Z**3 + q * Z * Z * u,
                    p * Z * Z * u + q * Z * u * u,
                )
                return -2 / mpmath.pi * kernels[index] / r4

            points = [lo, X, hi] if lo < X < hi else [lo, hi]
            return mpmath.quad(integrand, points)

        return component(0), component(1), component(2)
