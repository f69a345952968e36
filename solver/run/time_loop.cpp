#include "solver/run/time_loop.hpp"

#include "solver/run/arrest_rule.hpp"
#include "solver/run/critical_length_estimate.hpp"
#include "solver/run/divergence_check.hpp"
#include "solver/run/energy_recorder.hpp"
#include "solver/run/front_metrics.hpp"
#include "solver/run/front_tracker.hpp"
#include "solver/run/interface_sampler.hpp"
#include "solver/run/probe_recorder.hpp"
#include "solver/run/progress_reporter.hpp"
#include "solver/thread_team.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slipfront {

namespace {

bool cancel_requested(const RunHooks& hooks) {
  return hooks.cancel && hooks.cancel->load(std::memory_order_relaxed);
}

} // namespace

RunResult run_time_loop(RuptureMethod& method, const SimulationParams& params,
                        const RunHooks& hooks, std::chrono::steady_clock::time_point started) {
  FloatModeGuard float_mode;
  RunResult result;
  result.mesh = method.mesh_info();
  Metrics& m = result.metrics;
  const double dt = method.dt();
  m.front_threshold = params.probes.front_threshold;
  m.dt = dt;
  const long total_steps = long(std::ceil(params.time.duration / dt - 1e-9));
  const std::vector<double>& x1 = method.interface().x1;

  ProbeRecorder probes(params.probes, params.geometry.x_min, result.mesh.dx, x1);
  InterfaceSampler sampler(hooks.sink, params.output, dt, total_steps, x1);
  EnergyRecorder energy(dt);
  DivergenceCheck divergence(params);
  FrontTracker front(result.mesh.nx, params.probes.front_threshold);
  ArrestRule arrest(params);
  ProgressReporter progress(hooks, params.time.duration, dt, total_steps, started);

  // What the loop does after step n with the method's interface (and energy) of that step;
  // true: the run stops there.
  auto after_step = [&](long n, const InterfaceFields& f, const EnergyBalance* e) {
    const double t_n = n * dt;
    front.update(f.half_velocity, t_n + 0.5 * dt, dt);
    divergence.check(f);
    probes.record(f, t_n);
    if (e) {
      energy.record(*e, t_n);
      divergence.check_energy(*e);
    }
    sampler.record(f, n, t_n);
    if (divergence.diverged()) {
      m.outcome = Outcome::diverged;
      m.message = divergence.message(t_n, n);
      return true;
    }
    if (arrest.update(t_n, front.last_new_arrival())) return true; // stop_on_arrest
    progress.after_step(n);
    return false;
  };

  // The method takes up to block_steps() steps at once (FE: one trip over the mesh for
  // several steps); the loop then reads them one by one, in order, as if stepped singly. A
  // stop inside a block leaves the later steps of that block unread: the run ends at the
  // same step with the same records.
  const int block = std::max(1, method.block_steps());
  std::vector<bool> energy_steps;
  long n = 0;
  bool stopped = false;
  auto cancelled = [&] { // checked before every step, also inside a block
    if (!cancel_requested(hooks)) return false;
    result.cancelled = true;
    m.message = "cancelled at t = " + std::to_string(n * dt) + " s";
    return true;
  };
  while (n < total_steps && !stopped && !cancelled()) {
    const int count = int(std::min<long>(block, total_steps - n));
    energy_steps.assign(count, false);
    for (int k = 0; k < count; ++k)
      energy_steps[k] = energy.due(n + k);
    method.step_block(energy_steps);
    for (int k = 0; k < count && !stopped; ++k) {
      if (k > 0 && cancelled()) {
        stopped = true;
        break;
      }
      stopped = after_step(n, method.interface_after(k),
                           energy_steps[k] ? &method.energy_after(k) : nullptr);
      ++n;
    }
  }

  m.steps = n;
  m.simulated_time = n * dt;
  m.max_slip_velocity = divergence.max_slip_velocity();
  if (m.outcome != Outcome::diverged)
    m.outcome = arrest.arrested() ? Outcome::arrested : Outcome::running_at_end;
  result.probes = probes.take();
  result.energy = energy.take();
  derive_front_metrics(params, result.mesh.dx, front.arrival(), result.front, m);
  derive_spectral_estimate(params, result.front, result.probes, result.mesh.dx, dt, m);
  m.energy_error = energy_balance_error(result.energy);
  for (std::string& warning : method.end_warnings(m.simulated_time))
    m.warnings.push_back(std::move(warning));
  m.wall_time_s = progress.wall_seconds();
  progress.final_report(n, m.simulated_time, m.wall_time_s);
  return result;
}

} // namespace slipfront
