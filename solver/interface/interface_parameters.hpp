// The per-node parameters of the interface, built once at set-up (docs/physics.md
// "Profiles"): the initial shear and normal stress and the friction values of every node,
// from the uniform values (loading, friction), then the `profiles` entries in order, then
// the overstressed patch of the nucleation. Both methods start from them.
#pragma once

#include "solver/interface/friction/strength_law.hpp"
#include "solver/interface/interface_fields.hpp"
#include "solver/params.hpp"

#include <vector>

namespace slipfront {

// Where a node's value was set last (for the messages of the job validation).
constexpr int uniform_source = -1; // loading or friction
constexpr int patch_source = -2;   // the overstressed patch; k >= 0: profiles[k]

struct NodeParameters {
  double shear_stress = 0;  // tau0 [Pa], the initial shear traction on the solid
  double normal_stress = 0; // sigma0 [Pa], < 0 in compression
  FrictionValues friction;
  int shear_source = uniform_source, normal_source = uniform_source;
  // The last source of each friction value a profile set (absent: uniform_source).
  std::vector<std::pair<double FrictionValues::*, int>> friction_sources;
  int friction_source(double FrictionValues::*value) const;
};

// The parameters at position x1 (O(number of profiles)).
NodeParameters node_parameters(const SimulationParams& params, double x1);

// The positions where node_parameters may change: every interval end of the profiles and
// of the overstressed patch (between two of them it is constant).
std::vector<double> parameter_breakpoints(const SimulationParams& params);

// One node of every stretch of the interface (nx nodes spaced dx from x_min) on which
// node_parameters is constant, and the nodes on both sides of every breakpoint: where a
// check of the set-up must look to see every value the nodes take (in increasing order).
std::vector<int> representative_nodes(const SimulationParams& params, int nx, double dx);

struct InterfaceParameters {
  std::vector<double> x1;            // node positions x_min + i dx
  std::vector<double> shear_stress;  // tau0_i
  std::vector<double> normal_stress; // sigma0_i
  std::vector<FrictionValues> friction;
};

InterfaceParameters interface_parameters(const SimulationParams& params, int nx, double dx);

// The resting, pre-stressed state of the interface: no motion, tau1 = tau0_i, p = |sigma0_i|,
// strength mu_0 p (docs/physics.md "Load"), and the friction state of each node.
InterfaceFields resting_interface(const InterfaceParameters& parameters, const StrengthLaw& law);
std::vector<FrictionState> resting_friction(const InterfaceParameters& parameters,
                                            const StrengthLaw& law);

} // namespace slipfront
