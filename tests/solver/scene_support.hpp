// The paper's scene (Kammer et al. 2014, Sec. 2) at a given mesh density and L, and the
// quantities the scene tests compare with the paper (Sec. 2-3;
// docs/physics.md "The paper's published values").
#pragma once

#include "verification_support.hpp"

#include "solver/interface/nucleation.hpp"
#include "solver/simulation.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront::verification {

inline SimulationParams paper_scene(double nodes_per_meter, double L, int threads = 2) {
  SimulationParams p; // every default is the paper's scene
  p.geometry.nodes_per_meter = nodes_per_meter;
  p.friction.L = L;
  p.threads = threads;
  p.probes.arrival_x1 = 6.0;  // the paper quotes the arrival at x1 = 6 m (Sec. 3)
  p.probes.spectrum_x1 = 6.0; // and the slip velocity there
  return p;
}

// Front arrival time at a node position x1 (NaN if it never slipped or no node is there).
inline double arrival_at(const RunResult& r, double x1) {
  for (std::size_t i = 0; i < r.front.x1.size(); ++i)
    if (std::abs(r.front.x1[i] - x1) < 1e-9) return r.front.arrival_time[i];
  return NAN;
}

struct SceneSummary {
  double peak_v_at_probe = 0;     // max |V| at probes.spectrum_x1 (6 m) [m/s]
  double peak_time_at_probe = 0;  // when [s]
  double supershear_fraction = 0; // of the nodes in [patch end, 10 m] with c_s < V_r < c_p
  double vr_start = NAN;          // V_r just after the nucleation patch (mean over 1 m)
  double vr_end = NAN;            // V_r at x1 = 9..10 m (mean)
};

inline SceneSummary summarise(const SimulationParams& p, const RunResult& r) {
  SceneSummary s;
  for (std::size_t k = 0; k < r.probes.time.size(); ++k) {
    const double v = std::abs(r.probes.slip_velocity_spectrum[k]);
    if (v > s.peak_v_at_probe) s.peak_v_at_probe = v, s.peak_time_at_probe = r.probes.time[k];
  }
  const double patch_end = nucleation_patch(p.nucleation).hi;
  const double cs = p.material.s_wave_speed(), cp = p.material.p_wave_speed();
  int n = 0, super = 0, n_start = 0, n_end = 0;
  double sum_start = 0, sum_end = 0;
  for (std::size_t i = 0; i < r.front.x1.size(); ++i) {
    const double x = r.front.x1[i], vr = r.front.rupture_speed[i];
    if (x < patch_end || x > 10.0) continue;
    ++n;
    if (vr > cs && vr < cp) ++super;
    if (std::isnan(vr)) continue;
    if (x <= patch_end + 1.0) sum_start += vr, ++n_start;
    if (x >= 9.0) sum_end += vr, ++n_end;
  }
  s.supershear_fraction = n > 0 ? double(super) / n : 0.0;
  if (n_start) s.vr_start = sum_start / n_start;
  if (n_end) s.vr_end = sum_end / n_end;
  return s;
}

} // namespace slipfront::verification
