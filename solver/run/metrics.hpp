// Derived metrics of a run (SPEC §2). How each one is computed: docs/metrics.md.
#pragma once

#include "solver/params.hpp"
#include "solver/run/records.hpp"

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

// Front speed from arrival times, by a centred difference of x1 against t_front over
// a window of +- half_window metres (nodes without arrival are skipped).
std::vector<double> rupture_speed_profile(const std::vector<double>& x1,
                                          const std::vector<double>& arrival_time,
                                          double half_window);

// The filter law of the paper (eq. 6): A/A0 = 1/sqrt(1 + (2 pi f L / (V* + |V|))^2).
double filter_amplitude_ratio(double frequency, double L, double v_star, double slip_velocity);

// Largest L for which A/A0 >= ratio at frequency f (inverse of the filter law).
double filter_critical_length(double frequency, double v_star, double slip_velocity,
                              double ratio = 0.98);

// The ruptured stretch of the interface: the run of consecutive nodes (periodic in x1) that
// slipped and that contains the nucleation patch's slipped nodes. Positions are unwrapped
// so that left <= right even when the stretch crosses the periodic seam.
struct RupturedStretch {
  bool ruptured = false; // a node outside the nucleation patch slipped
  bool any_slip = false;
  double left = 0, right = 0; // smallest and largest x1 reached [m]
  std::vector<int> nodes;     // node indices from left to right
};
RupturedStretch ruptured_stretch(const std::vector<double>& x1,
                                 const std::vector<double>& arrival_time, double patch_lo,
                                 double patch_hi, double width);

// Frequency content of a strength record tau_s(t) (uniform steps): the frequency below which
// `fraction` of the power of the detrended, Hann-windowed signal lies (DC excluded).
double spectral_cutoff_frequency(const std::vector<double>& signal, double dt,
                                 double fraction = 0.99);

// The node nearest to x1 on the periodic line of nx nodes x_min + i dx.
int nearest_node(double x1, double x_min, double dx, int nx);

// Value at x1 of a nodal quantity, linear between the two nodes around x1 (NaN if either is).
double interpolate_nodal(const std::vector<double>& values, double x1, double x_min, double dx);

// The front profile (node positions, arrival times, V_r) and the front metrics of a run
// from the arrival times (NaN where the front never came): arrest position, propagation
// distance, arrival at probes.arrival_x1, max and mean V_r outside the nucleation patch;
// sets the outcome to no_rupture if nothing outside the patch slipped (unless diverged).
void derive_front_metrics(const SimulationParams& p, double dx,
                          const std::vector<double>& arrival_time, FrontProfile& front, Metrics& m);

// The spectral estimate of L_c (paper eq. 6) from the strength record at the spectrum probe,
// from half a second before the front arrives there to the end (NaN when undefined).
void derive_spectral_estimate(const SimulationParams& p, const FrontProfile& front,
                              const ProbeRecords& probes, double dx, double dt, Metrics& m);

// Energy balance at the last record: |E - (W - D)| / max(|W|, |E|), E = kinetic + strain
// (E(0) = 0); 0 without records.
double energy_balance_error(const EnergyRecords& energy);

} // namespace slipfront
