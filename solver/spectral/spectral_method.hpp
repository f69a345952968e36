// The elastic half-space x2 > 0 on the rigid plane by the spectral boundary-integral method
// (Geubelle & Rice 1995; Breitenfeld & Geubelle 1998; Lapusta et al. 2000 for the velocity
// form; Cochard & Rice 2000 used it for this friction law). Only the interface is
// discretised: N = width / dx nodes, periodic in x1. See docs/spectral-bi.md.
//
// At every interface node the traction on the solid's boundary is (perturbation form)
//     sigma_2j = sigma0_j + f_j - eta_j V_j,   eta_1 = rho c_s, eta_2 = rho c_p,
// with sigma0 = (tau0_i, sigma0_i) the node's initial stresses (interface_parameters.hpp) and
// f_j the elastodynamic memory, computed mode by mode in Fourier space from the slip and
// opening histories (half_space_kernels.hpp, mode_memory.hpp). The plane's contact and
// friction force C_j and the interface loads L_j balance it: -sigma_2j dx = C_j + L_j, so
//     V_j = V_free_j + C_j / (eta_j dx),   V_free_j = (sigma0_j + f_j + L_j / dx) / eta_j,
// which is the FE interface step with the node mass replaced by eta_j dx dt: the same law
// (interface_law.hpp) resolves contact, opening and friction.
//
// Time stepping: V is constant over each step, D^{n+1} = D^n + dt V^{n+1/2}; the balance
// holds at t_{n+1/2}. The known part of f (the history and the static term on D^n) is
// computed once a step; the part of the current interval is predicted with V^{n-1/2} and
// corrected with the solved V^{n+1/2} (`corrector_passes`).
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/interface/interface_law.hpp"
#include "solver/interface/interface_parameters.hpp"
#include "solver/interface/split_node.hpp"
#include "solver/method_entry.hpp"
#include "solver/params.hpp"
#include "solver/run_work.hpp"
#include "solver/rupture_method.hpp"
#include "solver/spectral/half_space.hpp"
#include "solver/thread_team.hpp"

#include <memory>
#include <vector>

namespace slipfront::spectral {

class SpectralMethod : public RuptureMethod {
public:
  explicit SpectralMethod(const SimulationParams& params, int threads = 1);

  void step(bool compute_energy) override;
  double dt() const override { return dt_; }
  const InterfaceFields& interface() const override { return iface_; }
  const EnergyBalance& energy() const override { return energy_; }
  MeshInfo mesh_info() const override;
  // Said at the end of the run: plain Coulomb friction at time_step_factor >= 0.4 grows a
  // mesh-scale mode that the continuum does not have (docs/verification.md, BI findings);
  // between two different solids it is ill-posed (the continuum's growth rate ~ 1/dx).
  std::vector<std::string> end_warnings(double simulated_time) const override;

  int nx() const { return nx_; }
  double dx() const { return dx_; }
  double time() const { return step_ * dt_; }
  const ModeMemory& memory() const { return upper_.memory(); }

  // Time step of the method: beta dx / c_s, with the larger c_s of two elastic solids (each
  // side's own c_s dt / dx then is at most beta: docs/spectral-bi.md "Two half-spaces").
  static double time_step(const SimulationParams& params);
  static double reference_shear_speed(const SimulationParams& params); // the c_s of dt
  // c_s dt / dx of a half-space of material `side`.
  static double side_step_factor(const SimulationParams& params, const Material& side);
  // The elastic solids of the run: the upper one, and the lower one if it is elastic.
  static std::vector<const Material*> solids(const SimulationParams& params);
  // Kernel table length needed for these parameters (scaled time), of the upper solid or
  // of the solid `side`.
  static double kernel_span(const SimulationParams& params);
  static double kernel_span(const SimulationParams& params, const Material& side);
  // Steps of a run that goes to `duration`, in double (may be inf for an impossible job).
  static double step_bound(const SimulationParams& params);
  // The same as an integer; throws std::invalid_argument above max_run_steps
  // (solver/step_count.hpp), which the job validation never lets through.
  static long max_steps(const SimulationParams& params);
  // Bytes the run will hold (memory of the modes, interface fields, probe records).
  static double estimated_memory_bytes(const SimulationParams& params);
  // The work of a run up to simulated time `until` (solver/run_work.hpp): each mode's history
  // convolved every step, min(n, its memory length) lags at step n, and the transforms.
  static RunWork estimated_work(const SimulationParams& params, double until);

private:
  void solve_nodes(const std::vector<double>& slip_speed);
  void record_interface();
  double slip_rate(int i) const;     // V^{n-1/2}, upper minus lower, at node i
  double new_slip_rate(int i) const; // V^{n+1/2}

  SimulationParams params_;
  int nx_;
  double dx_, dt_;
  ThreadTeam team_;
  HalfSpace upper_;                  // the solid x2 > 0
  std::unique_ptr<HalfSpace> lower_; // the solid x2 < 0 in its mirrored frame (none: rigid)
  InterfaceNodeConstants node_;
  InterfaceParameters parameters_;      // tau0, sigma0 and friction values per node
  std::vector<FrictionState> friction_; // the friction state of each node after the last step

  std::vector<double> load1_, load2_; // interface loads at t_{n+1/2} [Pa]
  std::vector<double> slip_speed_;    // |V| entering the strength update (scratch)
  std::vector<InterfaceNodeStep> solved_;

  InterfaceFields iface_;
  EnergyBalance energy_;
  long step_ = 0;
};

// The method's entry in the registry of methods (solver/methods.hpp; spectral_entry.cpp).
const MethodEntry& method_entry();

} // namespace slipfront::spectral
