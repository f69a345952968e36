// Speed and accuracy of the runs of a study (every result says how accurate it is and
// what it cost; docs/studies.md "Speed and accuracy"): cost against the errors relative to the
// reference run of each L, and the relative L2 error of a time record (docs/studies.md). Pure
// functions.
#pragma once

#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// Per finished run: cost and errors relative to the reference run of its L.
nlohmann::json speed_accuracy(const std::vector<StudyRun>& runs,
                              const ConvergenceTolerances& tol = {});

// As speed_accuracy, over the runs of two methods of one scene (FE and spectral_bi, in that
// order): each entry names its "method", and its errors are against the finest reference run
// of its L by either method (the second on a tie: spectral_bi), named by "reference_run_id"
// and "reference_method".
nlohmann::json speed_accuracy_across_methods(const MethodRuns& first, const MethodRuns& second,
                                             const ConvergenceTolerances& tol = {});

// ||v_a - v_ref|| / ||v_ref|| in L2 over time, on the samples of `a` that lie in the common
// time range; the reference is interpolated linearly onto them (trapezoidal rule).
// NaN when fewer than two samples of `a` lie in the common range or ||v_ref|| = 0.
// Throws std::invalid_argument on size mismatch or times that do not increase.
double relative_l2_error(const std::vector<double>& t_a, const std::vector<double>& v_a,
                         const std::vector<double>& t_ref, const std::vector<double>& v_ref);

// The slip-velocity record of a run at the spectrum probe (/probes/slip_velocity_spectrum;
// the server reads it from the result file).
struct ProbeSeries {
  std::vector<double> time;
  std::vector<double> slip_velocity;
  double x1 = 0.0; // the probe node's x1
};

// The probe record of a run by id; nullopt with the reason in `why` when it has none.
using ProbeSeriesReader =
    std::function<std::optional<ProbeSeries>(const std::string& run_id, std::string& why)>;

// Adds to speed_accuracy entries the relative L2 error of the run's slip-velocity record
// against its reference run's record: errors.slip_velocity_l2, null when undefined with the
// reason in slip_velocity_l2_unavailable; and job_id (the entry's id). Each run's record is
// read once, however many entries need it.
class SlipVelocityErrors {
public:
  explicit SlipVelocityErrors(ProbeSeriesReader read) : read_(std::move(read)) {}
  void add_to(nlohmann::json& entry);
  // x1 of the probe of the last reference record compared; NaN before the first.
  double probe_x1() const { return probe_x1_; }

private:
  const std::optional<ProbeSeries>& record_of(const std::string& run_id);

  ProbeSeriesReader read_;
  std::map<std::string, std::optional<ProbeSeries>> records_;
  std::map<std::string, std::string> why_;
  double probe_x1_ = not_available;
};

// One run of a study with its failure regime ("" outside the preset).
struct RegimeRun {
  std::string regime;
  StudyRun run;
};

// speed_accuracy of each regime's runs (regimes sorted by name, runs in the given order),
// each entry with "regime" (unless "") and its slip-velocity L2 error from `errors`.
nlohmann::json speed_accuracy_by_regime(const std::vector<RegimeRun>& runs,
                                        SlipVelocityErrors& errors);

} // namespace slipfront::api
