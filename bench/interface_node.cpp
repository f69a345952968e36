// The cost of the interface law at one node and step (resolve_interface_node: contact, the
// friction state's update and the tangential solve), per law: linear slip weakening (sliding
// and stuck nodes), rate-and-state with the aging and the slip law. The nodes are those of a
// rupture in progress: 4096 nodes at TPV101's numbers (sigma 120 MPa, a 0.008, b 0.012, D_c
// 0.02 m), each driven with a trial slip rate between 1e-9 and 10 m/s that drifts by a few per
// cent from step to step, as a node's does, so that the last slip rate is the solve's guess as
// in a run. Each benchmark iteration steps all nodes once; the figure is the time per node
// (per_node) (docs/performance.md "Rate-and-state friction: cost per step").
//
//   build/bench/slipfront_interface_node --benchmark_min_time=1
#include "solver/interface/interface_law.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

using namespace slipfront;

constexpr int node_count = 4096;
constexpr double sigma = 120e6; // [Pa]

enum class Law { slip_weakening, aging, slip };

Friction friction_of(Law law) {
  Friction f;
  if (law == Law::slip_weakening) {
    f.law = "slip_weakening";
    f.mu_s = 0.677, f.mu_d = 0.525, f.D_c = 0.4;
    return f;
  }
  f.law = "rate_and_state";
  f.state_evolution = law == Law::aging ? StateEvolution::aging : StateEvolution::slip;
  f.a = 0.008, f.b = 0.012, f.D_c = 0.02, f.f0 = 0.6, f.v_star = 1e-6;
  f.initial_slip_rate = 1e-12;
  return f;
}

void interface_node(benchmark::State& run) {
  const Law law = Law(run.range(0));
  InterfaceNodeConstants c;
  c.dt = 2e-3, c.tributary_length = 25.0;
  const double eta = 2670.0 * 3464.0 / 2.0; // rho c_s / 2, the radiation damping [Pa s/m]
  c.mass1 = c.mass2 = eta * c.tributary_length * c.dt;
  const Friction friction = friction_of(law);
  c.law = StrengthLaw(friction);
  const FrictionValues& values = friction;

  std::vector<double> slip_rate(node_count), target(node_count), pressure(node_count, sigma);
  std::vector<FrictionState> state(node_count);
  for (int i = 0; i < node_count; ++i) {
    target[i] = 1e-9 * std::pow(1e10, double(i) / (node_count - 1)); // 1e-9 ... 10 m/s
    slip_rate[i] = target[i];
    state[i] = c.law.resting_state(values, sigma, 0.6 * sigma);
    if (law != Law::slip_weakening) state[i].theta = values.D_c / target[i]; // steady state
  }
  // The trial velocity that drives node i at about its target rate against the strength.
  const double u2 = sigma * c.dt * c.dt / c.mass2; // the gap the contact closes this step
  long step = 0;
  for (auto _ : run) {
    const double drift = 1.0 + 0.03 * std::sin(0.1 * double(step++));
    for (int i = 0; i < node_count; ++i) {
      const double tau = 0.6 * sigma * drift;
      const double v1_trial = (tau / eta + target[i] * drift);
      const InterfaceNodeStep out = resolve_interface_node(c, values, 0.0, v1_trial, -u2 / c.dt,
                                                           slip_rate[i], state[i], pressure[i]);
      slip_rate[i] = std::abs(out.v1);
      state[i] = out.friction;
      pressure[i] = out.pressure;
      benchmark::DoNotOptimize(out);
    }
  }
  run.counters["per_node"] =
      benchmark::Counter(double(node_count) * double(run.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK(interface_node)
    ->Arg(int(Law::slip_weakening))
    ->Arg(int(Law::aging))
    ->Arg(int(Law::slip))
    ->ArgNames({"law(0 sw,1 aging,2 slip)"})
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
