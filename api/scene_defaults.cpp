#include "api/scene_defaults.hpp"

#include "api/job_schema.hpp"
#include "api/number_text.hpp"
#include "solver/interface/nucleation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace slipfront::api {

namespace {

using Pointer = nlohmann::json::json_pointer;

// The paper's run keeps 800 samples: 16 s, one every 0.02 s.
constexpr double samples_per_run = 800.0;
// The derived arrest window is a tenth of the duration (an arrest in the first nine tenths of
// the run is seen), at most the time an S wave takes to cross the domain.
constexpr double arrest_windows_per_run = 10.0;
// The derived probes stand beyond the nucleation patch in the direction the shear load drives:
// the arrival probe two patch lengths beyond its end, the spectrum probe half a patch length
// (the paper's 11 m and 6 m beyond its 3.65 m patch), each at most a half and a quarter of
// the rest of the periodic domain away; a patch shorter than this many elements counts as
// that long.
constexpr double arrival_patch_lengths = 2.0;
constexpr double spectrum_patch_lengths = 0.5;
constexpr double shortest_patch_elements = 10.0;

std::string text(double value) {
  return number_text(value, 4);
}

bool has(const nlohmann::json& document, const std::string& pointer) {
  return document.is_object() && document.contains(Pointer(pointer));
}

// A value found from the scene and how.
struct Derived {
  double value;
  std::string how;
};

// The slip-speed scale of the uniform load, (|tau2_0| + |tau1_0|) / (rho c_s).
double load_slip_speed(const SimulationParams& p) {
  return p.material.particle_velocity(std::abs(p.loading.normal_stress) +
                                      std::abs(p.loading.shear_stress));
}

Derived front_threshold(const SimulationParams& p) {
  const SimulationParams paper;
  const double paper_speed = load_slip_speed(paper);
  const double speed = load_slip_speed(p);
  return {paper.probes.front_threshold * speed / paper_speed,
          "derived: the paper's " + text(paper.probes.front_threshold) +
              " m/s scaled by the load's slip-speed scale (|normal_stress| + |shear_stress|) / "
              "(rho c_s) = " +
              text(speed) + " m/s (the paper's " + text(paper_speed) + " m/s)"};
}

Derived arrest_window(const SimulationParams& p) {
  const double tenth = p.time.duration / arrest_windows_per_run;
  const double transit = p.geometry.width / p.material.s_wave_speed();
  if (transit < tenth)
    return {transit, "derived: the time an S wave takes to cross the domain, width / c_s = " +
                         text(p.geometry.width) + " m / " + text(p.material.s_wave_speed()) +
                         " m/s (less than a tenth of the duration)"};
  return {tenth, "derived: a tenth of the duration " + text(p.time.duration) + " s"};
}

Derived output_interval(const SimulationParams& p) {
  return {p.time.duration / samples_per_run, "derived: the duration " + text(p.time.duration) +
                                                 " s over the paper's " + text(samples_per_run) +
                                                 " samples"};
}

// x1 on the nearest interface node x_min + i dx, wrapped onto the periodic domain.
double on_node(const Geometry& g, double x1) {
  const double nodes = std::round(g.width * g.nodes_per_meter);
  double i = std::fmod(std::round((x1 - g.x_min) * g.nodes_per_meter), nodes);
  if (i < 0) i += nodes;
  return g.x_min + i / g.nodes_per_meter;
}

// A probe `patch_lengths` nucleation-patch lengths beyond the patch's end in the direction of
// the shear load (at most `share` of the rest of the domain away); without nucleation, from
// the middle of the domain with a quarter of its width as the length.
Derived probe(const SimulationParams& p, double patch_lengths, double share, const char* what) {
  const Geometry& g = p.geometry;
  const slipfront::Interval patch = nucleation_patch(p.nucleation);
  const bool none = !(patch.lo <= patch.hi);
  const double direction = p.loading.shear_stress < 0 ? -1.0 : 1.0;
  const double length =
      none ? g.width / 4
           : std::max(patch.hi - patch.lo, shortest_patch_elements / g.nodes_per_meter);
  const double end = none ? g.x_min + g.width / 2 : (direction > 0 ? patch.hi : patch.lo);
  const double rest = std::max(g.width - length, 0.0);
  const double distance = std::min(patch_lengths * length, share * rest);
  const double x1 = on_node(g, end + direction * distance);
  const std::string side = direction > 0 ? "+x1" : "-x1";
  if (none)
    return {x1, "derived: " + text(distance) + " m towards " + side +
                    " from the middle of the domain (no nucleation), on a node"};
  return {x1, "derived: " + std::string(what) + " " + text(distance) +
                  " m beyond the nucleation patch " + patch_text(patch) + " towards " + side +
                  " (the way the shear load drives), on a node"};
}

// One default that belongs to the scene's scale: its field, and how to find it.
struct SceneDefault {
  const char* pointer;
  double& (*field)(SimulationParams&);
  Derived (*derive)(const SimulationParams&);
};

// The defaults that only watch the run, derived for a material other than the paper's. The
// front threshold comes first: the stations' threshold follows it.
const SceneDefault measuring_defaults[] = {
    {"/probe/front_threshold",
     [](SimulationParams& p) -> double& { return p.probes.front_threshold; }, front_threshold},
    {"/time/arrest_window", [](SimulationParams& p) -> double& { return p.time.arrest_window; },
     arrest_window},
    {"/output/interval", [](SimulationParams& p) -> double& { return p.output.interval; },
     output_interval},
    {"/probe/arrival_x1", [](SimulationParams& p) -> double& { return p.probes.arrival_x1; },
     [](const SimulationParams& p) {
       return probe(p, arrival_patch_lengths, 0.5, "two patch lengths,");
     }},
    {"/probe/spectrum_x1", [](SimulationParams& p) -> double& { return p.probes.spectrum_x1; },
     [](const SimulationParams& p) {
       return probe(p, spectrum_patch_lengths, 0.25, "half a patch length,");
     }},
};

// Sets a derived value in the run's parameters and the canonical form; a value that is not
// finite and positive where it must be (an impossible material, which the limits of a run
// refuse) leaves the default.
bool set(JobSpec& job, const SceneDefault& d, const Derived& derived,
         std::map<std::string, std::string>& how) {
  if (!std::isfinite(derived.value)) return false;
  d.field(job.params) = derived.value;
  job.canonical[Pointer(d.pointer)] = derived.value;
  how[d.pointer] = derived.how;
  return true;
}

// The source of the field at `pointer`: given in the job, by its preset, derived, or the
// default.
std::string source_of(const std::string& pointer, const nlohmann::json& given,
                      const nlohmann::json& document,
                      const std::map<std::string, std::string>& derived) {
  if (has(given, pointer)) return "given";
  if (has(document, pointer)) return "preset " + given.value("preset", std::string());
  if (const auto d = derived.find(pointer); d != derived.end()) return d->second;
  return "default";
}

} // namespace

std::string patch_text(const slipfront::Interval& patch) {
  const double tiny = 1e-9 * std::abs(patch.hi - patch.lo);
  const auto end = [&](double x) { return text(std::abs(x) <= tiny ? 0.0 : x); };
  std::string out = "["; // built in steps: GCC 12 warns wrongly on "[" + std::string
  out += end(patch.lo) + ", " + end(patch.hi) + "] m";
  return out;
}

bool paper_material(const Material& m) {
  const Material paper;
  const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); };
  return same(m.density, paper.density) && same(m.young_modulus, paper.young_modulus) &&
         same(m.poisson_ratio, paper.poisson_ratio);
}

void apply_scene_defaults(const nlohmann::json& given, const nlohmann::json& document,
                          JobSpec& job) {
  std::map<std::string, std::string> derived;
  if (!paper_material(job.params.material)) {
    for (const SceneDefault& d : measuring_defaults) {
      if (!has(document, d.pointer)) set(job, d, d.derive(job.params), derived);
    }
  }
  // One threshold for the front and the stations unless the job gives both.
  const char* station_threshold = "/stations/rupture_threshold";
  if (!job.params.stations.x1.empty() && !has(document, station_threshold)) {
    const double front = job.params.probes.front_threshold;
    job.params.stations.rupture_threshold = front;
    job.canonical[Pointer(station_threshold)] = front;
    derived[station_threshold] =
        "derived: the front threshold probe.front_threshold = " + text(front) +
        " m/s (one threshold unless the job gives two)";
  }

  static const std::vector<JobField> fields = job_fields();
  job.provenance.clear();
  for (const JobField& field : fields) {
    if (field.unit.empty() || field.pointer.find('*') != std::string::npos) continue;
    if (!has(job.canonical, field.pointer)) continue;
    const nlohmann::json& value = job.canonical.at(Pointer(field.pointer));
    if (!value.is_number()) continue; // a height "auto", the stations' list
    job.provenance.push_back({field.pointer, value.get<double>(), field.unit,
                              source_of(field.pointer, given, document, derived)});
  }
}

nlohmann::json provenance_json(const std::vector<ValueSource>& provenance) {
  nlohmann::json list = nlohmann::json::array();
  for (const ValueSource& v : provenance)
    list.push_back(
        {{"pointer", v.pointer}, {"value", v.value}, {"unit", v.unit}, {"source", v.source}});
  return list;
}

} // namespace slipfront::api
