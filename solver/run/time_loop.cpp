// The time loop in its five phases (numbered below as in the code):
//   1. set up the observers of the run, one concern each;
//   2. step a block: the method advances up to block_steps() steps at once;
//   3. record each step of the block, in order, as if the steps had been taken singly;
//   4. apply the stop rules (cancel before every step; divergence and arrest after it) and
//      report progress;
//   5. derive the metrics from the records (docs/metrics.md).
#include "solver/run/time_loop.hpp"

#include "solver/interface/nucleation.hpp"
#include "solver/run/arrest_rule.hpp"
#include "solver/run/critical_length_estimate.hpp"
#include "solver/run/divergence_check.hpp"
#include "solver/run/energy_recorder.hpp"
#include "solver/run/front_metrics.hpp"
#include "solver/run/front_tracker.hpp"
#include "solver/run/interface_sampler.hpp"
#include "solver/run/probe_recorder.hpp"
#include "solver/run/progress_reporter.hpp"
#include "solver/run/station_recorder.hpp"
#include "solver/step_count.hpp"
#include "solver/thread_team.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slipfront {

namespace {

// 1. What watches a run. Constructed in this order: the sampler announces the layout to
//    the sink, the progress reporter's clock counts from `started`.
struct Observers {
  ProbeRecorder probes;
  StationRecorder stations;
  InterfaceSampler sampler;
  EnergyRecorder energy;
  DivergenceCheck divergence;
  FrontTracker front;
  ArrestRule arrest;
  ProgressReporter progress;
};

// The nodes of the overstressed patch (none for the ellipse, whose end the arrest rule takes
// from its time).
std::vector<bool> patch_nodes(const Nucleation& nucleation, const std::vector<double>& x1) {
  std::vector<bool> inside(x1.size(), false);
  if (!nucleation.patch()) return inside;
  const Interval patch = nucleation_patch(nucleation);
  for (std::size_t i = 0; i < x1.size(); ++i)
    inside[i] = x1[i] >= patch.lo && x1[i] <= patch.hi;
  return inside;
}

Observers set_up_observers(const SimulationParams& params, const RunHooks& hooks,
                           const MeshInfo& mesh, const std::vector<double>& x1, double dt,
                           long total_steps, std::chrono::steady_clock::time_point started) {
  return {
      ProbeRecorder(params.probes, params.geometry.x_min, mesh.dx, x1),
      StationRecorder(params.stations, params.geometry.x_min, mesh.dx, int(x1.size()), total_steps),
      InterfaceSampler(hooks.sink, params.output, dt, total_steps, x1),
      EnergyRecorder(dt),
      DivergenceCheck(params, x1),
      FrontTracker(mesh.nx, params.probes.front_threshold, patch_nodes(params.nucleation, x1)),
      ArrestRule(params),
      ProgressReporter(hooks, params.time.duration, dt, total_steps, started)};
}

// 2. The method advances `count` steps from step n at once (FE: one trip over the mesh for
//    all of them); energy_steps[k]: step n + k evaluates the energy terms (when the energy
//    recorder is due).
void step_block(RuptureMethod& method, const EnergyRecorder& energy, long n, int count,
                std::vector<bool>& energy_steps) {
  energy_steps.assign(count, false);
  for (int k = 0; k < count; ++k)
    energy_steps[k] = energy.due(n + k);
  method.step_block(energy_steps);
}

// 3. Every observer records step n from the method's interface of that step (and its energy
//    balance, on the steps that evaluated it).
void record_step(Observers& o, long n, double dt, const InterfaceFields& f,
                 const EnergyBalance* e) {
  const double t_n = n * dt;
  o.front.update(f.half_velocity, t_n + 0.5 * dt, dt);
  o.divergence.check(f);
  o.probes.record(f, t_n);
  o.stations.record(f, t_n);
  if (e) {
    o.energy.record(*e, t_n);
    o.divergence.check_energy(*e);
  }
  o.sampler.record(f, n, t_n);
}

// 4a. The cancel rule, checked before every step (also inside a block): the run ends
//     before step n, its result marked cancelled.
bool cancel_before_step(const RunHooks& hooks, long n, double dt, RunResult& result) {
  if (!hooks.cancel || !hooks.cancel->load(std::memory_order_relaxed)) return false;
  result.cancelled = true;
  result.metrics.message = "cancelled at t = " + std::to_string(n * dt) + " s";
  return true;
}

// 4b. The stop rules after step n: the run diverged (outcome and message set here), or the
//     rupture arrested and time.stop_on_arrest asks to stop.
bool stop_after_step(Observers& o, long n, double dt, Metrics& m) {
  const double t_n = n * dt;
  if (o.divergence.diverged()) {
    m.outcome = Outcome::diverged;
    m.message = o.divergence.message(t_n, n);
    return true;
  }
  return o.arrest.update(t_n, o.front.last_new_arrival(), o.front.first_arrival_outside());
}

// 5. The metrics of a run that ended after `steps` steps, from the observers' records.
void derive_metrics(const RuptureMethod& method, const SimulationParams& params, Observers& o,
                    long steps, double dt, RunResult& result) {
  Metrics& m = result.metrics;
  m.steps = steps;
  m.simulated_time = steps * dt;
  m.max_slip_velocity = o.divergence.max_slip_velocity();
  if (m.outcome != Outcome::diverged)
    m.outcome = o.arrest.arrested() ? Outcome::arrested : Outcome::running_at_end;
  result.probes = o.probes.take();
  result.stations = o.stations.take();
  result.energy = o.energy.take();
  derive_front_metrics(params, result.mesh.dx, o.front.arrival(), result.front, m);
  derive_spectral_estimate(params, result.front, result.probes, result.mesh.dx, dt, m);
  m.energy_error = energy_balance_error(result.energy);
  for (std::string& warning : method.end_warnings(m.simulated_time))
    m.warnings.push_back(std::move(warning));
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
  const long total_steps = checked_step_count(steps_to_reach(params.time.duration, dt));

  // 1. Set up the observers.
  Observers o =
      set_up_observers(params, hooks, result.mesh, method.interface().x1, dt, total_steps, started);

  // 2-4. Block by block: the method takes up to block_steps() steps at once; the loop then
  // reads them one by one, in order, as if stepped singly. A stop inside a block leaves the
  // later steps of that block unread: the run ends at the same step with the same records.
  const int block = std::max(1, method.block_steps());
  std::vector<bool> energy_steps;
  long n = 0;
  bool stopped = false;
  while (n < total_steps && !stopped && !cancel_before_step(hooks, n, dt, result)) {
    const int count = int(std::min<long>(block, total_steps - n));
    step_block(method, o.energy, n, count, energy_steps); // 2
    for (int k = 0; k < count && !stopped; ++k) {
      if (k > 0 && cancel_before_step(hooks, n, dt, result)) { // 4a
        stopped = true;
        break;
      }
      record_step(o, n, dt, method.interface_after(k), // 3
                  energy_steps[k] ? &method.energy_after(k) : nullptr);
      stopped = stop_after_step(o, n, dt, m); // 4b
      if (!stopped) o.progress.after_step(n);
      ++n;
    }
  }

  // 5. Derive the metrics; the cost counts the set-up, the loop and the derivation.
  derive_metrics(method, params, o, n, dt, result);
  m.wall_time_s = o.progress.wall_seconds();
  o.progress.final_report(n, m.simulated_time, m.wall_time_s);
  return result;
}

} // namespace slipfront
