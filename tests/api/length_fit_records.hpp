// Synthetic records for the length-fit tests: a slip pulse under a varying contact
// pressure, the frictional stress integrated from the simplified Prakash-Clifton law (paper
// eq. 1) by RK4 on the continuous inputs with steps far below the law's time scale (an
// integration independent of the fit's own), sampled evenly, with Gaussian noise if asked.
#pragma once

#include "api/length_fit/interface_record.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace slipfront::test {

struct SyntheticEvent {
  double L = 1e-3;      // [m]
  double v_star = 1e-4; // [m/s]
  double mu = 0.6;
  double pressure = 1e6;          // p0 [Pa]
  double peak_speed = 0.05;       // [m/s]
  double onset = 3.0;             // [s] the slip and the pressure change start
  double rise = 0.5;              // [s] rise time of the slip pulse
  double wiggle = 2.0;            // [Hz] frequency of the pressure's oscillation
  double wiggle_amplitude = 0.05; // of p0
  double duration = 10.0;         // [s]
  std::size_t samples = 500;
  double noise = 0.0; // rms noise on the stress, as a fraction of its range while slipping
  unsigned seed = 1;
};

// Smooth 0 -> 1 from the onset over 0.4 s.
inline double ramp_up(const SyntheticEvent& e, double t) {
  const double x = std::clamp((t - e.onset) / 0.4, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

inline double pressure_at(const SyntheticEvent& e, double t) {
  const double s = ramp_up(e, t);
  return e.pressure *
         (1 - 0.2 * s + e.wiggle_amplitude * s * std::sin(2 * std::numbers::pi * e.wiggle * t));
}

inline double speed_at(const SyntheticEvent& e, double t) {
  if (t <= e.onset) return 0.0;
  const double x = (t - e.onset) / e.rise;
  return e.peak_speed * x * std::exp(1 - x);
}

inline api::InterfaceRecord synthetic_record(const SyntheticEvent& e) {
  api::InterfaceRecord r;
  const auto rate = [&](double t, double tau) {
    return -(speed_at(e, t) + e.v_star) / e.L * (tau - e.mu * pressure_at(e, t));
  };
  // RK4 steps of at most a tenth of the law's shortest time scale L / (V_max + V*).
  const double dt = e.duration / double(e.samples - 1);
  const double h_max = 0.1 * e.L / (e.peak_speed + e.v_star);
  const int sub = std::max(1, int(std::ceil(dt / h_max)));
  double tau = e.mu * pressure_at(e, 0.0), t = 0.0;
  std::mt19937 random(e.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double range = 0.25 * e.mu * e.pressure; // about the stress's range while slipping
  for (std::size_t k = 0; k < e.samples; ++k) {
    if (k > 0) {
      const double h = dt / sub;
      for (int i = 0; i < sub; ++i) {
        const double k1 = rate(t, tau), k2 = rate(t + h / 2, tau + h / 2 * k1);
        const double k3 = rate(t + h / 2, tau + h / 2 * k2), k4 = rate(t + h, tau + h * k3);
        tau += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        t += h;
      }
      t = dt * double(k);
    }
    r.time.push_back(t);
    r.slip_rate.push_back(speed_at(e, t));
    r.contact_pressure.push_back(pressure_at(e, t));
    r.frictional_stress.push_back(tau + e.noise * range * gauss(random));
  }
  return r;
}

} // namespace slipfront::test
