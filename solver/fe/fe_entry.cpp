// The finite-element method's entry in the registry of methods (solver/methods.hpp): the
// paper's explicit Q4 elements of a block of height h, on the rigid plane or on a lower block.
#include "solver/fe/absorbing_layer.hpp"
#include "solver/fe/finite_element_method.hpp"
#include "solver/mesh_size.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace slipfront::fe {

namespace {

constexpr const char* discretisation = "Q4 2x2 Gauss, lumped mass, central differences";

const char* boundary_name(TopBoundary boundary) {
  switch (boundary) {
  case TopBoundary::absorbing:
    return "absorbing";
  case TopBoundary::pml:
    return "pml";
  case TopBoundary::traction:
    break;
  }
  return "traction";
}

std::string describe(const SimulationParams& params) {
  std::string text = std::string(discretisation) + "; top boundary: " + boundary_name(params.top);
  if (params.top == TopBoundary::pml) {
    char layer[200];
    std::snprintf(layer, sizeof layer,
                  " (a perfectly matched layer of %d elements above the height, quadratic "
                  "profile, design reflection %g, ended by dashpots)",
                  params.geometry.pml_elements, kLayerDesignReflection);
    text += layer;
  }
  if (params.lower.elastic())
    text += std::string("; lower solid: elastic block (split-node interface), bottom "
                        "boundary: ") +
            boundary_name(params.lower.bottom);
  if (params.fe.mesh_damping > 0) {
    char damping[200];
    std::snprintf(damping, sizeof damping,
                  "; mesh-scale stiffness-proportional damping -a K v, a = %g dx / c_s",
                  params.fe.mesh_damping);
    text += damping;
  }
  return text;
}

std::string mesh_summary(const SimulationParams& params) {
  const Geometry& g = params.geometry;
  const double height = mesh_size(params).height;
  char mesh[200];
  const int layer_rows = mesh_size(params).layer_rows;
  std::snprintf(mesh, sizeof mesh, "%ld x %ld nodes, dx = %g m, height = %g m%s",
                std::lround(g.width * g.nodes_per_meter),
                std::lround(height * g.nodes_per_meter) + 1 + layer_rows, 1.0 / g.nodes_per_meter,
                height, g.auto_height ? " (auto)" : "");
  std::ostringstream out;
  out << "mesh: " << mesh << '\n';
  if (layer_rows > 0)
    out << "perfectly matched layer: " << layer_rows << " rows above the height\n";
  if (params.lower.elastic()) {
    const MeshSize m = lower_mesh_size(params);
    out << "lower block: " << m.nx << " x " << m.ny << " nodes, height = " << m.height << " m"
        << (params.lower.auto_height ? " (auto)" : "") << '\n';
  }
  return out.str();
}

} // namespace

const MethodEntry& method_entry() {
  static const MethodEntry entry{
      .method = Method::finite_element,
      .label = "FE",
      .heading = "FE",
      .title = "finite elements",
      .description = "the explicit Q4 finite elements of the paper (a block of height h; "
                     "docs/physics.md)",
      .run_cost = "minutes per run at fine meshes",
      .cost_rank = 1,
      .counterpart = Method::spectral_bi,
      .supports = {.rigid_base = true, .two_solids = true, .block_height = true},
      .time_step = {.safety_factor = true,
                    .rule = "time.safety_factor * the stable step of the mesh"},
      .wave_speeds = {},
      .make = [](const SimulationParams& params) -> std::unique_ptr<RuptureMethod> {
        return std::make_unique<FiniteElementMethod>(params);
      },
      .time_step_bounds = &FiniteElementMethod::time_step_bounds,
      .step_count_bound = &FiniteElementMethod::step_count_bound,
      .estimated_memory_bytes = &FiniteElementMethod::estimated_memory_bytes,
      .estimated_work = &FiniteElementMethod::estimated_work,
      .cost_terms = {{{"node_step_s", &RunWork::node_steps},
                      {"row_step_s", &RunWork::row_steps},
                      {"interface_step_s", &RunWork::interface_steps},
                      {"rate_solve_s", &RunWork::rate_solves}}},
      .discretisation = discretisation,
      .describe = &describe,
      .mesh_summary = &mesh_summary,
  };
  return entry;
}

} // namespace slipfront::fe
