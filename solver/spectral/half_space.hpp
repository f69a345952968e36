// One elastic half-space of the spectral boundary-integral method, in its own frame: the
// solid lies above its boundary (x2' > 0), periodic in x1 with N nodes (docs/spectral-bi.md).
// The rigid-plane scene has one (the upper solid); two deformable solids have two, the lower
// one seen in its mirrored frame (x2' = -x2: u'_1 = u_1, u'_2 = -u_2), where it is an upper
// half-space like the other (docs/spectral-bi.md "Two half-spaces").
//
// At every node the traction on its boundary is (perturbation form)
//     sigma'_2j = sigma0'_j + f_j - eta_j V_j,   eta_1 = rho c_s, eta_2 = rho c_p,
// with f_j the elastodynamic memory of the boundary's motion, computed mode by mode in
// Fourier space (half_space_kernels.hpp, mode_memory.hpp) with this solid's kernels (its
// Poisson ratio), mu |k|, c_s and history. The caller solves the nodes for V^{n+1/2}
// (motion().v1_new, v2_new); one step of the half-space is then:
//     sum_history (per team member) -> known_memory_term -> predict (f with V^{n-1/2})
//     -> [correct (f with the solved V^{n+1/2})]... -> finish_step.
#pragma once

#include "solver/params.hpp"
#include "solver/spectral/half_space_kernels.hpp"
#include "solver/spectral/mode_memory.hpp"
#include "solver/spectral/real_fft.hpp"

#include <complex>
#include <memory>
#include <vector>

namespace slipfront::spectral {

// What fixes a half-space's discretisation besides its material.
struct HalfSpaceGrid {
  int nx = 0;                // nodes (periodic)
  double width = 0;          // [m]
  double dt = 0;             // [s]
  double memory_periods = 8; // q: mode k keeps q periods 2 pi / (|k| c_s) of its history
  long max_steps = 0;        // the run's steps at most (bounds the stored history)
  double kernel_span = 0;    // kernel table length in scaled time T = |k| c_s t
  int parts = 1;             // mode ranges for a thread team of this size
};

class HalfSpace {
public:
  HalfSpace(const Material& material, const HalfSpaceGrid& grid);

  // The boundary's motion at the nodes, in this half-space's frame.
  struct Motion {
    std::vector<double> d1, d2;         // D^n
    std::vector<double> v1, v2;         // V^{n-1/2}
    std::vector<double> v1_new, v2_new; // V^{n+1/2}, set by the caller's node solve
  };
  Motion& motion() { return motion_; }
  const Motion& motion() const { return motion_; }

  // f at the nodes at t_{n+1/2} after predict() or correct().
  const std::vector<double>& f1() const { return f1_; }
  const std::vector<double>& f2() const { return f2_; }

  double eta1() const { return eta1_; } // radiation damping rho c_s
  double eta2() const { return eta2_; } // rho c_p
  const ModeMemory& memory() const { return *memory_; }
  const HalfSpaceKernels& kernels() const { return kernels_; }

  // Once a step, in this order: the history sums of team member `member`'s modes (may run
  // on the team), then the known part of f_hat (history and static term on D^n).
  void sum_history(int member);
  void known_memory_term();
  // f at the nodes with this interval's V predicted by V^{n-1/2} / taken from v_new.
  void predict();
  void correct();
  // V^{n+1/2} into the memory, D^{n+1} = D^n + dt V^{n+1/2}, V^{n-1/2} <- V^{n+1/2}.
  void finish_step();

private:
  using complex = std::complex<double>;
  void add_current_interval(const std::vector<complex>& v1, const std::vector<complex>& v2);
  void forward_new_velocity();

  int nx_, modes_;
  double dt_;
  double eta1_, eta2_;
  HalfSpaceKernels kernels_;
  std::unique_ptr<ModeMemory> memory_;
  RealFft fft_;
  Motion motion_;

  std::vector<double> mu_k_;                     // mu |k_n|
  std::vector<complex> d1_hat_, d2_hat_;         // D^n in Fourier space
  std::vector<complex> v1_hat_, v2_hat_;         // V^{n-1/2} in Fourier space
  std::vector<complex> v1_hat_new_, v2_hat_new_; // V^{n+1/2} in Fourier space (scratch)
  std::vector<complex> f1_known_, f2_known_;     // known part of f_hat at t_{n+1/2}
  std::vector<complex> f1_hat_, f2_hat_;         // scratch
  std::vector<ModeHistorySums> sums_;
  std::vector<double> f1_, f2_; // f at the nodes
  std::vector<int> split_;      // mode ranges per team member
};

} // namespace slipfront::spectral
