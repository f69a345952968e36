// The cost of a run before it starts (docs/performance.md "Cost estimate"): its steps, time
// step and memory, and its wall time on this machine from a cost model calibrated here
// (`slipfront calibrate`, stored with the server as DATA_DIR/cost_model.json).
//
// The model times the work counts of solver/run_work.hpp, per method and thread count, as
// the method's entry names them (its cost_terms):
//   FE: wall = setup + node_step * node_steps + row_step * row_steps
//              + interface_step * interface_steps + rate_solve * rate_solves
//   BI: wall = setup + lag_step * lag_steps + transform_step * transform_steps
//              + interface_step * interface_steps + rate_solve * rate_solves
// (lag_steps: the history sums of every solid; transform_steps: steps x nx log2 nx per solid,
// the FFTs).
// Its coefficients are fitted to timed runs by least squares on the relative error, each
// coefficient >= 0.
#pragma once

#include "solver/params.hpp"
#include "solver/run_work.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// Seconds per unit of work of one method at one thread count: the set-up [s], then one per
// count of the method's work it times (its entry's cost_terms, solver/method_entry.hpp) [s].
struct CostCoefficients {
  std::array<double, 5> seconds{}; // {setup, then the method's four terms}
};

struct CostModel {
  // By method ("fe", "spectral_bi"), then by thread count.
  std::map<std::string, std::map<int, CostCoefficients>> coefficients;
  std::string machine;       // where it was calibrated (host name, cores)
  std::string calibrated_at; // ISO 8601
  std::string source;        // "built-in", or the file it was read from
  bool outdated = false;     // the file lacked terms of today's model (the built-in ones used)

  // The model measured on the development machine (docs/performance.md), for a server
  // that was never calibrated.
  static CostModel built_in();
  nlohmann::json to_json() const;
  // Reads a model written by to_json(); the reason in `error` if it cannot.
  static std::optional<CostModel> from_json(const nlohmann::json& json, std::string& error);
  // The model of a file written by `slipfront calibrate`, its source the path; throws
  // std::runtime_error saying why it cannot be read.
  static CostModel read_file(const std::string& path);
  // The coefficients for `method` at `threads` (the nearest calibrated count, scaled by the
  // ratio of the counts when it is not the same); nullptr when the method was never timed.
  std::optional<CostCoefficients> at(const std::string& method, int threads) const;
};

struct CostEstimate {
  double steps = 0;
  double dt = 0; // [s]
  double memory_bytes = 0;
  double wall_time_s = 0; // on this machine, to the whole duration
  int threads = 1;
  bool stops_on_arrest = false; // then the run may end earlier, and cost less
  std::string model;            // where the coefficients come from
};

// The wall time the model gives for `work` of `method` at `threads`; NaN without
// coefficients.
double modelled_wall_time(const CostModel& model, const std::string& method, int threads,
                          const RunWork& work);

// The estimate of a job (its threads: 0 = all hardware threads).
CostEstimate estimate_cost(const SimulationParams& params, double memory_bytes,
                           const CostModel& model);

nlohmann::json estimate_json(const CostEstimate& estimate);

// A wall time as people read it: "42 s", "3.5 min", "5.2 h", "2.1 days".
std::string wall_time_text(double seconds);

// A timed run for the fit.
struct CostSample {
  std::string method;
  int threads = 1;
  RunWork work; // up to the simulated time the run reached
  double wall_time_s = 0;
};

// Fits the coefficients of each method and thread count of `samples` (least squares on the
// relative error, every coefficient >= 0).
CostModel fit_cost_model(const std::vector<CostSample>& samples);

} // namespace slipfront::api
