#include "api/run_bounds.hpp"

#include "api/job_methods.hpp"
#include "api/material_reader.hpp"
#include "api/number_text.hpp"
#include "solver/run/station_recorder.hpp"
#include "solver/simulation.hpp"
#include "solver/step_count.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace slipfront::api {

namespace {

// A field that the bounded quantities depend on, and how to give it the job's value.
struct Input {
  const char* pointer;
  void (*take)(SimulationParams& params, const SimulationParams& job);
};

// Every such field of the job outside the methods' sections (a field the job's method does not
// read changes nothing: never named).
const Input common_inputs[] = {
    {"/material/density",
     [](auto& p, const auto& job) { p.material.density = job.material.density; }},
    {"/material/young_modulus",
     [](auto& p, const auto& job) { p.material.young_modulus = job.material.young_modulus; }},
    {"/material/poisson_ratio",
     [](auto& p, const auto& job) { p.material.poisson_ratio = job.material.poisson_ratio; }},
    {"/geometry/nodes_per_meter",
     [](auto& p, const auto& job) { p.geometry.nodes_per_meter = job.geometry.nodes_per_meter; }},
    {"/time/duration", [](auto& p, const auto& job) { p.time.duration = job.time.duration; }},
    {"/time/safety_factor",
     [](auto& p, const auto& job) { p.time.safety_factor = job.time.safety_factor; }},
    {"/lower/density",
     [](auto& p, const auto& job) { p.lower.material.density = job.lower.material.density; }},
    {"/lower/young_modulus",
     [](auto& p, const auto& job) {
       p.lower.material.young_modulus = job.lower.material.young_modulus;
     }},
    {"/lower/poisson_ratio",
     [](auto& p, const auto& job) {
       p.lower.material.poisson_ratio = job.lower.material.poisson_ratio;
     }},
};

// The common fields, then each method's own (its section's: api/job_methods.hpp), in the
// registry's order.
std::vector<Input> inputs() {
  std::vector<Input> all(std::begin(common_inputs), std::end(common_inputs));
  for (const MethodEntry* method : methods())
    if (const MethodOptions* options = find_options(method->method))
      for (const StepInput& input : options->step_inputs)
        all.push_back({input.pointer, input.take});
  return all;
}

using Quantity = double (*)(const SimulationParams&);
enum class Direction { too_large, too_small };

// The field that, alone given the job's value in the paper's scene (with the job's method),
// moves `quantity` furthest in `direction`: the one an error about the quantity names.
const char* culprit(const SimulationParams& job, Quantity quantity, Direction direction) {
  SimulationParams scene;
  scene.method = job.method;
  scene.lower.side = job.lower.side; // a rigid plane's fields are never named
  const double base = std::log(quantity(scene));
  const char* named = common_inputs[0].pointer;
  double furthest = -std::numeric_limits<double>::infinity();
  for (const Input& input : inputs()) {
    SimulationParams one = scene;
    input.take(one, job);
    double shift = std::log(quantity(one)) - base; // +-inf where the quantity overflows or is 0
    if (direction == Direction::too_small) shift = -shift;
    if (std::isnan(shift)) shift = std::numeric_limits<double>::infinity();
    if (shift > furthest) {
      furthest = shift;
      named = input.pointer;
    }
  }
  return named;
}

std::string text(double value) {
  return number_text(value, 3);
}

// A solid whose wave speeds are bounded: the upper (`material`) or the lower (`lower`).
struct Solid {
  const char* pointer; // of its poisson_ratio
  Quantity s_wave_speed, p_wave_speed;
  Quantity p_impedance; // rho c_p: the dashpot of an absorbing boundary, the radiation damping
};
const Solid upper_solid = {
    "/material/poisson_ratio", [](const SimulationParams& p) { return p.material.s_wave_speed(); },
    [](const SimulationParams& p) { return p.material.p_wave_speed(); },
    [](const SimulationParams& p) { return p.material.density * p.material.p_wave_speed(); }};
const Solid lower_solid = {
    "/lower/poisson_ratio",
    [](const SimulationParams& p) { return p.lower.material.s_wave_speed(); },
    [](const SimulationParams& p) { return p.lower.material.p_wave_speed(); },
    [](const SimulationParams& p) {
      return p.lower.material.density * p.lower.material.p_wave_speed();
    }};

double shortest_step(const SimulationParams& p) {
  return time_step_bounds(p).shortest;
}
// The duration in units of the longest step the run could take.
double duration_in_steps(const SimulationParams& p) {
  return p.time.duration / time_step_bounds(p).longest;
}

bool finite_positive(double value) {
  return std::isfinite(value) && value > 0.0;
}

// c_s = sqrt(mu / rho) and c_p = sqrt((lambda + 2 mu) / rho) of a solid (docs/physics.md),
// finite and > 0, and so is rho c_p. False if not (the error is appended).
bool check_wave_speeds(const SimulationParams& p, const Solid& solid,
                       std::vector<FieldError>& errors) {
  const double c_s = solid.s_wave_speed(p), c_p = solid.p_wave_speed(p);
  const std::string speeds = "c_s = " + text(c_s) + " m/s, c_p = " + text(c_p) + " m/s";
  if (!finite_positive(c_s) || !finite_positive(c_p)) {
    const Quantity speed = finite_positive(c_s) ? solid.p_wave_speed : solid.s_wave_speed;
    const bool overflow = !std::isfinite(speed(p));
    errors.push_back({culprit(p, speed, overflow ? Direction::too_large : Direction::too_small),
                      "the wave speeds (" + speeds +
                          ") must be finite and > 0: young_modulus / density is " +
                          (overflow ? "too large" : "too small") + " for a double"});
    return false;
  }
  if (!std::isfinite(solid.p_impedance(p))) {
    errors.push_back({culprit(p, solid.p_impedance, Direction::too_large),
                      "the impedance density * c_p is not a finite number (" + speeds + ")"});
    return false;
  }
  // The method's own limit (its kernel's quadrature, say; solver/method_entry.hpp).
  const WaveSpeedLimit& limit = method_entry(p.method).wave_speeds;
  if (c_p / c_s > limit.max_ratio) {
    errors.push_back({solid.pointer, "c_p / c_s = " + text(c_p / c_s) + " is more than the " +
                                         text(limit.max_ratio) + " " + limit.why});
    return false;
  }
  return true;
}

// The time step and the number of steps (solver/simulation.hpp: time_step_bounds,
// step_count_bound), all in double: checked before anything becomes an integer.
void check_time_steps(const SimulationParams& p, std::vector<FieldError>& errors) {
  const TimeStepBounds dt = time_step_bounds(p);
  // A stable step found when the run starts is known within bounds; any other, exactly.
  const bool exact = !method_entry(p.method).time_step.safety_factor;
  if (!(dt.shortest >= min_time_step)) {
    errors.push_back({culprit(p, shortest_step, Direction::too_small),
                      "the time step would be " + std::string(exact ? "" : "as short as ") +
                          text(dt.shortest) + " s, less than the limit " + text(min_time_step) +
                          " s"});
    return;
  }
  const double steps = step_count_bound(p);
  if (!(steps <= max_run_steps)) {
    errors.push_back({culprit(p, step_count_bound, Direction::too_large),
                      "the run would take " + std::string(exact ? "" : "up to ") + text(steps) +
                          " time steps (duration " + text(p.time.duration) + " s / dt " +
                          text(dt.shortest) + " s), more than the limit " + text(max_run_steps)});
    return;
  }
  if (!(duration_in_steps(p) >= 1.0)) {
    errors.push_back({culprit(p, duration_in_steps, Direction::too_small),
                      "the duration " + text(p.time.duration) +
                          " s is shorter than one time step (" + (exact ? "dt = " : "dt up to ") +
                          text(dt.longest) + " s): the run would simulate nothing"});
  }
}

// The stations record every step: stations x steps within max_station_record_bytes. Call
// it after check_time_steps (the step count is then finite).
void check_station_record(const SimulationParams& p, std::vector<FieldError>& errors) {
  const double bytes = StationRecorder::record_bytes(p.stations, step_count_bound(p));
  if (bytes <= max_station_record_bytes) return;
  errors.push_back({"/stations/x1",
                    "the " + std::to_string(p.stations.x1.size()) + " stations would record " +
                        text(bytes / 1e9) + " GB over up to " + text(step_count_bound(p)) +
                        " time steps, more than the limit " + text(max_station_record_bytes / 1e9) +
                        " GB: use fewer stations or a shorter duration"});
}

} // namespace

void check_run_bounds(const JobSpec& job, std::vector<FieldError>& errors) {
  const SimulationParams& p = job.params;
  const std::size_t before = errors.size();
  if (check_wave_speeds(p, upper_solid, errors) &&
      (!p.lower.elastic() || check_wave_speeds(p, lower_solid, errors))) {
    const std::size_t steps_before = errors.size();
    check_time_steps(p, errors);
    if (errors.size() == steps_before) check_station_record(p, errors);
  }
  // A material given in wave speeds (api/material_reader.hpp): its E comes from c_s, its nu
  // from c_p / c_s.
  const bool speeds = job.canonical.is_object() &&
                      given_in_wave_speeds(job.canonical.value("material", nlohmann::json()));
  if (!speeds) return;
  for (std::size_t k = before; k < errors.size(); ++k) {
    std::string& pointer = errors[k].pointer;
    if (pointer == "/material/young_modulus") pointer = "/material/s_wave_speed";
    if (pointer == "/material/poisson_ratio") pointer = "/material/p_wave_speed";
  }
}

} // namespace slipfront::api
