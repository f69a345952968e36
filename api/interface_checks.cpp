#include "api/interface_checks.hpp"

#include "api/friction_fields.hpp"
#include "api/number_text.hpp"
#include "solver/interface/interface_parameters.hpp"
#include "solver/mesh_size.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace slipfront::api {

namespace {

constexpr double strength_tolerance = 1e-12; // relative: a load equal to mu |p| may stick

std::string text(double value) {
  return number_text(value, 12);
}

bool has_error_under(const std::vector<FieldError>& errors, const std::string& prefix) {
  return std::any_of(errors.begin(), errors.end(), [&](const FieldError& e) {
    return e.pointer.compare(0, prefix.size(), prefix) == 0;
  });
}

// A value's pointer: the profiles entry that set it last, or its uniform field.
struct Source {
  int index; // uniform_source or the profile's index
  std::string pointer;
};

Source source_of(int index, const std::string& uniform_section, const std::string& name) {
  return {index, index >= 0 ? "/profiles/" + std::to_string(index) + "/" + name
                            : "/" + uniform_section + "/" + name};
}

// The source applied last among `sources` (the first of equals).
Source latest(const std::vector<Source>& sources) {
  return *std::max_element(sources.begin(), sources.end(),
                           [](const Source& a, const Source& b) { return a.index < b.index; });
}

void add_once(std::vector<FieldError>& errors, std::set<std::string>& named, FieldError error) {
  if (named.insert(error.pointer).second) errors.push_back(std::move(error));
}

void check_patch(const SimulationParams& p, int nx, double dx, std::vector<FieldError>& errors) {
  const Nucleation& n = p.nucleation;
  const Geometry& g = p.geometry;
  const std::string domain =
      "[x_min, x_min + width) = [" + text(g.x_min) + ", " + text(g.x_min + g.width) + ")";
  if (n.x1_min > n.x1_max) {
    errors.push_back({"/nucleation/x1_min",
                      "must be at most x1_max = " + text(n.x1_max) + ", got " + text(n.x1_min)});
    return;
  }
  if (n.x1_min < g.x_min || n.x1_min >= g.x_min + g.width)
    errors.push_back({"/nucleation/x1_min", "the overstressed patch must lie in the domain " +
                                                domain + ", got " + text(n.x1_min)});
  if (n.x1_max < g.x_min || n.x1_max >= g.x_min + g.width)
    errors.push_back({"/nucleation/x1_max", "the overstressed patch must lie in the domain " +
                                                domain + ", got " + text(n.x1_max)});
  const int first = int(std::clamp(std::ceil((n.x1_min - g.x_min) / dx), 0.0, double(nx)));
  bool holds_node = false;
  for (int i = std::max(0, first - 1); i <= std::min(nx - 1, first + 1); ++i) {
    const double x1 = g.x_min + i * dx;
    holds_node = holds_node || (x1 >= n.x1_min && x1 <= n.x1_max);
  }
  if (!holds_node)
    errors.push_back({"/nucleation/x1_max", "the overstressed patch [" + text(n.x1_min) + ", " +
                                                text(n.x1_max) +
                                                "] holds no interface node "
                                                "(spacing dx = " +
                                                text(dx) + " m)"});
}

void check_node(const SimulationParams& p, double x1, std::set<std::string>& named,
                std::vector<FieldError>& errors) {
  const NodeParameters node = node_parameters(p, x1);
  const CoefficientLaw& law = coefficient_law(p.friction);
  const FrictionValues& f = node.friction;
  if (law.description().check) {
    if (auto problem = law.description().check(f)) {
      std::vector<Source> sources;
      for (const auto member : problem->members)
        sources.push_back(
            source_of(node.friction_source(member), "friction", friction_field_name(member)));
      add_once(errors, named,
               {latest(sources).pointer, "at x1 = " + text(x1) + " m " + problem->reason});
    }
  }
  if (!law.starts_stuck()) return;
  if (node.shear_source == patch_source) return; // the patch may start above its strength
  const double strength = law.static_coefficient(f) * std::abs(node.normal_stress);
  if (!(std::abs(node.shear_stress) > strength * (1.0 + strength_tolerance))) return;
  std::vector<Source> sources = {source_of(node.shear_source, "loading", "shear_stress"),
                                 source_of(node.normal_source, "loading", "normal_stress")};
  for (const LawParameter& parameter : law.description().parameters)
    sources.push_back(
        source_of(node.friction_source(parameter.member), "friction", parameter.name));
  const Source s = latest(sources);
  if (s.index == uniform_source) {
    add_once(errors, named,
             {"/loading/shear_stress",
              "|shear_stress| must not exceed the static strength mu * |normal_stress| = " +
                  text(strength) + " Pa (the initial state is stuck), got " +
                  text(node.shear_stress)});
    return;
  }
  add_once(
      errors, named,
      {s.pointer, "at x1 = " + text(x1) + " m the initial state is not stuck: |shear stress| " +
                      text(std::abs(node.shear_stress)) +
                      " Pa exceeds the static strength mu_0 |normal stress| = " + text(strength) +
                      " Pa (the interface must start stuck outside the nucleation patch)"});
}

} // namespace

void check_interface_setup(const JobSpec& job, std::vector<FieldError>& errors) {
  for (const char* section : {"/geometry", "/loading", "/friction", "/profiles", "/nucleation"})
    if (has_error_under(errors, section)) return;
  const SimulationParams& p = job.params;
  const MeshSize mesh = mesh_size(p);
  if (mesh.nx < 1) return; // the mesh check has said why
  if (p.nucleation.patch()) {
    const std::size_t before = errors.size();
    check_patch(p, mesh.nx, mesh.dx, errors);
    if (errors.size() != before) return;
  }
  std::set<std::string> named;
  for (const int i : representative_nodes(p, mesh.nx, mesh.dx))
    check_node(p, p.geometry.x_min + i * mesh.dx, named, errors);
}

} // namespace slipfront::api
