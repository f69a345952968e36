#include "api/scene_checks.hpp"

#include "api/number_text.hpp"
#include "api/scene_defaults.hpp"
#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"
#include "solver/interface/nucleation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace slipfront::api {

namespace {

// Stresses beyond this fraction of the shear modulus are strains linear elasticity does not
// describe; a load below the smaller fraction is a strain no earthquake or laboratory rupture
// has (the paper's: 0.015 of the modulus), most likely stresses and material in different
// units.
constexpr double max_stress_over_modulus = 0.1;
constexpr double min_stress_over_modulus = 1e-6;

std::string text(double value) {
  return number_text(value, 4);
}

bool warned(const std::vector<FieldWarning>& warnings, const std::string& pointer) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const FieldWarning& w) { return w.pointer == pointer; });
}

// Whether a friction law or regularisation of the run reads the number `name`.
bool reads(const LawDescription& law, const std::string& name, const Friction& friction) {
  return std::any_of(law.parameters.begin(), law.parameters.end(),
                     [&](const LawParameter& q) { return name == q.name && q.read_by(friction); });
}

// Whether the run reads the field at all (a friction number only its law or regularisation
// has: plain coulomb keeps L and v_star unused in its canonical form; a disabled nucleation
// keeps its fields).
bool read_by_run(const SimulationParams& p, const std::string& pointer) {
  const std::string friction = "/friction/";
  if (pointer.rfind(friction, 0) == 0) {
    const std::string name = pointer.substr(friction.size());
    return reads(coefficient_law(p.friction).description(), name, p.friction) ||
           reads(effective_regularization(p.friction).description(), name, p.friction);
  }
  if (pointer.rfind("/nucleation/", 0) == 0) return p.nucleation.enabled;
  return true;
}

std::string material_scale(const Material& m) {
  return "c_s = " + text(m.s_wave_speed()) + " m/s, shear modulus " + text(m.shear_modulus()) +
         " Pa";
}

// The paper's defaults of the physics kept for another material.
void paper_defaults_at_another_scale(const JobSpec& job, std::vector<FieldWarning>& out) {
  const SimulationParams& p = job.params;
  if (paper_material(p.material)) return;
  for (const ValueSource& v : job.provenance) {
    if (v.source != "default" || !read_by_run(p, v.pointer)) continue;
    out.push_back({v.pointer, "not given, so the paper's default " + text(v.value) + " " + v.unit +
                                  " applies: it is in the paper's scaled units (c_s = 1 m/s, "
                                  "shear modulus 1 Pa), not this material's (" +
                                  material_scale(p.material) + "); give the scene's value"});
  }
}

// A stress of the scene against the shear modulus of the solid above the interface.
struct Stress {
  std::string pointer;
  double value;
};

void stresses_against_modulus(const JobSpec& job, std::vector<FieldWarning>& out) {
  const SimulationParams& p = job.params;
  const double modulus = p.material.shear_modulus();
  std::vector<Stress> stresses = {{"/loading/normal_stress", p.loading.normal_stress},
                                  {"/loading/shear_stress", p.loading.shear_stress}};
  if (p.nucleation.patch())
    stresses.push_back({"/nucleation/shear_stress", p.nucleation.shear_stress});
  for (std::size_t i = 0; i < p.profiles.size(); ++i) {
    const std::string entry = "/profiles/" + std::to_string(i);
    if (p.profiles[i].shear_stress)
      stresses.push_back({entry + "/shear_stress", *p.profiles[i].shear_stress});
    if (p.profiles[i].normal_stress)
      stresses.push_back({entry + "/normal_stress", *p.profiles[i].normal_stress});
  }
  const auto largest = std::max_element(stresses.begin(), stresses.end(), [](auto& a, auto& b) {
    return std::abs(a.value) < std::abs(b.value);
  });
  if (std::abs(largest->value) > max_stress_over_modulus * modulus &&
      !warned(out, largest->pointer)) {
    out.push_back({largest->pointer,
                   text(largest->value) + " Pa is " + text(std::abs(largest->value) / modulus) +
                       " times the shear modulus " + text(modulus) +
                       " Pa of the material: strains of that size are beyond linear "
                       "elasticity, and stresses and material are likely in different units "
                       "(the paper's scene: |normal_stress| = 0.015 of the modulus)"});
  }
  const double load = std::max(std::abs(p.loading.normal_stress), std::abs(p.loading.shear_stress));
  const char* pointer = "/loading/normal_stress";
  if (load < min_stress_over_modulus * modulus && !warned(out, pointer)) {
    out.push_back(
        {pointer, "the load (largest of |normal_stress| and |shear_stress|: " + text(load) +
                      " Pa) is " + text(load / modulus) + " of the shear modulus " + text(modulus) +
                      " Pa, a strain no rupture has: stresses and material are likely "
                      "in different units (the paper's scene: 0.015 of the modulus)"});
  }
}

void process_zone_resolution(const JobSpec& job, std::vector<FieldWarning>& out) {
  const SimulationParams& p = job.params;
  const double zone = static_process_zone(p);
  if (!(zone > 0)) return; // NaN: the law does not weaken
  const double dx = 1.0 / p.geometry.nodes_per_meter;
  const double elements = zone / dx;
  if (elements >= min_process_zone_elements) return;
  out.push_back({"/geometry/nodes_per_meter",
                 std::string(coefficient_law(p.friction).weakening(p.friction)->formula) + " = " +
                     text(zone) + " m at rest, spans " + text(elements) +
                     " elements of dx = " + text(dx) +
                     " m, and it shrinks as the rupture speeds up; Day et al. (2005) resolve it "
                     "with " +
                     text(min_process_zone_elements) + " or more: nodes_per_meter at least " +
                     text(std::ceil(min_process_zone_elements / zone * 100) / 100)});
}

// What the job's friction law warns of (its scene_warnings: rate and state's velocity
// strengthening, for one), beside the law's field.
void law_warnings(const JobSpec& job, std::vector<FieldWarning>& out) {
  for (const LawWarning& w : coefficient_law(job.params.friction).scene_warnings(job.params))
    out.push_back({"/friction/" + w.field, w.message});
}

void arrest_window_room(const JobSpec& job, std::vector<FieldWarning>& out) {
  const TimeControl& t = job.params.time;
  const double quiet_from = nucleation_end_time(job.params.nucleation);
  if (t.arrest_window < t.duration - quiet_from) return;
  out.push_back({"/time/arrest_window",
                 "the front must stand still " + text(t.arrest_window) +
                     " s to count as arrested, but the run has " + text(t.duration - quiet_from) +
                     " s after the nucleation ends (duration " + text(t.duration) + " s" +
                     (quiet_from > 0 ? ", nucleation over at " + text(quiet_from) + " s" : "") +
                     "): it can never end `arrested`, and ends `running_at_end` even where slip "
                     "stops; give a shorter arrest_window"});
}

void probes_outside_patch(const JobSpec& job, std::vector<FieldWarning>& out) {
  const SimulationParams& p = job.params;
  const slipfront::Interval patch = nucleation_patch(p.nucleation);
  const auto inside = [&](double x1) { return x1 >= patch.lo && x1 <= patch.hi; };
  const std::string where = patch_text(patch);
  if (inside(p.probes.arrival_x1))
    out.push_back({"/probe/arrival_x1",
                   text(p.probes.arrival_x1) + " m lies inside the nucleation patch " + where +
                       ": the arrival there is the nucleation's, not the rupture's "
                       "(arrival_time_at_probe, and the convergence rule that compares it)"});
  if (inside(p.probes.spectrum_x1) && effective_regularization(p.friction).slip_filter())
    out.push_back({"/probe/spectrum_x1", text(p.probes.spectrum_x1) +
                                             " m lies inside the nucleation patch " + where +
                                             ": the strength recorded there is the nucleation's "
                                             "(spectral_critical_length)"});
  const std::vector<double>& stations = p.stations.x1;
  if (!stations.empty() && std::all_of(stations.begin(), stations.end(), inside))
    out.push_back({"/stations/x1", "every station lies inside the nucleation patch " + where +
                                       ": their rupture times are the nucleation's; put one "
                                       "beyond it to watch the rupture"});
}

void duration_against_nucleation(const JobSpec& job, std::vector<FieldWarning>& out) {
  const SimulationParams& p = job.params;
  const slipfront::Interval patch = nucleation_patch(p.nucleation);
  if (!(patch.lo <= patch.hi)) return;
  const double crossing = (patch.hi - patch.lo) / p.material.s_wave_speed();
  const double end = nucleation_end_time(p.nucleation);
  if (p.time.duration > std::max(crossing, end)) return;
  const std::string why =
      end >= crossing
          ? "the nucleation ellipse is over (at " + text(end) + " s)"
          : "an S wave crosses the nucleation patch (" + text(patch.hi - patch.lo) + " m / " +
                text(p.material.s_wave_speed()) + " m/s = " + text(crossing) + " s)";
  out.push_back({"/time/duration", "the run ends at " + text(p.time.duration) + " s, before " +
                                       why + ": no rupture can grow beyond the patch"});
}

} // namespace

double static_process_zone(const SimulationParams& p) {
  const auto weakening = coefficient_law(p.friction).weakening(p.friction);
  const double strength_drop = weakening ? weakening->drop * std::abs(p.loading.normal_stress) : 0;
  if (!(strength_drop > 0)) return std::numeric_limits<double>::quiet_NaN();
  const auto compliance = [](const Material& m) {
    return (1 - m.poisson_ratio) / m.shear_modulus();
  };
  const double lower = p.lower.elastic() ? compliance(p.lower.material) : 0.0; // rigid plane
  const double modulus = 2.0 / (compliance(p.material) + lower);
  return weakening->factor * modulus * weakening->distance / strength_drop;
}

std::vector<FieldWarning> scene_warnings(const JobSpec& job) {
  std::vector<FieldWarning> warnings;
  paper_defaults_at_another_scale(job, warnings);
  stresses_against_modulus(job, warnings);
  process_zone_resolution(job, warnings);
  law_warnings(job, warnings);
  arrest_window_room(job, warnings);
  probes_outside_patch(job, warnings);
  duration_against_nucleation(job, warnings);
  return warnings;
}

nlohmann::json warnings_json(const std::vector<FieldWarning>& warnings) {
  nlohmann::json list = nlohmann::json::array();
  for (const FieldWarning& w : warnings)
    list.push_back({{"pointer", w.pointer}, {"message", w.message}});
  return list;
}

} // namespace slipfront::api

namespace slipfront::api {

nlohmann::json resolution_json(const SimulationParams& params) {
  const double zone = static_process_zone(params);
  if (!(zone > 0)) return nullptr;
  return {{"process_zone", zone},
          {"elements", zone * params.geometry.nodes_per_meter},
          {"formula", coefficient_law(params.friction).weakening(params.friction)->formula}};
}

} // namespace slipfront::api
