#include "solver/interface/interface_parameters.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront {

int NodeParameters::friction_source(double FrictionValues::*value) const {
  int source = uniform_source;
  for (const auto& [member, index] : friction_sources)
    if (member == value) source = index;
  return source;
}

NodeParameters node_parameters(const SimulationParams& params, double x1) {
  NodeParameters node;
  node.shear_stress = params.loading.shear_stress;
  node.normal_stress = params.loading.normal_stress;
  node.friction = params.friction; // the FrictionValues part
  for (std::size_t k = 0; k < params.profiles.size(); ++k) {
    const Profile& profile = params.profiles[k];
    const double w = profile.weight(x1);
    if (!(w > 0.0)) continue;
    // The profile's value where it applies in full (exactly), a blend in its ramp.
    auto apply = [w](double& target, double value) {
      target = w == 1.0 ? value : target + w * (value - target);
    };
    const int source = int(k);
    if (profile.shear_stress) {
      apply(node.shear_stress, *profile.shear_stress);
      node.shear_source = source;
    }
    if (profile.normal_stress) {
      apply(node.normal_stress, *profile.normal_stress);
      node.normal_source = source;
    }
    for (const auto& [member, value] : profile.friction) {
      apply(node.friction.*member, value);
      node.friction_sources.emplace_back(member, source);
    }
  }
  const Nucleation& n = params.nucleation;
  if (n.patch() && x1 >= n.x1_min && x1 <= n.x1_max) {
    node.shear_stress = n.shear_stress;
    node.shear_source = patch_source;
  }
  return node;
}

std::vector<double> parameter_breakpoints(const SimulationParams& params) {
  std::vector<double> points;
  for (const Profile& profile : params.profiles)
    for (double x : {profile.x1_min, profile.x1_max, profile.x1_min - profile.ramp,
                     profile.x1_max + profile.ramp})
      if (std::isfinite(x)) points.push_back(x);
  if (params.nucleation.patch()) {
    points.push_back(params.nucleation.x1_min);
    points.push_back(params.nucleation.x1_max);
  }
  return points;
}

std::vector<int> representative_nodes(const SimulationParams& params, int nx, double dx) {
  std::vector<int> nodes = {0, nx - 1};
  for (const double x : parameter_breakpoints(params)) {
    // The node at or just below x, clamped before it becomes an integer.
    const double below = std::clamp(std::floor((x - params.geometry.x_min) / dx), -2.0, nx + 1.0);
    for (int d = -1; d <= 2; ++d) {
      const int i = int(below) + d;
      if (i >= 0 && i < nx) nodes.push_back(i);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

InterfaceParameters interface_parameters(const SimulationParams& params, int nx, double dx) {
  InterfaceParameters out;
  out.x1.resize(nx);
  out.shear_stress.resize(nx);
  out.normal_stress.resize(nx);
  out.friction.resize(nx);
  for (int i = 0; i < nx; ++i) {
    const double x1 = params.geometry.x_min + i * dx;
    const NodeParameters node = node_parameters(params, x1);
    out.x1[i] = x1;
    out.shear_stress[i] = node.shear_stress;
    out.normal_stress[i] = node.normal_stress;
    out.friction[i] = node.friction;
  }
  return out;
}

std::vector<FrictionState> resting_friction(const InterfaceParameters& parameters,
                                            const StrengthLaw& law) {
  const std::size_t nx = parameters.x1.size();
  std::vector<FrictionState> state(nx);
  for (std::size_t i = 0; i < nx; ++i)
    state[i] = law.resting_state(parameters.friction[i], std::abs(parameters.normal_stress[i]),
                                 parameters.shear_stress[i]);
  return state;
}

InterfaceFields resting_interface(const InterfaceParameters& parameters, const StrengthLaw& law) {
  const std::size_t nx = parameters.x1.size();
  InterfaceFields f;
  f.x1 = parameters.x1;
  f.velocity.assign(nx, 0.0);
  f.half_velocity.assign(nx, 0.0);
  f.slip.assign(nx, 0.0);
  f.opening.assign(nx, 0.0);
  f.shear_traction = parameters.shear_stress;
  f.pressure.resize(nx);
  f.strength.resize(nx);
  const std::vector<FrictionState> state = resting_friction(parameters, law);
  for (std::size_t i = 0; i < nx; ++i) {
    f.pressure[i] = std::abs(parameters.normal_stress[i]);
    f.strength[i] = law.strength(parameters.friction[i], state[i],
                                 law.coefficient().initial_slip_rate(parameters.friction[i]));
  }
  f.state.assign(nx, std::int8_t(NodeState::stick));
  return f;
}

} // namespace slipfront
