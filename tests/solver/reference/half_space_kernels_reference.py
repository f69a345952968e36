#!/usr/bin/python3
"""Reference values for the 2D plane-strain half-space Dirichlet-to-Neumann kernel.

Half-space x2 > 0, prescribed surface displacement u_j(x1,0,t) = D_j(t) exp(i k x1), k > 0.
S_j = sigma_{2j}(x1, 0, t) exp(-i k x1).  Laplace domain:  S_hat = mu k M(p) D_hat,
p = s/(k c_s), r = c_s/c_p,  a = sqrt(1 + r^2 p^2),  b = sqrt(1 + p^2),  Delta = 1 + r^2 + r^2 p^2:

    M11 = -a (1 + a b)/Delta          M12 = +i [2 - (1 + a b)/Delta]
    M22 = -b (1 + a b)/Delta          M21 = -M12

M = -diag(p, p/r) + M_inf + H_hat(p),  M_inf = [[0, i(2 - 1/r)], [-i(2 - 1/r), 0]].
Off-diagonal quantities are purely imaginary; they are reported as coefficients of i:
    H12(T) = i * H12_over_i(T),  H21(T) = i * H21_over_i(T) = -H12(T).

Run:  /usr/bin/python3 kernels_reference.py > kernels_reference.json
"""
import json, sys, time
import numpy as np
import mpmath as mp

DPS = 40
mp.mp.dps = DPS
T_LIST = [0.01, 0.5, 1, 2, 3.7, 5, 10, 20, 40]
NU_LIST = [0.25, 0.35]
t_start = time.time()


def r_of_nu(nu):
    nu = mp.mpf(nu)
    return mp.sqrt((1 - 2 * nu) / (2 * (1 - nu)))


# ---------------------------------------------------------------------------
# closed forms (branch cuts pointing to the left: sqrt(p+i c) sqrt(p-i c);
# equals the principal sqrt(1+c^2 p^2)/c-branch with Re>0 for Re p > 0,
# and is what Talbot / de Hoog contours need)
def ab(p, r):
    a = r * mp.sqrt(p + 1j / r) * mp.sqrt(p - 1j / r)
    b = mp.sqrt(p + 1j) * mp.sqrt(p - 1j)
    return a, b


def M_closed(p, r):
    a, b = ab(p, r)
    D = 1 + r**2 + r**2 * p**2
    q = (1 + a * b) / D
    m12 = 2 - q                      # M12 = i*m12
    return {"M11": -a * q, "M22": -b * q, "M12_over_i": m12, "M21_over_i": -m12}


def M_potential_raw(p, r):
    """unsimplified form straight from the potential solution (before rationalising)"""
    a, b = ab(p, r)
    den = 1 - a * b
    return {"M11": a * p**2 / den, "M22": b * p**2 / den,
            "M12_over_i": (1 + b**2 - 2 * a * b) / den,
            "M21_over_i": -(1 + b**2 - 2 * a * b) / den}


def Minf(r):
    return {"M11": mp.mpf(0), "M22": mp.mpf(0), "M12_over_i": 2 - 1 / r, "M21_over_i": -(2 - 1 / r)}


def Hhat(name, p, r):
    M = M_closed(p, r)
    lin = {"M11": p, "M22": p / r, "M12_over_i": 0, "M21_over_i": 0}[name]
    return M[name] + lin - Minf(r)[name]


KERNELS = ["M11", "M22", "M12_over_i", "M21_over_i"]
HN = {"M11": "H11", "M22": "H22", "M12_over_i": "H12_over_i", "M21_over_i": "H21_over_i"}
GN = {"M11": "G11", "M22": "G22", "M12_over_i": "G12_over_i", "M21_over_i": "G21_over_i"}


def M0_closed(r):
    return {"M11": -2 / (1 + r**2), "M22": -2 / (1 + r**2),
            "M12_over_i": 2 * r**2 / (1 + r**2), "M21_over_i": -2 * r**2 / (1 + r**2)}


def H0plus_closed(r):
    # lim_{p->inf} p*H_hat(p)
    return {"M11": -(2 - r) / (2 * r), "M22": -(2 * r - 1) / (2 * r**3),
            "M12_over_i": mp.mpf(0), "M21_over_i": mp.mpf(0)}


def H0plus_slope_offdiag(r):
    # H12_over_i(T) ~ (1-r)^2/(2 r^3) * T for small T   (h12_hat ~ (1-r)^2/(2 r^3 p^2))
    return (1 - r)**2 / (2 * r**3)


# ---------------------------------------------------------------------------
# independent check of M: numerical eigen-solution of Navier's equations (numpy,
# no potentials).  u = v exp(i x1 - q x2) (k = 1), Re q > 0.
def M_navier_numeric(p, nu):
    p = complex(p)
    kap = 2 * (1 - nu) / (1 - 2 * nu)          # (lambda+2mu)/mu = 1/r^2
    Q2 = np.diag([1.0, kap]).astype(complex)
    Q1 = -1j * (kap - 1) * np.array([[0, 1], [1, 0]], dtype=complex)
    Q0 = np.diag([-kap - p**2, -1 - p**2]).astype(complex)
    # linearise (Q2 q^2 + Q1 q + Q0) v = 0
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(Q2, Q0), -np.linalg.solve(Q2, Q1)]])
    w, V = np.linalg.eig(A)
    idx = [i for i in range(4) if w[i].real > 0]
    assert len(idx) == 2
    U = np.zeros((2, 2), complex); Tr = np.zeros((2, 2), complex)
    for c, i in enumerate(idx):
        q = w[i]; v = V[:2, i]
        U[:, c] = v
        Tr[0, c] = -q * v[0] + 1j * v[1]                         # sigma_12/mu
        Tr[1, c] = (kap - 2) * 1j * v[0] - kap * q * v[1]        # sigma_22/mu
    return Tr @ np.linalg.inv(U)


# ---------------------------------------------------------------------------
# Rayleigh wave speed: det M(i w) = 0, 0 < w < 1
def rayleigh(r):
    # det M = M11 M22 - M12 M21 = M11 M22 - m12^2   (M12 = i m12, M21 = -i m12)
    def detM2(w):
        M = M_closed(mp.mpc(0, w), r)
        return mp.re(M["M11"] * M["M22"] - M["M12_over_i"] ** 2)
    ws = [mp.mpf(i) / 200 for i in range(1, 200)]
    vals = [detM2(w) for w in ws]
    roots = []
    for i in range(len(ws) - 1):
        if vals[i] * vals[i + 1] < 0:
            roots.append(mp.findroot(detM2, (ws[i], ws[i + 1]), solver="anderson"))
    return roots


# ---------------------------------------------------------------------------
# numerical inverse Laplace transforms
def inv_talbot(F, T):
    deg = max(60, int(6 * T) + 60)
    with mp.workdps(max(DPS, deg + 20)):
        return mp.invertlaplace(F, T, method="talbot", degree=deg)


def inv_dehoog(F, T):
    with mp.workdps(80):      # mpmath's de Hoog default degree scales with dps; 40 digits is too few at T = 40
        return mp.invertlaplace(F, T, method="dehoog")


# independent method: causal real kernel from its spectrum on the imaginary axis.
# For w > 1/r, Re H_hat_diag(iw) = 0 and Im h12_hat(iw) = 0 exactly, so integrals are finite-range.
def spec(name, w, r):
    w = mp.mpf(w)
    a = mp.sqrt(1 - r**2 * w**2) if w < 1 / r else 1j * mp.sqrt(r**2 * w**2 - 1)
    b = mp.sqrt(1 - w**2) if w < 1 else 1j * mp.sqrt(w**2 - 1)
    p = mp.mpc(0, w)
    D = 1 + r**2 + r**2 * p**2
    q = (1 + a * b) / D
    if name == "M11":
        return p - a * q
    if name == "M22":
        return p / r - b * q
    h = 1 / r - q                      # h12_hat
    return h if name == "M12_over_i" else -h


def quad_pts(r, T):
    wmax = 1 / r
    n = max(2, int(mp.ceil(wmax * T / mp.pi)) + 1)
    pts = sorted(set([mp.mpf(0), mp.mpf(1), wmax] + [wmax * i / n for i in range(1, n)]))
    return pts


def H_branchcut(name, T, r):
    T = mp.mpf(T)
    pts = quad_pts(r, T)
    if name in ("M11", "M22"):
        return 2 / mp.pi * mp.quad(lambda w: mp.re(spec(name, w, r)) * mp.cos(w * T), pts)
    return -2 / mp.pi * mp.quad(lambda w: mp.im(spec(name, w, r)) * mp.sin(w * T), pts)


def G_branchcut(name, T, r, Hh0):
    # G(T) = H_hat(0) - int_0^T H
    T = mp.mpf(T)
    pts = quad_pts(r, T)
    if name in ("M11", "M22"):
        I = 2 / mp.pi * mp.quad(lambda w: mp.re(spec(name, w, r)) * mp.sin(w * T) / w, pts)
    else:
        I = -2 / mp.pi * mp.quad(lambda w: mp.im(spec(name, w, r)) * (1 - mp.cos(w * T)) / w, pts)
    return Hh0 - I


# ---------------------------------------------------------------------------
out = {
    "description": ("2D plane-strain half-space x2>0, u_j(x1,0,t)=D_j(t)exp(i k x1), S_j = sigma_2j on x2=0; "
                    "S_hat = mu k M(p) D_hat, p = s/(k c_s), r = c_s/c_p, T = k c_s t. "
                    "M = -diag(p, p/r) + M_inf + H_hat(p); H = L^-1[H_hat]; G(T) = int_T^inf H. "
                    "Keys *_over_i are coefficients of the imaginary unit: X12 = i*X12_over_i, X21 = i*X21_over_i = -X12."),
    "closed_forms": {
        "a": "sqrt(1 + r^2 p^2)", "b": "sqrt(1 + p^2)", "Delta": "1 + r^2 + r^2 p^2 = 1 + r^2 b^2",
        "M11": "-a (1 + a b) / Delta", "M22": "-b (1 + a b) / Delta",
        "M12": "i [2 - (1 + a b)/Delta]", "M21": "-M12",
        "equivalent_unrationalised": "M11 = a p^2/(1-ab), M22 = b p^2/(1-ab), M12 = -M21 = i(1 + b^2 - 2ab)/(1-ab)",
        "det_M": "((2+p^2)^2 - 4ab)/(1 - ab)",
        "M0": "M11 = M22 = -2/(1+r^2) = -4(1-nu)/(3-4nu);  M12 = -M21 = 2i r^2/(1+r^2) = 2i(1-2nu)/(3-4nu)",
        "M_inf": "[[0, i(2-1/r)], [-i(2-1/r), 0]]",
        "large_p": "M11 = -p - (2-r)/(2r p) + O(p^-3); M22 = -p/r - (2r-1)/(2 r^3 p) + O(p^-3); "
                   "M12 = i(2-1/r) + i (1-r)^2/(2 r^3 p^2) + O(p^-4)",
        "H0plus": "H11(0+) = -(2-r)/(2r); H22(0+) = -(2r-1)/(2r^3); H12(0+) = H21(0+) = 0, H12_over_i(T) ~ (1-r)^2/(2r^3) T",
    },
    "T": T_LIST,
    "results": {},
}
log = sys.stderr

# sanity check of the inversion machinery on a known pair
kp = {}
for T in T_LIST:
    F = lambda p: mp.sqrt(p + 1j) * mp.sqrt(p - 1j) - p
    ex = mp.besselj(1, T) / T
    kp[str(T)] = {"talbot_err": float(abs(inv_talbot(F, T) - ex)), "dehoog_err": float(abs(inv_dehoog(F, T) - ex))}
out["check_known_pair_sqrt(1+p^2)-p_vs_J1(T)/T"] = kp
print("known pair done", kp, file=log)

for nu in NU_LIST:
    r = r_of_nu(nu)
    res = {"nu": nu, "r": float(r), "r2": float(r**2)}
    chk = {}
    # --- M closed form vs raw potential form vs independent Navier eigen-solution
    test_ps = [0.3, 1.7, 5.0, 0.4 + 2.5j, 2 + 0.7j, 0.05 + 1.3j, 1e-3 + 0.2j]
    err_raw = 0.0; err_nav = 0.0
    for pp in test_ps:
        Mc = M_closed(mp.mpc(pp), r); Mr = M_potential_raw(mp.mpc(pp), r)
        Mn = M_navier_numeric(pp, nu)
        for key, (i, j, fac) in {"M11": (0, 0, 1), "M22": (1, 1, 1), "M12_over_i": (0, 1, 1j), "M21_over_i": (1, 0, 1j)}.items():
            err_raw = max(err_raw, float(abs(Mc[key] - Mr[key])))
            err_nav = max(err_nav, abs(complex(Mc[key]) * fac - Mn[i, j]))
    chk["max_abs_diff_closed_vs_unrationalised"] = err_raw
    chk["max_abs_diff_closed_vs_numpy_navier_eigensolution"] = err_nav
    # --- static limit
    M0 = M0_closed(r)
    Mpsmall = M_closed(mp.mpf("1e-20"), r)
    chk["max_abs_diff_M(1e-20)_vs_M0_closed"] = float(max(abs(Mpsmall[kk] - M0[kk]) for kk in KERNELS))
    # classical static: normal pressure P cos(kx) (traction +P e2 applied on x2=0 into the body, sigma22 = -P):
    # u2 = (1-nu) P/(mu k) cos kx,  u1 = -(1-2nu) P/(2 mu k) sin kx   (Johnson, Contact Mechanics, sec. 2.x)
    nuq = mp.mpf(nu)
    D2 = (1 - nuq); D1 = 1j * (1 - 2 * nuq) / 2      # for P = mu k = 1, complex amplitudes of exp(ikx)
    S1 = M0["M11"] * D1 + 1j * M0["M12_over_i"] * D2
    S2 = 1j * M0["M21_over_i"] * D1 + M0["M22"] * D2
    chk["static_classical_sinusoidal_load"] = {
        "S1_should_be_0": float(abs(S1)), "S2_should_be_-1": complex(S2).real, "S2_imag": complex(S2).imag,
        "tangential/normal_ratio_from_M0": float(M0["M12_over_i"] / -M0["M11"]),
        "classical_(1-2nu)/(2(1-nu))": float((1 - 2 * nuq) / (2 * (1 - nuq))),
    }
    # --- large-p limits
    P = mp.mpf(10) ** 12
    with mp.workdps(80):
        Ml = M_closed(mp.mpf(10) ** 12, r)
        chk["M11/(-p)_at_p=1e12"] = float(mp.re(Ml["M11"] / (-P)))
        chk["M22/(-p/r)_at_p=1e12"] = float(mp.re(Ml["M22"] / (-P / r)))
        chk["M12_over_i(1e12)-(2-1/r)"] = float(mp.re(Ml["M12_over_i"] - (2 - 1 / r)))
        h0p_num = {kk: P * Hhat(kk, P, r) for kk in KERNELS}
    H0p = H0plus_closed(r)
    chk["max_abs_diff_pHhat(p=1e12)_vs_H0plus_closed"] = float(max(abs(h0p_num[kk] - H0p[kk]) for kk in KERNELS))
    with mp.workdps(80):
        chk["p^2*h12hat(p=1e12)"] = float(mp.re(P**2 * Hhat("M12_over_i", P, r)))
    chk["(1-r)^2/(2r^3)"] = float(H0plus_slope_offdiag(r))
    # --- Rayleigh
    roots = rayleigh(r)
    res["cR_over_cs"] = [float(x) for x in roots]
    chk["rayleigh_roots_in_(0,1)"] = len(roots)
    if nu == 0.25:
        chk["cR_exact_nu0.25_sqrt(2-2/sqrt3)"] = float(mp.sqrt(2 - 2 / mp.sqrt(3)))
    chk["cR_Viktorov_approx_(0.87+1.12nu)/(1+nu)"] = (0.87 + 1.12 * nu) / (1 + nu)
    chk["classical_Rayleigh_fn_(2-w^2)^2-4sqrt(1-r2w2)sqrt(1-w2)_at_root"] = float(
        (2 - roots[0]**2)**2 - 4 * mp.sqrt(1 - r**2 * roots[0]**2) * mp.sqrt(1 - roots[0]**2))

    Hh0 = {kk: M0[kk] - Minf(r)[kk] for kk in KERNELS}
    res["M0"] = {kk: float(M0[kk]) for kk in KERNELS}
    res["M_inf"] = {kk: float(Minf(r)[kk]) for kk in KERNELS}
    res["radiation_damping_coeffs"] = {"M11": -1.0, "M22": float(-1 / r)}
    res["Hhat0=G0"] = {HN[kk]: float(Hh0[kk]) for kk in KERNELS}
    res["H0plus"] = {HN[kk]: float(H0p[kk]) for kk in KERNELS}
    res["H12_over_i_small_T_slope"] = float(H0plus_slope_offdiag(r))
    # off-diagonal Hhat(0) via Kramers-Kronig-type integral: h12hat(0) = -(2/pi) int Im h12(iw)/w dw
    kk0 = -2 / mp.pi * mp.quad(lambda w: mp.im(spec("M12_over_i", w, r)) / w, [0, 1, 1 / r])
    chk["h12hat(0)_via_-(2/pi)int_Im/w_minus_closed"] = float(kk0 - Hh0["M12_over_i"])

    tables = {}
    disc = {}
    for kk in KERNELS:
        Fh = (lambda kk_: (lambda p: Hhat(kk_, p, r)))(kk)
        Fg = (lambda kk_: (lambda p: (Hh0[kk_] - Hhat(kk_, p, r)) / p))(kk)
        th, tg = {}, {}
        dmax = {"H_talbot_vs_dehoog": 0.0, "H_talbot_vs_branchcut": 0.0,
                "G_talbot_vs_dehoog": 0.0, "G_talbot_vs_branchcut": 0.0}
        for T in T_LIST:
            h_t = inv_talbot(Fh, T); h_d = inv_dehoog(Fh, T); h_b = H_branchcut(kk, T, r)
            g_t = inv_talbot(Fg, T); g_d = inv_dehoog(Fg, T); g_b = G_branchcut(kk, T, r, Hh0[kk])
            th[str(T)] = float(mp.re(h_t)); tg[str(T)] = float(mp.re(g_t))
            dmax["H_talbot_vs_dehoog"] = max(dmax["H_talbot_vs_dehoog"], float(abs(h_t - h_d)))
            dmax["H_talbot_vs_branchcut"] = max(dmax["H_talbot_vs_branchcut"], float(abs(h_t - h_b)))
            dmax["G_talbot_vs_dehoog"] = max(dmax["G_talbot_vs_dehoog"], float(abs(g_t - g_d)))
            dmax["G_talbot_vs_branchcut"] = max(dmax["G_talbot_vs_branchcut"], float(abs(g_t - g_b)))
        tables[HN[kk]] = th; tables[GN[kk]] = tg
        disc[HN[kk] + "/" + GN[kk]] = dmax
        print(nu, kk, dmax, round(time.time() - t_start, 1), file=log)
    chk["max_abs_discrepancy_between_inversion_methods"] = disc
    res["tables"] = tables
    res["checks"] = chk
    out["results"]["nu=%g" % nu] = res

out["runtime_s"] = round(time.time() - t_start, 1)
json.dump(out, sys.stdout, indent=1)
print()
