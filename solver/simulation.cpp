// The time loop of one run: steps the model, follows the slip front, samples the
// interface, reports progress, stops on cancel, divergence or arrest, and derives the
// metrics (docs/metrics.md).
#include "solver/simulation.hpp"

#include "solver/mesh_size.hpp"
#include "solver/nucleation.hpp"
#include "solver/rupture_model.hpp"
#include "solver/thread_team.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <thread>

namespace slipfront {

double resolved_height(const SimulationParams& params) {
  return mesh_size(params).height;
}

double estimated_memory_bytes(const SimulationParams& params) {
  const MeshSize m = mesh_size(params);
  const double nodes = double(m.nx + 2) * m.ny;
  const double fields = 4.0 * 8.0 * nodes;    // u and v, two components each
  const double interface = 24.0 * 8.0 * m.nx; // interface fields, front, buffers
  // Probe records (4 doubles a step) for the longest possible run; the stable step of a
  // regular Q4 mesh is above 0.5 dx / c_p.
  const double steps = params.time.duration /
                       (params.time.safety_factor * 0.5 * m.dx / params.material.p_wave_speed());
  const double records = 4.0 * 8.0 * steps;
  const double sample_buffer = 64.0 * 6.0 * 8.0 * m.nx; // a chunk of samples in the writer
  const double baseline = 16.0e6;                       // code, libraries, HDF5 caches
  return fields + interface + records + sample_buffer + baseline;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Follows the slip front: per node, the first time the half-step slip speed crossed the
// threshold, interpolated linearly between the two half steps around the crossing.
class FrontTracker {
public:
  FrontTracker(int nx, double threshold)
      : threshold_(threshold), arrival_(nx, kNaN), previous_(nx, 0.0) {}

  // half_velocity holds v^{n+1/2}; previous_ holds v^{n-1/2}. t_half = t_{n+1/2}.
  void update(const std::vector<double>& half_velocity, double t_half, double dt) {
    for (std::size_t i = 0; i < arrival_.size(); ++i) {
      const double now = std::abs(half_velocity[i]);
      if (std::isnan(arrival_[i]) && now > threshold_) {
        const double before = std::abs(previous_[i]);
        const double s = (threshold_ - before) / (now - before); // in [0, 1)
        // Not before t = 0: the motion starts at t_0 even though v^{-1/2} sits at -dt/2.
        arrival_[i] = std::max(0.0, t_half - dt + std::clamp(s, 0.0, 1.0) * dt);
        last_new_arrival_ = std::max(last_new_arrival_, arrival_[i]);
      }
      previous_[i] = half_velocity[i];
    }
  }
  const std::vector<double>& arrival() const { return arrival_; }
  double last_new_arrival() const { return last_new_arrival_; }

private:
  double threshold_;
  std::vector<double> arrival_, previous_;
  double last_new_arrival_ = -std::numeric_limits<double>::infinity();
};

InterfaceSample make_sample(const InterfaceFields& f, double t, int stride) {
  InterfaceSample s;
  s.time = t;
  for (std::size_t i = 0; i < f.x1.size(); i += stride) {
    s.slip_velocity.push_back(f.velocity[i]);
    s.slip.push_back(f.slip[i]);
    s.shear_traction.push_back(f.shear_traction[i]);
    s.contact_pressure.push_back(f.pressure[i]);
    s.strength.push_back(f.strength[i]);
    s.state.push_back(f.state[i]);
  }
  return s;
}

// Restores the caller's floating-point mode when the run ends, however it ends.
struct FloatModeGuard {
  unsigned saved = set_flush_denormals(true);
  ~FloatModeGuard() { restore_float_mode(saved); }
};

} // namespace

RunResult run_simulation(const SimulationParams& params, const RunHooks& hooks) {
  using clock = std::chrono::steady_clock;
  const auto wall_start = clock::now();
  auto wall_seconds = [&] {
    return std::chrono::duration<double>(clock::now() - wall_start).count();
  };
  FloatModeGuard float_mode;

  const int threads =
      params.threads > 0 ? params.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  RuptureModel model(params);
  ThreadTeam team(threads);

  RunResult result;
  result.mesh = {model.nx(),        model.ny(), model.dx(), model.height(),
                 model.stable_dt(), model.dt(), threads};
  Metrics& m = result.metrics;
  m.front_threshold = params.probes.front_threshold;
  m.dt = model.dt();

  const double dt = model.dt();
  const long total_steps = long(std::ceil(params.time.duration / dt - 1e-9));
  const int sample_every = std::max(1, int(std::lround(params.output.interval / dt)));
  const int stride = std::max(1, params.output.space_stride);
  // The energy balance (a sweep that does not vectorise) is evaluated every 0.05 s of
  // simulated time; energy_error is the balance at the last evaluation.
  const int energy_every = std::max(1, int(std::lround(0.05 / dt)));
  const int nx = model.nx();
  const int probe_arrival =
      nearest_node(params.probes.arrival_x1, params.geometry.x_min, model.dx(), nx);
  const int probe_spectrum =
      nearest_node(params.probes.spectrum_x1, params.geometry.x_min, model.dx(), nx);
  result.probes.arrival_node_x1 = model.interface().x1[probe_arrival];
  result.probes.spectrum_node_x1 = model.interface().x1[probe_spectrum];

  if (hooks.sink) {
    InterfaceLayout layout;
    for (int i = 0; i < nx; i += stride)
      layout.x1.push_back(model.interface().x1[i]);
    layout.expected_samples = total_steps / sample_every + 1;
    layout.sample_interval = sample_every * dt;
    hooks.sink->begin(layout);
  }

  // Divergence: a slip speed far above anything the loads can drive (1000 times the
  // particle velocity that the whole remote load would cause, |tau| / (rho c_s)), or a
  // non-finite value anywhere (checked through the energy sums on sampled steps).
  const Material& mat = params.material;
  const double load_scale =
      std::abs(params.loading.normal_stress) + std::abs(params.loading.shear_stress);
  const double speed_limit = 1000.0 * load_scale / (mat.density * mat.s_wave_speed());
  const double quiet_after =
      params.nucleation.enabled ? nucleation_end_time(params.nucleation) : 0.0;

  FrontTracker front(nx, params.probes.front_threshold);
  double max_coulomb_strength = params.friction.mu * std::abs(params.loading.normal_stress);
  std::string strength_message;
  bool arrested = false;
  double last_progress = -1e9;
  long n = 0;
  for (; n < total_steps; ++n) {
    if (hooks.cancel && hooks.cancel->load(std::memory_order_relaxed)) {
      result.cancelled = true;
      m.message = "cancelled at t = " + std::to_string(n * dt) + " s";
      break;
    }
    const bool sample = n % sample_every == 0;
    const bool energy_step = n % energy_every == 0;
    model.step(team, energy_step);
    const double t_n = n * dt;
    const InterfaceFields& f = model.interface();
    front.update(f.half_velocity, t_n + 0.5 * dt, dt);

    bool finite = true;
    for (int i = 0; i < nx; ++i) {
      const double v = std::abs(f.velocity[i]);
      if (!(v <= speed_limit)) finite = false; // also catches NaN
      m.max_slip_velocity = std::max(m.max_slip_velocity, v);
      max_coulomb_strength = std::max(max_coulomb_strength, params.friction.mu * f.pressure[i]);
    }
    // A stable strength update makes tau_s a convex combination of its start and the mu p
    // of the step (friction.hpp), so it stays within [0, the largest mu p seen, p0
    // included]; leaving that range means the update is unstable
    // even if it stays bounded (explicit Euler with dt (|V| + V*) / L > 2).
    for (int i = 0; i < nx && strength_message.empty(); ++i) {
      const double ts = f.strength[i];
      if (ts < -1e-12 * max_coulomb_strength || ts > (1 + 1e-12) * max_coulomb_strength) {
        char msg[240];
        std::snprintf(
            msg, sizeof msg,
            "frictional strength %.4g Pa at x1 = %.4g m left its physical range [0, %.4g] Pa: "
            "the strength update is unstable",
            ts, f.x1[i], max_coulomb_strength);
        strength_message = msg;
      }
    }
    if (!strength_message.empty()) finite = false;
    result.probes.time.push_back(t_n);
    result.probes.slip_velocity_arrival.push_back(f.velocity[probe_arrival]);
    result.probes.slip_velocity_spectrum.push_back(f.velocity[probe_spectrum]);
    result.probes.strength_spectrum.push_back(f.strength[probe_spectrum]);
    if (energy_step) {
      const EnergyBalance& e = model.energy();
      result.energy.time.push_back(t_n + 0.5 * dt);
      result.energy.kinetic.push_back(e.kinetic);
      result.energy.strain.push_back(e.strain);
      result.energy.external_work.push_back(e.external_work);
      result.energy.dissipated.push_back(e.dissipated);
      if (!std::isfinite(e.kinetic) || !std::isfinite(e.strain)) finite = false;
    }
    if (sample && hooks.sink) hooks.sink->write(make_sample(f, t_n, stride));
    if (!finite) {
      m.outcome = Outcome::diverged;
      char msg[200];
      std::snprintf(msg, sizeof msg, "diverged at t = %.6g s (step %ld): ", t_n, n);
      m.message = msg;
      if (strength_message.empty()) {
        std::snprintf(msg, sizeof msg, "slip speed above %.3g m/s or a non-finite field",
                      speed_limit);
        m.message += msg;
      } else {
        m.message += strength_message;
      }
      ++n;
      break;
    }

    // Arrest: after the nucleation, no node has been reached by the front for a window.
    const double quiet_since = std::max(quiet_after, front.last_new_arrival());
    arrested = t_n - quiet_since >= params.time.arrest_window;
    if (arrested && params.time.stop_on_arrest) {
      ++n;
      break;
    }

    const double wall = wall_seconds();
    if (hooks.on_progress && wall - last_progress >= hooks.progress_interval_s) {
      last_progress = wall;
      Progress pr{(n + 1) * dt,
                  params.time.duration,
                  n + 1,
                  total_steps,
                  double(n + 1) / total_steps,
                  wall,
                  (n + 1) / std::max(wall, 1e-9),
                  0.0};
      pr.eta_s = (total_steps - n - 1) / std::max(pr.steps_per_s, 1e-9);
      hooks.on_progress(pr);
    }
  }

  m.steps = n;
  m.simulated_time = n * dt;
  if (m.outcome != Outcome::diverged)
    m.outcome = arrested ? Outcome::arrested : Outcome::running_at_end;
  derive_front_metrics(params, result.mesh.dx, front.arrival(), result.front, m);
  derive_spectral_estimate(params, result.front, result.probes, result.mesh.dx, dt, m);
  m.energy_error = energy_balance_error(result.energy);

  const double reflection_time = 2.0 * model.height() / mat.p_wave_speed();
  if (m.simulated_time > reflection_time) {
    char msg[300];
    std::snprintf(
        msg, sizeof msg,
        "h = %.4g m is small for this run: a P wave reflected by the top reaches the interface "
        "at t = 2h/c_p = %.4g s, before the run ended at %.4g s%s",
        model.height(), reflection_time, m.simulated_time,
        params.top == TopBoundary::absorbing
            ? " (the absorbing top weakens, but does not remove, the reflection)"
            : "");
    m.warnings.push_back(msg);
  }
  m.wall_time_s = wall_seconds();
  if (hooks.on_progress) {
    Progress pr{m.simulated_time,
                params.time.duration,
                n,
                total_steps,
                double(n) / std::max(total_steps, 1L),
                m.wall_time_s,
                n / std::max(m.wall_time_s, 1e-9),
                0.0};
    hooks.on_progress(pr);
  }
  return result;
}

} // namespace slipfront
