#!/usr/bin/python3
"""Is steady Coulomb sliding of an elastic half-space on a rigid plane stable? (continuum)

docs/verification.md (BI findings) asks whether a growing interface mode of plain Coulomb
friction is a property of the continuum or of a discretisation. In the continuum a
perturbation D_1 = A exp(i k x1 + s t) of the slip of a steadily sliding interface (contact
kept, D_2 = 0) changes the tractions by (solver/spectral/half_space_kernels.hpp)
    S_1 = mu_s |k| K11(p) A,   S_2 = -i sgn(k) mu_s |k| K12(p) A,    p = s / (|k| c_s),
and Coulomb friction (slip continuing in +x1: sigma_21 = -mu sigma_22) requires S_1 = -mu S_2:
    F(p) = K11(p) - i sgn(k) mu K12(p) = 0.
A root with Re p > 0 grows at s = p |k| c_s: a rate proportional to |k|, unbounded over the
modes (Renardy 1992's ill-posedness). The roots of k < 0 are the complex conjugates of those
of k > 0, so F for k > 0 is enough.

F is analytic in Re p > 0 and F(p) ~ -p at infinity, so the number of its roots there is
the winding number of F along the boundary of the half disc {Re p > eps, |p| < R}. This
script counts them for several friction coefficients mu, finds the critical mu_c where the
first root enters, and exits non-zero unless: no root for mu < mu_c, a root for mu > mu_c,
and mu_c > 0.75 (the paper's mu) for nu = 0.25 and 0.35.

Measured: mu_c = 1 for both. It is exact for every nu: at p = -i sqrt(2) (b^2 = -1,
a = sqrt(1 - 2 r^2), Q = 1 - r^2), F = (mu - 1) a (1 - i a) / (1 - r^2) with the branch b = -i
of the limit from Re p > 0, so the root leaves the imaginary axis there as mu passes 1.
The paper's mu = 0.75 is below it: the continuum has no growing mode, and a growth that a
scheme shows at mu = 0.75 is the scheme's (tests/solver/interface_growth_test.cpp).

Run: /usr/bin/python3 tests/solver/reference/coulomb_stability.py
"""
import sys

import numpy as np

EPS, RADIUS, SAMPLES = 1e-9, 60.0, 100_000


def stiffness(p, r):
    """K11, K12 of the half-space (principal square roots: Re a, Re b > 0 for Re p > 0)."""
    a = np.sqrt(1 + r * r * p * p)
    b = np.sqrt(1 + p * p)
    q = 1 + r * r + r * r * p * p
    return -a * (1 + a * b) / q, 2 - (1 + a * b) / q


def contour():
    """The boundary of {Re p > EPS, |p| < RADIUS}, counter-clockwise, with extra points near
    the branch points p = +-i, +-i/r on the imaginary axis."""
    y = np.linspace(-RADIUS, RADIUS, SAMPLES)
    y = np.sort(np.concatenate([y, np.linspace(-2.0, 2.0, SAMPLES)]))
    line = EPS + 1j * y[::-1]                          # from +i R down to -i R
    angle = np.linspace(-np.pi / 2, np.pi / 2, SAMPLES)
    arc = RADIUS * np.exp(1j * angle)                  # from -i R round to +i R
    return np.concatenate([line, arc])


def roots_in_right_half_plane(mu, r):
    k11, k12 = stiffness(contour(), r)
    f = k11 - 1j * mu * k12
    closest = np.min(np.abs(f))
    if closest < 1e-6:
        raise RuntimeError(f"mu = {mu}: F vanishes near the contour ({closest:.1e})")
    turns = np.sum(np.diff(np.unwrap(np.angle(np.append(f, f[0]))))) / (2 * np.pi)
    return int(round(turns))


def critical_mu(r, low=0.0, high=4.0):
    """The smallest mu with a root in Re p > 0 (bisection on the root count)."""
    if roots_in_right_half_plane(high, r) == 0:
        return float("inf")
    for _ in range(20):
        mid = 0.5 * (low + high)
        if roots_in_right_half_plane(mid, r) > 0:
            high = mid
        else:
            low = mid
    return 0.5 * (low + high)


def main():
    failures = []
    for nu in (0.25, 0.35):
        r = np.sqrt((1 - 2 * nu) / (2 * (1 - nu)))  # c_s / c_p
        mu_c = critical_mu(r)
        counts = {mu: roots_in_right_half_plane(mu, r) for mu in (0.3, 0.5, 0.75, 1.5, 2.0)}
        print(f"[measure] Coulomb sliding stability, nu = {nu}: roots with Re p > 0 by mu: "
              f"{counts}; critical mu_c = {mu_c:.6f}")
        for mu, count in counts.items():
            if (mu < mu_c) != (count == 0):
                failures.append(f"nu = {nu}, mu = {mu}: {count} roots, mu_c = {mu_c}")
        if not mu_c > 0.75:
            failures.append(f"nu = {nu}: mu_c = {mu_c} <= 0.75 (the paper's mu)")
    for f in failures:
        print("FAIL:", f)
    print("coulomb_stability:", "failed" if failures else "passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
