#include "api/job_schema.hpp"

#include "api/friction_fields.hpp"
#include "api/job_methods.hpp"
#include "api/job_reader.hpp"
#include "api/presets.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace slipfront::api {

namespace {

struct Words {
  std::string unit;
  std::string meaning;
};

// The unit and meaning of every field but friction's and the methods' (docs/api-job-spec.md
// shows them beside the type, default and range that the reader records). Rules across fields
// are named here too; the code that checks them is api/job_checks.cpp. The friction fields'
// words come from the laws' descriptions (friction_words()), the words of "method" and of each
// method's section from the method (method_field_words, api/job_methods.hpp).
const std::map<std::string, Words>& fixed_words() {
  static const std::map<std::string, Words> words = {
      {"/material/density", {"kg/m^3", "rho: mass density of the solid above the interface"}},
      {"/material/young_modulus", {"Pa", "E: Young's modulus of the solid above the interface"}},
      {"/material/poisson_ratio",
       {"", "nu: Poisson's ratio of the solid above the interface; 0.5 (incompressible) has no "
            "finite c_p"}},
      {"/material/p_wave_speed",
       {"m/s", "c_p: with s_wave_speed instead of young_modulus and poisson_ratio (not mixed); "
               "more than sqrt(2) · c_s (poisson_ratio > 0). Converted with mu = rho c_s², "
               "nu = (c_p² − 2 c_s²)/(2 (c_p² − c_s²)), E = 2 mu (1 + nu) (docs/physics.md)"}},
      {"/material/s_wave_speed", {"m/s", "c_s: with p_wave_speed (see there)"}},
      {"/geometry/width", {"m", "w: x1 in [x_min, x_min + w), periodic"}},
      {"/geometry/height",
       {"m", "h; `\"auto\"`: the smallest height whose top reflection cannot reach the "
             "interface before the run ends (c_p · duration / 2, in whole elements, plus one; "
             "docs/physics.md)"}},
      {"/geometry/x_min", {"m", "left end of the domain"}},
      {"/geometry/nodes_per_meter",
       {"1/m", "n_d: interface nodes per metre; element size dx = 1/n_d. width · n_d (and "
               "height · n_d) must be whole numbers of elements, 3 to 1e7 along x1"}},
      {"/geometry/top_boundary",
       {"", "the top keeps the remote traction, or absorbs waves: `\"absorbing\"` "
            "(Lysmer–Kuhlemeyer dashpots) or `\"pml\"` (a perfectly matched layer of "
            "pml_elements rows above the height, ended by the dashpots; docs/physics.md "
            "\"Perfectly matched layer\")"}},
      {"/geometry/pml_elements",
       {"", "top_boundary `\"pml\"` only: the layer's thickness in elements (its rows are "
            "added above the height)"}},
      {"/lower/solid",
       {"", "what lies below the interface (docs/physics.md \"Two solids\"): the rigid plane of "
            "the paper, or a second elastic solid (FE: a block below the interface; "
            "spectral_bi: a half-space). Every other field of `lower` is used only with "
            "`\"elastic\"`"}},
      {"/lower/density", {"kg/m^3", "rho of the lower solid"}},
      {"/lower/young_modulus", {"Pa", "E of the lower solid"}},
      {"/lower/poisson_ratio", {"", "nu of the lower solid"}},
      {"/lower/p_wave_speed",
       {"m/s", "c_p of the lower solid, with s_wave_speed instead of young_modulus and "
               "poisson_ratio (as in material)"}},
      {"/lower/s_wave_speed", {"m/s", "c_s of the lower solid, with p_wave_speed"}},
      {"/lower/height",
       {"m", "the lower block's height below the interface; `\"auto\"` as geometry.height, with "
             "the lower solid's c_p"}},
      {"/lower/bottom_boundary",
       {"", "the lower block's far boundary x2 = -height keeps the remote traction, or absorbs "
            "waves (Lysmer–Kuhlemeyer dashpots)"}},
      {"/loading/normal_stress",
       {"Pa", "tau2_0: the uniform initial normal stress on the interface; negative = "
              "compressive (the solid must be pressed on the plane)"}},
      {"/loading/shear_stress",
       {"Pa", "tau1_0: the uniform initial shear stress on the interface; positive drives the "
              "solid towards +x1. At most mu_0 · "
              "\\|normal_stress\\| outside the nucleation patch (the initial state is stuck)"}},
      {"/nucleation/enabled", {"", "start the rupture at all (false: no nucleation of any type)"}},
      {"/nucleation/type",
       {"", "`ellipse`: the moving ellipse of the paper's appendix A (a, b, v, alpha); "
            "`overstressed_patch`: a uniform initial shear stress in [x1_min, x1_max] (x1_min, "
            "x1_max, shear_stress); `stress_perturbation`: a smooth shear-stress increase "
            "Delta tau_0 F(r) G(t) around x1 (SCEC TPV101; x1, radius, shear_stress_increase, "
            "rise_time)"}},
      {"/nucleation/a",
       {"m", "a_ell: the ellipse's size along x1 − v t, xi = (x1 − v t)/a (docs/physics.md; "
             "ellipse)"}},
      {"/nucleation/b",
       {"m", "b_ell: the ellipse's size along x1 + v t, eta = (x1 + v t)/b − eta_0 "
             "(docs/physics.md; ellipse)"}},
      {"/nucleation/v", {"m/s", "v_ell: speed of the ellipse towards +x1 (ellipse)"}},
      {"/nucleation/alpha", {"", "largest relative reduction of the normal load (ellipse)"}},
      {"/nucleation/x1_min",
       {"m", "left end of the overstressed patch (closed interval), inside the domain"}},
      {"/nucleation/x1_max",
       {"m", "right end of the overstressed patch, inside the domain; the patch must hold a "
             "node"}},
      {"/nucleation/shear_stress",
       {"Pa", "the initial shear stress in the patch (applied after the profiles; may exceed "
              "the static strength)"}},
      {"/nucleation/x1", {"m", "centre of the stress perturbation"}},
      {"/nucleation/radius",
       {"m", "R: the perturbation is Delta tau_0 F(r) with F(r) = exp(r²/(r² − R²)) for r < R, "
             "0 beyond (docs/physics.md)"}},
      {"/nucleation/shear_stress_increase",
       {"Pa", "Delta tau_0: the perturbation's largest shear-stress increase, at its centre"}},
      {"/nucleation/rise_time",
       {"s", "T: the perturbation grows by G(t) = exp((t − T)²/(t (t − 2T))) for 0 < t < T and "
             "stays after it"}},
      {"/profiles",
       {"", "overrides along x1 of the initial stresses and the friction values, piecewise "
            "constant or with smooth ramps, applied in order after the uniform values "
            "(entries: below)"}},
      {"/profiles/*/x1_min", {"m", "left end of the closed interval; absent: unbounded"}},
      {"/profiles/*/x1_max", {"m", "right end of the closed interval; absent: unbounded"}},
      {"/profiles/*/ramp",
       {"m", "w: beyond each end of the interval the entry's share falls smoothly from 1 to 0 "
             "over w by SCEC TPV101's boxcar B (docs/physics.md \"Profiles\"); absent or 0: "
             "piecewise constant"}},
      {"/profiles/*/outside",
       {"", "apply to x1 < x1_min or x1 > x1_max (strict) instead of the interval"}},
      {"/profiles/*/shear_stress", {"Pa", "initial shear stress tau1_0 there"}},
      {"/profiles/*/normal_stress", {"Pa", "initial normal stress tau2_0 there, < 0"}},
      {"/time/duration", {"s", "simulated time"}},
      {"/time/safety_factor",
       {"", "dt = safety_factor × the stable step of the discrete system; above 1 the scheme is "
            "unstable and the run ends `diverged` (for failure studies)"}},
      {"/time/stop_on_arrest", {"", "end the run once the rupture has arrested"}},
      {"/time/arrest_window",
       {"s", "the front must have stood still this long to count as arrested (docs/metrics.md). "
             "Default for another material than the paper's: a tenth of the duration, at most "
             "width / c_s (docs/api-job-spec.md \"Defaults and the scene's scale\")"}},
      {"/output/interval",
       {"s", "time between stored samples, rounded to whole steps (at least one). Default for "
             "another material: duration / 800"}},
      {"/output/space_stride",
       {"", "store every k-th interface node (at most the number of interface nodes)"}},
      {"/probe/arrival_x1",
       {"m", "where `arrival_time_at_probe` is measured; inside [x_min, x_min + width). Default "
             "for another material: two nucleation-patch lengths beyond the patch, the way the "
             "shear load drives"}},
      {"/probe/spectrum_x1",
       {"m", "where tau_s(t) is recorded for the spectral L_c estimate; inside the domain. "
             "Default for another material: half a patch length beyond the patch"}},
      {"/probe/front_threshold",
       {"m/s", "slip velocity that defines the slip front. Default for another material: "
               "1e-6 m/s scaled by (\\|normal_stress\\| + \\|shear_stress\\|) / (rho c_s) "
               "against the paper's 0.0255 m/s"}},
      {"/stations/x1",
       {"m", "on-fault stations: each inside [x_min, x_min + width), each once; the interface is "
             "recorded there every step, linearly between the two nodes around it (exact on a "
             "node), into /stations of the result file, with the rupture time in the metrics "
             "(docs/hdf5-layout.md). Empty: no stations"}},
      {"/stations/rupture_threshold",
       {"m/s", "a station's rupture time is the first time its \\|V\\| exceeds this "
               "(interpolated linearly between steps); default: probe.front_threshold (one "
               "threshold unless the job gives two)"}},
      {"/threads", {"", "worker threads of the run; 0 = all hardware threads"}},
      {"/name", {"", "free text"}},
      {"/tags", {"", "free text, for filtering"}},
  };
  return words;
}

// `name` (meaning), `name` (meaning) or `name` (meaning): a list of laws for a sentence.
std::string listed_laws(const std::vector<std::pair<std::string, std::string>>& laws) {
  std::string out;
  for (std::size_t i = 0; i < laws.size(); ++i) {
    if (i > 0) out += i + 1 == laws.size() ? " or " : ", ";
    out += "`" + laws[i].first + "` (" + laws[i].second + ")";
  }
  return out;
}

// The words of the friction fields, from the laws' descriptions (api/friction_fields.hpp).
std::map<std::string, Words> friction_words() {
  std::map<std::string, Words> words;
  std::vector<std::pair<std::string, std::string>> laws, regularizations;
  std::string free_laws, fixed;
  for (const CoefficientLaw* law : coefficient_laws()) {
    const LawDescription& d = law->description();
    laws.emplace_back(d.name, d.meaning);
    if (*law->fixed_regularization())
      fixed += std::string(fixed.empty() ? "" : "; ") + d.name + " is always `" +
               law->fixed_regularization() + "` and takes no value here";
    else
      free_laws += std::string(free_laws.empty() ? "" : " and ") + d.name;
  }
  for (const RegularizationLaw* reg : regularization_laws()) {
    std::string meaning = reg->description().meaning;
    for (const CoefficientLaw* law : coefficient_laws())
      if (reg->description().name == std::string(law->fixed_regularization()) &&
          *law->unregularized_law())
        meaning +=
            std::string("; ") + law->unregularized_law() + " with it is " + law->description().name;
    regularizations.emplace_back(reg->description().name, meaning);
  }
  words["/friction/law"] = {"", "the coefficient: " + listed_laws(laws) + "; docs/physics.md"};
  words["/friction/regularization"] = {"", "the normal stress seen by friction (" + free_laws +
                                               (fixed.empty() ? "" : "; ") + fixed +
                                               "): " + listed_laws(regularizations)};
  for (const FrictionField& field : friction_fields()) {
    words["/friction/" + field.name] = {field.unit, field.meaning};
    std::string who;
    for (const auto& name : field.laws)
      who += (who.empty() ? "" : ", ") + name;
    for (const auto& name : field.regularizations)
      who += (who.empty() ? "regularization " : ", regularization ") + name;
    words["/profiles/*/" + field.name] = {field.unit, field.name + " there (" + who + ")"};
  }
  for (const FrictionChoice& c : friction_choices())
    words["/friction/" + std::string(c.choice.name)] = {"", c.meaning};
  return words;
}

// The words of every field.
std::map<std::string, Words> field_words() {
  std::map<std::string, Words> words = fixed_words();
  for (auto& [pointer, w] : friction_words())
    words[pointer] = std::move(w);
  return words;
}

// The fields the reader asks for when it reads `document` (an empty job of one method).
SchemaRecorder record_fields(const nlohmann::json& document) {
  SchemaRecorder recorder;
  std::vector<FieldError> errors;
  ObjectReader reader(&document, "", errors, &recorder);
  JobSpec job;
  read_job_fields(reader, job);
  reader.finish();
  if (!errors.empty())
    throw std::logic_error("job schema: reading " + document.dump() + " gave " + errors[0].pointer +
                           ": " + errors[0].reason);
  return recorder;
}

// "/friction/L" -> {"friction", "L"}; "/threads" -> {"", "threads"}; a field of the items
// of an array of objects: "/profiles/*/mu" -> {"profiles/*", "mu"}.
std::pair<std::string, std::string> split_pointer(const std::string& pointer) {
  const auto slash = pointer.rfind('/');
  return {slash == 0 ? "" : pointer.substr(1, slash - 1), pointer.substr(slash + 1)};
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string type_text(const nlohmann::json& schema) {
  if (schema.contains("oneOf")) return "number or `\"auto\"`";
  const std::string type = schema.at("type");
  if (type == "array") return "array of " + schema["items"]["type"].get<std::string>() + "s";
  return type;
}

std::string default_text(const nlohmann::json& schema) {
  if (!schema.contains("default")) return "none";
  const nlohmann::json& value = schema.at("default");
  if (value.is_string() || value.is_array()) return "`" + value.dump() + "`";
  if (value.is_number_float()) return format_number(value.get<double>());
  return value.dump();
}

std::string allowed_text(const nlohmann::json& schema) {
  if (schema.contains("oneOf")) return "> 0, or `\"auto\"`";
  if (schema.contains("enum")) {
    std::string list;
    for (const auto& name : schema["enum"])
      list += (list.empty() ? "`" : ", `") + name.dump() + "`";
    return list;
  }
  const std::string type = schema.at("type");
  if (type == "integer")
    return std::to_string(schema["minimum"].get<long>()) + " .. " +
           std::to_string(schema["maximum"].get<long>());
  if (type == "string")
    return "at most " + std::to_string(schema["maxLength"].get<long>()) +
           " characters, no control characters";
  if (type == "array" && schema["items"]["type"] == "object")
    return "at most " + std::to_string(schema["maxItems"].get<long>()) + " entries";
  if (type == "array" && schema["items"]["type"] == "number") {
    const std::string each = allowed_text(schema["items"]);
    return "at most " + std::to_string(schema["maxItems"].get<long>()) + " numbers" +
           (each == "any" ? "" : ", each " + each);
  }
  if (type == "array")
    return "at most " + std::to_string(schema["maxItems"].get<long>()) +
           " non-empty strings of at most " +
           std::to_string(schema["items"]["maxLength"].get<long>()) +
           " characters, no control characters";
  if (type != "number") return "";
  const bool lo = schema.contains("minimum") || schema.contains("exclusiveMinimum");
  const bool hi = schema.contains("maximum") || schema.contains("exclusiveMaximum");
  const double lo_value = lo ? schema.value("minimum", schema.value("exclusiveMinimum", 0.0)) : 0;
  const double hi_value = hi ? schema.value("maximum", schema.value("exclusiveMaximum", 0.0)) : 0;
  const bool lo_open = schema.contains("exclusiveMinimum");
  const bool hi_open = schema.contains("exclusiveMaximum");
  if (lo && hi)
    return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo_value) + ", " +
           format_number(hi_value) + (hi_open ? ")" : "]");
  if (lo) return (lo_open ? "> " : ">= ") + format_number(lo_value);
  if (hi) return (hi_open ? "< " : "<= ") + format_number(hi_value);
  return "any";
}

} // namespace

bool JobField::read_by(std::string_view method) const {
  return std::find(methods.begin(), methods.end(), method) != methods.end();
}

std::vector<JobField> job_fields() {
  // The default method's record gives the defaults of the fields every method reads. The
  // fields of an elastic lower solid are read only when it is chosen: a record of each
  // method with it, after those on the rigid plane (where the method supports each).
  std::vector<std::pair<SchemaRecorder, std::string>> records;
  for (const bool elastic : {false, true})
    for (const MethodEntry* method : methods()) {
      if (!(elastic ? method->supports.two_solids : method->supports.rigid_base)) continue;
      const std::string name(method->method.name());
      nlohmann::json document = nlohmann::json::object();
      if (method != &default_method()) document["method"] = name;
      if (elastic) document["lower"] = {{"solid", "elastic"}};
      records.emplace_back(record_fields(document), name);
    }
  std::vector<JobField> fields;
  std::map<std::string, std::size_t> index;
  for (const auto& [record, method] : records) {
    for (const auto& r : record) {
      auto found = index.find(r.pointer);
      if (found == index.end()) {
        found = index.emplace(r.pointer, fields.size()).first;
        fields.push_back({r.pointer, r.schema, {}, "", ""});
      }
      if (!fields[found->second].read_by(method)) fields[found->second].methods.push_back(method);
    }
  }
  fields[index.at("/method")].schema["default"] = default_method().method.name();
  std::map<std::string, FieldWords> method_words;
  for (FieldWords& words : method_field_words())
    method_words[words.pointer] = words;
  const std::map<std::string, Words> all_words = field_words();
  for (JobField& field : fields) {
    // In the registry's order, whatever the order of the records.
    std::vector<std::string> ordered;
    for (const MethodEntry* method : methods())
      if (field.read_by(method->method.name())) ordered.emplace_back(method->method.name());
    field.methods = ordered;
    if (const auto words = all_words.find(field.pointer); words != all_words.end()) {
      field.unit = words->second.unit;
      field.meaning = words->second.meaning;
    } else if (const auto own = method_words.find(field.pointer); own != method_words.end()) {
      field.unit = own->second.unit;
      field.meaning = own->second.meaning;
    } else {
      throw std::logic_error("job schema: no unit and meaning for " + field.pointer +
                             " (api/job_schema.cpp, or the method's in api/job_methods.cpp)");
    }
  }
  return fields;
}

// Fields that only some choices of other fields use (the rules api/job_checks.cpp and the
// friction laws enforce): the schema says so as "x-when": {"pointer": the choosing field,
// "values": the choices that use it}, or a list of such conditions of which one must hold,
// and the web view's form shows the field only then.
struct Condition {
  std::string pointer;
  std::vector<std::string> values;
};
using UsedWhen = std::vector<Condition>;

std::map<std::string, UsedWhen> used_when() {
  const UsedWhen ellipse{{"/nucleation/type", {"ellipse"}}};
  const UsedWhen patch{{"/nucleation/type", {"overstressed_patch"}}};
  const UsedWhen perturbation{{"/nucleation/type", {"stress_perturbation"}}};
  const UsedWhen elastic_lower{{"/lower/solid", {"elastic"}}};
  std::map<std::string, UsedWhen> rules = {
      {"/nucleation/a", ellipse},
      {"/nucleation/b", ellipse},
      {"/nucleation/v", ellipse},
      {"/nucleation/alpha", ellipse},
      {"/nucleation/x1_min", patch},
      {"/nucleation/x1_max", patch},
      {"/nucleation/shear_stress", patch},
      {"/nucleation/x1", perturbation},
      {"/nucleation/radius", perturbation},
      {"/nucleation/shear_stress_increase", perturbation},
      {"/nucleation/rise_time", perturbation},
      {"/lower/density", elastic_lower},
      {"/lower/young_modulus", elastic_lower},
      {"/lower/poisson_ratio", elastic_lower},
      {"/lower/p_wave_speed", elastic_lower},
      {"/lower/s_wave_speed", elastic_lower},
      {"/lower/height", elastic_lower},
      {"/lower/bottom_boundary", elastic_lower},
  };
  // The friction fields, by the laws and regularisations that use them.
  auto rule = [](const std::vector<std::string>& laws, const std::vector<std::string>& regs) {
    UsedWhen when;
    if (!laws.empty()) when.push_back({"/friction/law", laws});
    if (!regs.empty()) when.push_back({"/friction/regularization", regs});
    return when;
  };
  std::vector<std::string> free_laws;
  for (const CoefficientLaw* law : coefficient_laws())
    if (!*law->fixed_regularization()) free_laws.push_back(law->description().name);
  rules["/friction/regularization"] = rule(free_laws, {});
  for (const FrictionField& field : friction_fields())
    rules["/friction/" + field.name] = rule(field.laws, field.regularizations);
  for (const FrictionChoice& c : friction_choices())
    rules["/friction/" + std::string(c.choice.name)] = rule(c.laws, c.regularizations);
  return rules;
}

nlohmann::json when_json(const UsedWhen& when) {
  auto one = [](const Condition& c) {
    return nlohmann::json{{"pointer", c.pointer}, {"values", c.values}};
  };
  if (when.size() == 1) return one(when.front());
  nlohmann::json any = nlohmann::json::array();
  for (const Condition& c : when)
    any.push_back(one(c));
  return any;
}

std::vector<std::string> documented_job_pointers() {
  std::vector<std::string> pointers;
  for (const auto& [pointer, words] : field_words())
    pointers.push_back(pointer);
  for (const FieldWords& words : method_field_words())
    pointers.push_back(words.pointer);
  return pointers;
}

std::string field_unit(const std::string& pointer) {
  const auto words = field_words().find(pointer);
  return words == field_words().end() ? std::string() : std::string(words->second.unit);
}

nlohmann::json job_json_schema() {
  nlohmann::json root = {
      {"$schema", "https://json-schema.org/draft/2020-12/schema"},
      {"$id", "/api/v1/schema/job.json"},
      {"title", "slipfront job"},
      {"description", "One simulation (docs/api-job-spec.md). Every field is optional "
                      "and defaults to the paper's scene; unknown fields are errors, and so are "
                      "fields the chosen method does not use (x-methods). x-order lists an "
                      "object's properties in the reader's order; x-when names the choice of "
                      "another field a field is used with."},
      {"type", "object"},
      {"additionalProperties", false},
      {"properties", nlohmann::json::object()}};
  const std::map<std::string, UsedWhen> rules = used_when();
  for (const JobField& field : job_fields()) {
    const auto [section, name] = split_pointer(field.pointer);
    nlohmann::json* parent = &root;
    if (section.size() > 2 && section.ends_with("/*")) { // a field of an array's items
      nlohmann::json& items = root["properties"][section.substr(0, section.size() - 2)]["items"];
      items["additionalProperties"] = false;
      parent = &items;
    } else if (!section.empty()) {
      nlohmann::json& object = root["properties"][section];
      if (object.is_null())
        object = {{"type", "object"},
                  {"additionalProperties", false},
                  {"properties", nlohmann::json::object()}};
      parent = &object;
    }
    nlohmann::json schema = field.schema;
    schema["description"] = field.meaning + (field.unit.empty() ? "" : " [" + field.unit + "]");
    if (!field.unit.empty()) schema["x-unit"] = field.unit;
    schema["x-methods"] = field.methods;
    if (auto rule = rules.find(field.pointer); rule != rules.end())
      schema["x-when"] = when_json(rule->second);
    (*parent)["properties"][name] = schema;
    // The reader's order (the one docs/api-job-spec.md shows): JSON objects have none.
    (*parent)["x-order"].push_back(name);
    if (parent != &root && !section.ends_with("/*") &&
        std::find(root["x-order"].begin(), root["x-order"].end(), section) == root["x-order"].end())
      root["x-order"].push_back(section);
  }
  // How a run is labelled by its friction (the web view and the client): each law's and
  // regularisation's label, {name} standing for a value of the friction section.
  nlohmann::json& friction = root["properties"]["friction"]["properties"];
  for (const CoefficientLaw* law : coefficient_laws())
    friction["law"]["x-labels"][law->description().name] = {
        {"label", law->description().label}, {"alone", law->description().label_alone}};
  for (const RegularizationLaw* reg : regularization_laws())
    friction["regularization"]["x-labels"][reg->description().name] = {
        {"label", reg->description().label}, {"alone", reg->description().label_alone}};
  for (const CoefficientLaw* law : coefficient_laws())
    if (*law->fixed_regularization())
      friction["law"]["x-fixed-regularization"][law->description().name] =
          law->fixed_regularization();
  // Not a field of the job but a shorthand for one (api/presets.hpp): expanded before the
  // fields are read, so it has no default and never appears in a stored spec.
  nlohmann::json names = nlohmann::json::array();
  for (const Preset& preset : presets())
    names.push_back(preset.name);
  root["properties"]["preset"] = {
      {"type", "string"},
      {"enum", names},
      {"description", "start from this preset (GET /api/v1/presets): the job is the preset's "
                      "spec with the other members merged over it (JSON merge patch, RFC 7396; "
                      "docs/presets.md)"},
      {"x-methods", method_names()}};
  // The methods' labels, for the views (api/job_methods.hpp).
  root["properties"]["method"]["x-labels"] = method_labels_json();
  return root;
}

std::string job_fields_markdown() {
  // The docs' order of sections; a section not listed here comes last.
  const std::vector<std::string> order = {
      "top level", "spectral_bi", "fe",         "material", "geometry", "lower", "loading",
      "friction",  "profiles/*",  "nucleation", "time",     "output",   "probe", "stations"};
  std::map<std::string, std::string> rows;
  std::vector<std::string> titles = order;
  for (const JobField& field : job_fields()) {
    const auto [section, name] = split_pointer(field.pointer);
    const std::string title = section.empty() ? "top level" : section;
    if (std::find(titles.begin(), titles.end(), title) == titles.end()) titles.push_back(title);
    std::string meaning = field.meaning;
    if (field.methods.size() < methods().size()) { // "(method `fe` only)"
      std::string names;
      for (const std::string& method : field.methods)
        names += (names.empty() ? "`" : ", `") + method + "`";
      meaning += (field.methods.size() == 1 ? " (method " : " (methods ") + names + " only)";
    }
    rows[title] += "| `" + name + "` | " + type_text(field.schema) + " | " +
                   default_text(field.schema) + " | " + allowed_text(field.schema) + " | " +
                   field.unit + " | " + meaning + " |\n";
  }
  std::string out;
  for (const std::string& title : titles) {
    if (!rows.contains(title)) continue;
    out += "<!-- generated: job fields " + title + " -->\n";
    out += "| field | type | default | allowed | unit | meaning |\n";
    out += "| --- | --- | --- | --- | --- | --- |\n";
    out += rows[title];
    out += "<!-- end generated -->\n\n";
  }
  return out;
}

} // namespace slipfront::api
