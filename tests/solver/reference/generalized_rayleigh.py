#!/usr/bin/python3
"""The generalized Rayleigh speed of two elastic solids (Weertman 1980), independently.

docs/spectral-bi.md ("Two half-spaces") finds it as the root of mu+ N+(v) + mu- N-(v) = 0
with N = K22 - K12^2/K11 of each half-space's kernels; the C++ test
(tests/solver/spectral/bimaterial_kernels_test.cpp) checks solver/spectral/bimaterial_relations.*
against the numbers printed here. This script does not use those kernels: it writes the
wave e^{i k (x1 - v t)} (k = 1) in displacement potentials in both solids,
    u1 = phi,1 + psi,2,   u2 = phi,2 - psi,1,
    upper (x2 > 0): phi = A e^{i x1 - alpha x2},  psi = B e^{i x1 - beta x2},
    lower (x2 < 0): phi = C e^{i x1 + alpha' x2}, psi = D e^{i x1 + beta' x2},
    alpha = sqrt(1 - v^2/c_p^2), beta = sqrt(1 - v^2/c_s^2) (each solid's own),
    sigma12 = mu (2 phi,12 + psi,22 - psi,11), sigma22 = lambda lap(phi) + 2 mu (phi,22 - psi,12),
and asks for frictionless contact: sigma12 = 0 on both sides, u2 and sigma22 continuous.
The speed where the 4x4 determinant vanishes is printed (mpmath, 30 digits), for
  - identical solids (nu = 0.25): the Rayleigh speed sqrt(2 - 2/sqrt(3)) c_s (check);
  - the bimaterial presets' solids (upper rho 2730.834 kg/m^3, c_p 4537.973,
    c_s 2620 m/s; lower 2745.739, 5354.808, 3091.6 m/s).
Exits non-zero if the identical-solid root is not the Rayleigh speed.

Run: /usr/bin/python3 tests/solver/reference/generalized_rayleigh.py
"""
import sys

import mpmath as mp

mp.mp.dps = 30


def solid(rho, cp, cs):
    rho, cp, cs = mp.mpf(rho), mp.mpf(cp), mp.mpf(cs)
    mu = rho * cs**2
    return {"rho": rho, "cp": cp, "cs": cs, "mu": mu, "lam": rho * cp**2 - 2 * mu}


def boundary_rows(m, v, sign):
    """u2, sigma12, sigma22 at x2 = 0 per unit potential amplitude, for the solid on the
    side `sign` (+1 upper: decay e^{-alpha x2}; -1 lower: e^{+alpha x2})."""
    alpha = -sign * mp.sqrt(1 - v**2 / m["cp"] ** 2)  # d/dx2 of the phi exponent
    beta = -sign * mp.sqrt(1 - v**2 / m["cs"] ** 2)
    i = mp.mpc(0, 1)
    # phi = e^{i x1 + alpha x2}: phi,1 = i, phi,2 = alpha; psi likewise with beta.
    u2 = (alpha, -i)
    s12 = (m["mu"] * 2 * i * alpha, m["mu"] * (beta**2 + 1))
    s22 = (m["lam"] * (alpha**2 - 1) + 2 * m["mu"] * alpha**2, -2 * m["mu"] * i * beta)
    return u2, s12, s22


def frictionless_determinant(up, lo, v):
    u2p, s12p, s22p = boundary_rows(up, v, +1)
    u2m, s12m, s22m = boundary_rows(lo, v, -1)
    rows = [
        [s12p[0], s12p[1], 0, 0],
        [0, 0, s12m[0], s12m[1]],
        [u2p[0], u2p[1], -u2m[0], -u2m[1]],
        [s22p[0], s22p[1], -s22m[0], -s22m[1]],
    ]
    return mp.det(mp.matrix(rows))


def root(up, lo):
    hi = min(up["cs"], lo["cs"]) * (1 - mp.mpf(10) ** -25)
    f = lambda v: mp.re(frictionless_determinant(up, lo, v) / up["mu"] ** 2)
    lo_v = hi * mp.mpf("0.5")
    if f(lo_v) * f(hi) > 0:
        return None
    return mp.findroot(f, (lo_v, hi), solver="anderson")


def main():
    paper = solid(1, mp.sqrt(3), 1)  # nu = 0.25
    rayleigh = root(paper, paper)
    exact = mp.sqrt(2 - 2 / mp.sqrt(3))
    print(f"identical solids (nu = 0.25): c_GR / c_s = {mp.nstr(rayleigh, 20)} "
          f"(Rayleigh {mp.nstr(exact, 20)})")
    upper = solid("2730.834", "4537.973", "2620")
    lower = solid("2745.739", "5354.808", "3091.6")
    c_gr = root(upper, lower)
    print(f"bimaterial presets: c_GR = {mp.nstr(c_gr, 20)} m/s")
    if abs(rayleigh - exact) > mp.mpf(10) ** -20:
        print("generalized_rayleigh: FAILED")
        return 1
    print("generalized_rayleigh: passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
