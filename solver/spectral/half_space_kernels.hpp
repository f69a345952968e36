// The elastodynamic response of the half-space x2 > 0 to one Fourier mode of its boundary
// motion: the kernels of the spectral boundary-integral method (docs/spectral-bi.md).
//
// For a boundary displacement u_j(x1, 0, t) = D_j(t) e^{i k x1} of a solid at rest for t < 0,
// the stresses sigma_2j(x1, 0, t) = S_j(t) e^{i k x1} follow, in the Laplace domain, from
//     S_1 = mu |k| [ K11(p) D_1 + i sgn(k) K12(p) D_2 ]
//     S_2 = mu |k| [ -i sgn(k) K12(p) D_1 + K22(p) D_2 ]          p = s / (|k| c_s),
// with r = c_s / c_p, a = sqrt(1 + r^2 p^2), b = sqrt(1 + p^2), Q = 1 + r^2 + r^2 p^2:
//     K11 = -a (1 + a b) / Q,   K22 = -b (1 + a b) / Q,   K12 = 2 - (1 + a b) / Q.
// (Potentials phi, psi decaying in x2; the same matrix as Geubelle & Rice 1995 and
// Breitenfeld & Geubelle 1998 for one half-space, written without the 0/0 at p = 0.)
//   p -> infinity: K11 = -p + ..., K22 = -p/r + ...  (radiation damping rho c_s, rho c_p),
//                  K12 -> 2 - 1/r                      (instantaneous coupling);
//   p = 0:         K11 = K22 = -2/(1 + r^2), K12 = 2 r^2/(1 + r^2)   (static half-space).
//
// In the time domain (T = |k| c_s t), with V_j = dD_j/dt, every mode obeys
//     S_1 = -rho c_s V_1 + mu |k| [K11(0) D_1 - (g11 * V_1)] + i mu k [K12(0) D_2 - (g12 * V_2)]
//     S_2 = -rho c_p V_2 + mu |k| [K22(0) D_2 - (g22 * V_2)] - i mu k [K12(0) D_1 - (g12 * V_1)]
// where (g * V)(t) = int_0^t g(|k| c_s t') V(t - t') dt' and g_ij(T) = int_T^inf h_ij, h_ij the
// inverse transform of K_ij minus its radiation and instantaneous parts (the velocity form of
// Lapusta et al. 2000: the static stiffness acts on the current D, the memory on V).
//
// The kernels are finite Fourier integrals: on p = i w the real part of K11, K22 and the
// imaginary part of K12 vanish for w > 1/r, so for T > 0 (causality)
//     h_jj(T) =  (2/pi) int_0^{1/r} Re K_jj(i w) cos(w T) dw
//     h_12(T) = -(2/pi) int_1^{1/r} Im K12(i w) sin(w T) dw
//     g_jj(T) = K_jj(0) - (2/pi) int_0^{1/r} Re K_jj(i w) sin(w T) / w dw
//     g_12(T) = K12(0) - (2 - 1/r) + (2/pi) int_1^{1/r} Im K12(i w) (1 - cos(w T)) / w dw,
// evaluated by Gauss-Legendre quadrature after substitutions that remove the square-root
// endpoints at w = 1 (S wave) and w = 1/r (P wave).
#pragma once

#include <complex>
#include <vector>

namespace slipfront::spectral {

// The three independent entries of the dimensionless Laplace-domain stiffness.
struct ModeStiffness {
  std::complex<double> k11, k22, k12;
};

// K(p) for Re p > 0 (and its limit on the imaginary axis from the right), r = c_s / c_p.
ModeStiffness mode_stiffness(std::complex<double> p, double r);

// K(0): the static stiffness of the half-space.
ModeStiffness static_stiffness(double r);

// The three convolution kernels g11, g22, g12 and their derivatives -h, for one ratio r.
struct KernelValues {
  double g11 = 0, g22 = 0, g12 = 0;
  double h11 = 0, h22 = 0, h12 = 0; // h = -dg/dT
};

class HalfSpaceKernels {
public:
  // Tabulates the kernels on [0, t_max] (scaled time T) for interpolation.
  HalfSpaceKernels(double r, double t_max);

  double r() const { return r_; }
  double t_max() const { return t_max_; }

  // By quadrature (slow: for tests and for building the table).
  KernelValues exact(double T) const;

  // Cubic Hermite interpolation of the table (T in [0, t_max]).
  KernelValues operator()(double T) const;

  // int_{T0}^{T1} g(T) dT for the three kernels (4-point Gauss-Legendre on the interpolant).
  KernelValues integral(double T0, double T1) const;

  // Constants of the velocity form: K(0) and the instantaneous coupling 2 - 1/r.
  double static11() const { return k0_11_; }
  double static22() const { return k0_22_; }
  double static12() const { return k0_12_; }
  double coupling_at_infinity() const { return 2.0 - 1.0 / r_; }

  static constexpr double table_step = 1.0 / 32.0; // Delta T of the table

private:
  struct Node {
    double w, weight;        // abscissa and weight of the w-integral (substitution included)
    double re11, re22, im12; // the integrands' spectral factors at w
  };
  void build_nodes(double t_max);

  double r_, t_max_;
  double k0_11_, k0_22_, k0_12_;
  std::vector<Node> band_; // nodes on [0, 1/r]
  std::vector<KernelValues> table_;
};

} // namespace slipfront::spectral
