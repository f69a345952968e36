// The metrics of a run (docs/metrics.md): the outcome, the slip front's profile and the
// numbers derived from the records. The derivations: front_metrics.hpp,
// critical_length_estimate.hpp, energy_recorder.hpp (energy_balance_error).
#pragma once

#include <string>
#include <vector>

namespace slipfront {

enum class Outcome { arrested, running_at_end, no_rupture, diverged };
const char* to_string(Outcome outcome);

// The slip front: per interface node, the first time |V| exceeded the threshold
// (NaN if never), and the front speed V_r(x1) = d x1 / d t_front (NaN where undefined).
struct FrontProfile {
  std::vector<double> x1;
  std::vector<double> arrival_time;
  std::vector<double> rupture_speed;
};

struct Metrics {
  double front_threshold = 1e-6;
  double arrest_position = 0.0;       // NaN if no rupture
  double propagation_distance = 0.0;  // 0 if no rupture
  double arrival_time_at_probe = 0.0; // NaN if the front never reached the probe
  double probe_x1 = 0.0;
  double max_rupture_speed = 0.0;  // NaN if no rupture
  double mean_rupture_speed = 0.0; // NaN if no rupture
  double max_slip_velocity = 0.0;
  Outcome outcome = Outcome::no_rupture;
  double energy_error = 0.0;
  // Spectral estimate of the critical length (paper eq. 6, see docs/metrics.md).
  double spectral_frequency = 0.0;       // f used [Hz]
  double spectral_velocity = 0.0;        // |V| used [m/s]
  double spectral_critical_length = 0.0; // largest L with A/A0 >= 0.98 at that f and |V|
  // Cost.
  double wall_time_s = 0.0;
  long steps = 0;
  double dt = 0.0;
  double simulated_time = 0.0;
  std::vector<std::string> warnings;
  std::string message; // why the run diverged or stopped, when it did
};

} // namespace slipfront
