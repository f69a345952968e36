#!/usr/bin/python3
"""Steady Coulomb sliding between two different elastic solids is unstable (continuum).

tests/solver/interface_growth_test.cpp (case SpectralBiBimaterialCoulomb...) compares the
growth rate that the BI scheme measures with the continuum's. Perturb the slip of a steadily
sliding interface by D_1 = A exp(i k x1 + s t), k > 0, contact kept (no relative normal
motion). The tractions change by S = |k| Kc(sigma) D with sigma = s / |k| and Kc the
interface relation of two half-spaces (docs/spectral-bi.md "Two half-spaces";
solver/spectral/bimaterial_relations.hpp), and Coulomb friction (sliding towards +x1)
requires S_1 = -mu S_2:
    F(p) = Kc11 + mu Kc21 = 0,   p = s / (|k| c_s+).
A root with Re p > 0 grows at s = Re(p) |k| c_s+: the finest mode grows fastest, without
bound over k (Adams 1995; Ranjith & Rice 2001). The solids: the upper of the paper (rho = 1,
c_s = 1, nu = 0.25) and a lower one with the contrast of the bimaterial presets (density
x 2745.739/2730.834, c_s x 3091.6/2620, nu = 0.25). Roots are found by the secant method
from a grid of starting points; the script prints them for several mu and exits non-zero
unless every mu in (0, 0.75] has a root in Re p > 0 (the instability exists for any friction)
whose real part grows with mu.

Run: /usr/bin/python3 tests/solver/reference/bimaterial_coulomb_stability.py
"""
import sys

import numpy as np


def stiffness(p, r):
    a = np.sqrt(1 + r * r * p * p)
    b = np.sqrt(1 + p * p)
    q = 1 + r * r + r * r * p * p
    return -a * (1 + a * b) / q, -b * (1 + a * b) / q, 2 - (1 + a * b) / q


def half_space(sigma, rho, cs, cp, lower):
    mu = rho * cs * cs
    k11, k22, k12 = stiffness(sigma / cs, cs / cp)
    d = -1.0 if lower else 1.0
    return np.array([[d * mu * k11, 1j * mu * k12], [-1j * mu * k12, d * mu * k22]])


def interface(sigma, upper, lower):
    inv = np.linalg.inv
    return inv(inv(half_space(sigma, *upper, False)) - inv(half_space(sigma, *lower, True)))


UPPER = (1.0, 1.0, np.sqrt(3.0))
RHO, CS = 2745.739 / 2730.834, 3091.6 / 2620.0
LOWER = (RHO, CS, CS * np.sqrt(3.0))


def f(p, mu):
    kc = interface(p, UPPER, LOWER)  # c_s+ = 1: sigma = p
    return kc[0, 0] + mu * kc[1, 0]


def secant(g, x0, x1, iterations=80):
    g0, g1 = g(x0), g(x1)
    for _ in range(iterations):
        if g1 == g0:
            break
        x0, g0, x1 = x1, g1, x1 - g1 * (x1 - x0) / (g1 - g0)
        g1 = g(x1)
        if abs(x1 - x0) < 1e-14:
            break
    return x1


def growing_roots(mu):
    roots = set()
    for re in np.linspace(0.01, 3.0, 12):
        for im in np.linspace(-3.0, 3.0, 25):
            start = re + 1j * im
            with np.errstate(all="ignore"):
                p = secant(lambda z: f(z, mu), start, start * 1.001 + 0.001)
            if np.isfinite(p) and p.real > 1e-6 and abs(f(p, mu)) < 1e-9:
                roots.add(complex(round(p.real, 7), round(p.imag, 7)))
    return sorted(roots, key=lambda z: -z.real)


def main():
    fastest = []
    for mu in (0.1, 0.3, 0.5, 0.75):
        roots = growing_roots(mu)
        text = ", ".join(f"{z.real:.7f}{z.imag:+.7f}i" for z in roots)
        print(f"mu = {mu}: roots in Re p > 0: {text or 'none'}")
        fastest.append(roots[0].real if roots else 0.0)
    print(f"mu = 0.75: growth rate dx / c_s of the mode k = pi/dx: {np.pi * fastest[-1]:.4f}")
    ok = all(x > 0 for x in fastest) and all(b > a for a, b in zip(fastest, fastest[1:]))
    print("bimaterial_coulomb_stability: " + ("passed" if ok else "FAILED"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
