#include "api/job_checks.hpp"

#include "api/interface_checks.hpp"
#include "api/memory_size.hpp"
#include "api/number_text.hpp"
#include "solver/methods.hpp"
#include "solver/simulation.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront::api {

namespace {

constexpr double whole_elements_tolerance = 1e-9; // relative
constexpr double min_elements_along_x1 = 3.0;     // a periodic row needs distinct neighbours
constexpr double max_elements_per_axis = 1e7;     // node indices stay far inside an int

bool has_error(const std::vector<FieldError>& errors, const std::string& pointer) {
  return std::any_of(errors.begin(), errors.end(),
                     [&](const FieldError& e) { return e.pointer == pointer; });
}

bool any_error(const std::vector<FieldError>& errors, std::initializer_list<const char*> pointers) {
  return std::any_of(pointers.begin(), pointers.end(),
                     [&](const char* pointer) { return has_error(errors, pointer); });
}

// Twelve significant digits: a spec's numbers are echoed back as given.
std::string text(double value) {
  return number_text(value, 12);
}

// "length * nodes_per_meter" must be a whole number of elements. Too many of them is blamed
// on the factor that is out of scale: nodes_per_meter when it is above sqrt(1e7) ~ 3162 per
// metre (then every axis is too long, and the error is given once), else the length.
void check_whole_elements(const char* pointer, const char* what, double length,
                          double nodes_per_meter, double min_elements,
                          std::vector<FieldError>& errors) {
  const double elements = length * nodes_per_meter;
  const double whole = std::round(elements);
  if (!(whole <= max_elements_per_axis)) { // an infinite product too
    const bool resolution = nodes_per_meter > std::sqrt(max_elements_per_axis);
    const std::string blamed = resolution ? "/geometry/nodes_per_meter" : pointer;
    if (!has_error(errors, blamed))
      errors.push_back(
          {blamed, std::string(what) + " * nodes_per_meter = " + text(length) + " * " +
                       text(nodes_per_meter) + " = " + text(elements) +
                       " elements, more than the " + text(max_elements_per_axis) +
                       " allowed along one axis: use " +
                       (resolution ? "fewer nodes per meter" : "a smaller " + std::string(what))});
  } else if (std::abs(elements - whole) > whole_elements_tolerance * elements) {
    errors.push_back({pointer, std::string(what) + " * nodes_per_meter = " + text(length) + " * " +
                                   text(nodes_per_meter) + " = " + text(elements) +
                                   " must be a whole number of elements (within 1e-9 relative): "
                                   "the mesh is regular with element size 1/nodes_per_meter"});
  } else if (whole < min_elements) {
    errors.push_back({pointer, std::string(what) + " * nodes_per_meter = " + text(elements) +
                                   " elements, need at least " + text(min_elements)});
  }
}

// The height of an FE block (section "geometry" or "lower"): whole elements, or for "auto"
// (h = c_p * duration / 2, growing with the duration) not too many of them.
void check_block_height(const JobSpec& job, const std::string& section, double height,
                        bool auto_height, const Material& material,
                        std::vector<FieldError>& errors) {
  const std::string pointer = "/" + section + "/height";
  const SimulationParams& p = job.params;
  if (!auto_height) {
    if (!has_error(errors, pointer))
      check_whole_elements(pointer.c_str(), "height", height, p.geometry.nodes_per_meter, 1.0,
                           errors);
    return;
  }
  const double c_p = material.p_wave_speed(); // not finite: api/run_bounds.cpp tells
  const std::string m = section == "lower" ? "/lower" : "/material";
  if (!std::isfinite(c_p) || has_error(errors, "/time/duration") ||
      any_error(errors, {(m + "/density").c_str(), (m + "/young_modulus").c_str(),
                         (m + "/poisson_ratio").c_str()}))
    return;
  const double elements = 0.5 * c_p * p.time.duration * p.geometry.nodes_per_meter;
  if (!(elements <= max_elements_per_axis)) {
    errors.push_back(
        {pointer, "\"auto\" gives c_p * duration / 2 * nodes_per_meter = " + text(elements) +
                      " elements, more than the " + text(max_elements_per_axis) +
                      " allowed along one axis: give a height or a shorter duration"});
  }
}

void check_mesh(const JobSpec& job, std::vector<FieldError>& errors) {
  const Geometry& g = job.params.geometry;
  if (any_error(errors, {"/geometry/nodes_per_meter"})) return;
  if (!has_error(errors, "/geometry/width")) {
    check_whole_elements("/geometry/width", "width", g.width, g.nodes_per_meter,
                         min_elements_along_x1, errors);
  }
  const SimulationParams& p = job.params;
  if (method_entry(p.method).supports.block_height) { // else half-spaces: no height
    check_block_height(job, "geometry", g.height, g.auto_height, p.material, errors);
    if (p.lower.elastic())
      check_block_height(job, "lower", p.lower.height, p.lower.auto_height, p.lower.material,
                         errors);
  }
  const double interface_nodes = std::round(g.width * g.nodes_per_meter);
  if (!any_error(errors, {"/geometry/width", "/output/space_stride"}) &&
      p.output.space_stride > interface_nodes) {
    errors.push_back({"/output/space_stride", "must be at most the number of interface nodes (" +
                                                  text(interface_nodes) + "), got " +
                                                  std::to_string(p.output.space_stride)});
  }
}

void check_probe(const JobSpec& job, const std::string& pointer, double x1,
                 std::vector<FieldError>& errors) {
  const Geometry& g = job.params.geometry;
  if (any_error(errors, {"/geometry/width", "/geometry/x_min"}) || has_error(errors, pointer)) {
    return;
  }
  if (x1 < g.x_min || x1 >= g.x_min + g.width) {
    errors.push_back({pointer, "must lie in the domain [x_min, x_min + width) = [" + text(g.x_min) +
                                   ", " + text(g.x_min + g.width) + "), got " + text(x1)});
  }
}

// Every station lies in the domain, and no two at the same x1 (the CSV export keys its rows
// by station_x1).
void check_stations(const JobSpec& job, std::vector<FieldError>& errors) {
  const std::vector<double>& x1 = job.params.stations.x1;
  for (std::size_t i = 0; i < x1.size(); ++i) {
    const std::string pointer = "/stations/x1/" + std::to_string(i);
    check_probe(job, pointer, x1[i], errors);
    const auto first = std::find(x1.begin(), x1.begin() + long(i), x1[i]);
    if (first != x1.begin() + long(i))
      errors.push_back({pointer, "repeats station " + std::to_string(first - x1.begin()) +
                                     " (x1 = " + text(x1[i]) + "): each station once"});
  }
}

} // namespace

void check_job_consistency(const JobSpec& job, std::vector<FieldError>& errors) {
  check_mesh(job, errors);
  check_probe(job, "/probe/arrival_x1", job.params.probes.arrival_x1, errors);
  check_probe(job, "/probe/spectrum_x1", job.params.probes.spectrum_x1, errors);
  check_stations(job, errors);
  check_interface_setup(job, errors); // api/interface_checks.hpp: the initial state is stuck
}

void check_memory(const JobSpec& job, const ValidationLimits& limits,
                  std::vector<FieldError>& errors) {
  if (!(job.memory_estimate_bytes <= limits.max_memory_bytes)) { // NaN too
    errors.push_back({"/geometry/nodes_per_meter",
                      "the run would need about " + byte_size_text(job.memory_estimate_bytes) +
                          " of memory (estimate), above the limit of " +
                          byte_size_text(limits.max_memory_bytes) +
                          ": use fewer nodes per meter, a smaller domain or a shorter duration"});
  }
}

} // namespace slipfront::api
