#include "api/job_reader.hpp"

#include "api/interface_reader.hpp"
#include "api/job_methods.hpp"
#include "api/material_reader.hpp"
#include "api/run_annotations.hpp" // max_tags, max_tag_length

namespace slipfront::api {

namespace {

constexpr int max_threads = 256;
constexpr std::size_t max_name_length = 256;
constexpr std::size_t max_stations = 64;

// "height" is a number > 0 or the string "auto" (see resolved_height in solver/simulation.hpp),
// for the upper block (geometry) and the lower one (lower).
void read_height(ObjectReader& in, double& height, bool& auto_height) {
  if (const nlohmann::json* member = in.raw("height")) {
    if (*member == "auto") {
      auto_height = true;
    } else if (member->is_number() && positive().contains(member->get<double>())) {
      height = member->get<double>();
      auto_height = false;
    } else {
      in.error("height", "must be a finite number > 0 or \"auto\", got " + describe_value(*member));
    }
  }
  in.set_canonical("height", auto_height ? nlohmann::json("auto") : nlohmann::json(height));
  in.describe("height", {{"oneOf",
                          {{{"type", "number"}, {"exclusiveMinimum", 0}},
                           {{"type", "string"}, {"const", "auto"}}}}});
}

// A field that the chosen method has no use for is an error, not silently ignored.
void reject_for_method(ObjectReader& in, const std::string& key, const MethodEntry& method,
                       const std::string& why) {
  if (in.raw(key) != nullptr)
    in.error(key, "is not used by method \"" + std::string(method.method.name()) + "\": " + why);
}

void read_geometry(ObjectReader& in, SimulationParams& params) {
  const MethodEntry& method = method_entry(params.method);
  in.number("width", params.geometry.width, positive());
  if (method.supports.block_height) {
    read_height(in, params.geometry.height, params.geometry.auto_height);
  } else {
    reject_for_method(in, "height", method, "the half-space has no height; remove the field");
  }
  in.number("x_min", params.geometry.x_min, any_finite());
  in.number("nodes_per_meter", params.geometry.nodes_per_meter, positive());
  if (method.supports.block_height) {
    in.choice("top_boundary", params.top,
              {{"traction", TopBoundary::traction},
               {"absorbing", TopBoundary::absorbing},
               {"pml", TopBoundary::pml}});
    in.integer("pml_elements", params.geometry.pml_elements, 2, 1000);
    if (params.top != TopBoundary::pml) {
      if (in.raw("pml_elements") != nullptr)
        in.error("pml_elements", "is read only with top_boundary \"pml\"; remove the field");
      in.drop_canonical("pml_elements"); // the hashes of jobs without a layer stay as they were
    }
  } else {
    reject_for_method(in, "top_boundary", method, "the half-space has no top; remove the field");
    reject_for_method(in, "pml_elements", method, "the half-space has no top; remove the field");
  }
}

// The fields of an elastic lower solid: its material and, for a block, its height and far
// (bottom) boundary.
void read_elastic_lower(ObjectReader& in, LowerSolid& lower, const MethodEntry& method) {
  read_material(in, lower.material);
  if (method.supports.block_height) {
    read_height(in, lower.height, lower.auto_height);
    in.choice("bottom_boundary", lower.bottom,
              {{"traction", TopBoundary::traction}, {"absorbing", TopBoundary::absorbing}});
  } else {
    reject_for_method(in, "height", method, "the lower half-space has no height; remove the field");
    reject_for_method(in, "bottom_boundary", method,
                      "the lower half-space has no far boundary; remove the field");
  }
}

// What lies below the interface (docs/physics.md "Two solids"): the rigid plane (the default,
// which has no other field) or a second elastic solid, each where the method supports it.
void read_lower(ObjectReader& in, SimulationParams& params) {
  LowerSolid& lower = params.lower;
  const MethodEntry& method = method_entry(params.method);
  in.choice("solid", lower.side, {{"rigid", LowerSide::rigid}, {"elastic", LowerSide::elastic}});
  const std::string name(method.method.name());
  if (lower.elastic() && !method.supports.two_solids)
    in.error("solid", "method \"" + name +
                          "\" has no elastic solid below the interface: "
                          "remove the field (the rigid plane)");
  if (!lower.elastic() && !method.supports.rigid_base)
    in.error("solid", "method \"" + name + "\" has no rigid plane: give \"elastic\"");
  if (lower.elastic()) {
    read_elastic_lower(in, lower, method);
    return;
  }
  const auto elastic_fields = [&](ObjectReader& r) {
    LowerSolid ignored;
    read_elastic_lower(r, ignored, method);
  };
  for (const std::string& key : in.present_fields_of(elastic_fields))
    in.error(key, "is used only with \"solid\": \"elastic\" (below the interface is the rigid "
                  "plane, which has no material, height or boundary)");
}

void read_loading(ObjectReader& in, Loading& loading) {
  in.number("normal_stress", loading.normal_stress, negative());
  in.number("shear_stress", loading.shear_stress, any_finite());
}

void read_time(ObjectReader& in, TimeControl& time, const MethodEntry& method) {
  in.number("duration", time.duration, positive());
  if (method.time_step.safety_factor) {
    in.number("safety_factor", time.safety_factor,
              left_open(0.0, 2.0)); // > 1: unstable, for failure studies
  } else {
    reject_for_method(in, "safety_factor", method,
                      std::string("its time step is ") + method.time_step.rule);
  }
  in.boolean("stop_on_arrest", time.stop_on_arrest);
  in.number("arrest_window", time.arrest_window, positive());
}

void read_output(ObjectReader& in, OutputSampling& output) {
  in.number("interval", output.interval, positive());
  in.integer("space_stride", output.space_stride, 1, 1'000'000);
}

void read_probes(ObjectReader& in, Probes& probes) {
  in.number("arrival_x1", probes.arrival_x1, any_finite());
  in.number("spectrum_x1", probes.spectrum_x1, any_finite());
  in.number("front_threshold", probes.front_threshold, positive());
}

// On-fault stations (docs/hdf5-layout.md "/stations"); api/job_checks.cpp checks that each
// lies in the domain.
void read_stations(ObjectReader& in, Stations& stations) {
  in.number_list("x1", stations.x1, max_stations, any_finite());
  in.number("rupture_threshold", stations.rupture_threshold, positive());
}

} // namespace

void read_job_fields(ObjectReader& in, JobSpec& job) {
  SimulationParams& params = job.params;
  // The method first: it decides which other fields exist (solver/methods.hpp).
  std::vector<std::pair<std::string, Method>> names;
  for (const MethodEntry* entry : methods())
    names.emplace_back(entry->method.name(), entry->method);
  in.choice("method", params.method, names);
  // Its section of options (api/job_methods.hpp); another method's is an error.
  for (const MethodOptions* options : method_options()) {
    if (options->method == params.method) {
      in.object(options->section, [&](ObjectReader& o) { options->read(o, params); });
    } else if (in.raw(options->section) != nullptr) {
      in.error(options->section, "is used only with \"method\": \"" +
                                     std::string(options->method.name()) + "\" (the method is \"" +
                                     std::string(params.method.name()) + "\")");
    }
  }
  in.object("material", [&](ObjectReader& m) { read_material(m, params.material); });
  in.object("geometry", [&](ObjectReader& g) { read_geometry(g, params); });
  in.object("lower", [&](ObjectReader& l) { read_lower(l, params); });
  in.object("loading", [&](ObjectReader& l) { read_loading(l, params.loading); });
  in.object("friction", [&](ObjectReader& f) { read_friction(f, params.friction); });
  read_profiles(in, params.friction, params.profiles);
  in.object("nucleation", [&](ObjectReader& n) { read_nucleation(n, params.nucleation); });
  in.object("time",
            [&](ObjectReader& t) { read_time(t, params.time, method_entry(params.method)); });
  in.object("output", [&](ObjectReader& o) { read_output(o, params.output); });
  in.object("probe", [&](ObjectReader& p) { read_probes(p, params.probes); });
  in.object("stations", [&](ObjectReader& s) { read_stations(s, params.stations); });
  // Without stations the section changes nothing: it stays out of the canonical form, so the
  // specs written before it existed keep their hashes.
  if (params.stations.x1.empty()) in.omit_canonical("stations");
  in.integer("threads", params.threads, 0, max_threads);
  in.string("name", job.name, max_name_length);
  in.string_list("tags", job.tags, max_tags, max_tag_length);
}

} // namespace slipfront::api
