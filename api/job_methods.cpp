#include "api/job_methods.hpp"

#include "api/job_schema.hpp"

#include <algorithm>
#include <set>

#include <stdexcept>

namespace slipfront::api {

namespace {

// The options of the spectral boundary-integral method (docs/spectral-bi.md).
void read_spectral(ObjectReader& in, SimulationParams& params) {
  SpectralOptions& options = params.spectral;
  // beta = 1 diverges within ~50 steps on every mesh tried, 0.75 is stable (docs/spectral-bi.md).
  in.number("time_step_factor", options.time_step_factor, left_open(0.0, 0.75));
  in.number("memory_periods", options.memory_periods, left_open(0.0, 256.0));
  in.integer("corrector_passes", options.corrector_passes, 0, 4);
}

// The options of the finite-element method: the mesh-scale damping (docs/physics.md).
void read_fe(ObjectReader& in, SimulationParams& params) {
  in.number("mesh_damping", params.fe.mesh_damping, closed_interval(0.0, 4.0));
}

const MethodOptions& spectral_options() {
  static const MethodOptions options{
      Method::spectral_bi,
      "spectral_bi",
      &read_spectral,
      {{"time_step_factor", "",
        "beta: dt = beta · dx / c_s; beta = 1 diverges; with plain Coulomb friction use 0.25 "
        "(docs/spectral-bi.md)"},
       {"memory_periods", "",
        "q: each Fourier mode k keeps q periods 2 pi / (\\|k\\| c_s) of its history"},
       {"corrector_passes", "", "local solves after the predictor in each step"}},
      {{"/spectral_bi/time_step_factor",
        [](SimulationParams& p, const SimulationParams& job) {
          p.spectral.time_step_factor = job.spectral.time_step_factor;
        }}},
      nullptr,
  };
  return options;
}

const MethodOptions& fe_options() {
  static const MethodOptions options{
      Method::finite_element,
      "fe",
      &read_fe,
      {{"mesh_damping", "",
        "ζ of the mesh-scale stiffness-proportional (Kelvin–Voigt) damping force `−a K v`, "
        "`a = ζ dx / c_s`, which vanishes under refinement; 0 is the paper's undamped "
        "scheme. It shrinks the stable step to `sqrt(a² + dt0²) − a` (ζ = 0.1: 0.84 dt0) and "
        "costs about twice the work per step (docs/physics.md, docs/small-l-study.md)"}},
      {{"/fe/mesh_damping",
        [](SimulationParams& p, const SimulationParams& job) {
          p.fe.mesh_damping = job.fe.mesh_damping;
        }}},
      // The undamped scheme of every record made before the section existed.
      {{"mesh_damping", 0.0}},
  };
  return options;
}

std::vector<const MethodOptions*>& table() {
  // A new built-in method: its entry here. The spectral section is read before the FE one.
  static std::vector<const MethodOptions*> all = {&spectral_options(), &fe_options()};
  return all;
}

} // namespace

const std::vector<const MethodOptions*>& method_options() {
  return table();
}

const MethodOptions* find_options(Method method) {
  for (const MethodOptions* options : table())
    if (options->method == method) return options;
  return nullptr;
}

void register_method_options(const MethodOptions& options) {
  if (find_method(options.method.name()) == nullptr)
    throw std::invalid_argument("no rupture method is called \"" +
                                std::string(options.method.name()) + "\"");
  for (const MethodOptions* known : table())
    if (known->method == options.method || std::string(known->section) == options.section)
      throw std::invalid_argument("the options of \"" + std::string(options.method.name()) +
                                  "\" or its section \"" + options.section +
                                  "\" are registered already");
  table().push_back(&options);
}

std::vector<FieldWords> method_field_words() {
  std::string meaning;
  for (const MethodEntry* method : methods()) {
    if (!meaning.empty()) meaning += "; ";
    meaning.append("`\"").append(method->method.name()).append("\"`: ");
    meaning += method->description;
  }
  std::vector<FieldWords> words = {{"/method", "", meaning}};
  for (const MethodOptions* options : table())
    for (const OptionWords& field : options->words)
      words.push_back({child_pointer(child_pointer("", options->section), field.name), field.unit,
                       field.meaning});
  return words;
}

std::vector<const MethodEntry*> cheaper_methods() {
  std::vector<const MethodEntry*> cheaper;
  for (const MethodEntry* method : methods())
    if (method->cost_rank < default_method().cost_rank) cheaper.push_back(method);
  std::stable_sort(cheaper.begin(), cheaper.end(), [](const MethodEntry* a, const MethodEntry* b) {
    return a->cost_rank < b->cost_rank;
  });
  return cheaper;
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const MethodEntry* method : methods())
    names.emplace_back(method->method.name());
  return names;
}

std::string or_list(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text.append(k == 0 ? "" : k + 1 == names.size() ? " or " : ", ").append(names[k]);
  return text;
}

nlohmann::json method_labels_json() {
  nlohmann::json labels = nlohmann::json::object();
  for (const MethodEntry* m : methods())
    labels[std::string(m->method.name())] = {{"label", m->label},
                                             {"heading", m->heading},
                                             {"title", m->title},
                                             {"run_cost", m->run_cost},
                                             {"cost_rank", m->cost_rank}};
  return labels;
}

nlohmann::json method_document(const nlohmann::json& job, const MethodEntry& to) {
  const MethodEntry* from = find_method(method_name_of(job));
  if (from == nullptr) from = &default_method();
  // The fields only `from` reads, and the sections (first members) that `to` has no field of.
  std::set<std::string> dropped, kept_sections;
  for (const JobField& field : job_fields()) {
    const std::string section = field.pointer.substr(1, field.pointer.find('/', 1) - 1);
    if (field.read_by(to.method.name())) kept_sections.insert(section);
    if (field.read_by(from->method.name()) && !field.read_by(to.method.name()))
      dropped.insert(field.pointer);
  }
  nlohmann::json out = job;
  out["method"] = std::string(to.method.name());
  for (const std::string& pointer : dropped) {
    const std::string section = pointer.substr(1, pointer.find('/', 1) - 1);
    if (!out.contains(section)) continue;
    if (!kept_sections.contains(section)) {
      out.erase(section); // a section of options of `from`, whole
    } else if (out[section].is_object() && pointer.size() > section.size() + 1) {
      out[section].erase(pointer.substr(section.size() + 2));
    }
  }
  return out;
}

std::string method_name_of(const nlohmann::json& job) {
  if (job.is_object())
    if (const auto it = job.find("method"); it != job.end() && it->is_string())
      return it->get<std::string>();
  return std::string(default_method().method.name());
}

} // namespace slipfront::api
