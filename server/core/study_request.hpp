// The body of POST /api/v1/studies (docs/studies-api.md), parsed and checked: every bad
// field is reported by its JSON pointer, as for jobs. The job specs of the runs are checked
// later, by StudyService, with the job validator.
#pragma once

#include "api/job_spec.hpp"
#include "api/study/accuracy_target.hpp"
#include "api/study/l_search.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

enum class StudyKind { grid, convergence, failure_regimes, accuracy };
const char* to_string(StudyKind kind);
std::optional<StudyKind> parse_study_kind(const std::string& text);

struct StudyRequest {
  std::string name;
  std::vector<std::string> tags;
  StudyKind kind = StudyKind::grid;
  nlohmann::json base = nlohmann::json::object(); // job spec without friction.L, n_d
  std::vector<double> L;                          // grid / convergence
  std::vector<double> n_d;                        // grid: meshes; convergence: the ladder
  double n_d_max = 0.0;                           // convergence: the cap
  std::optional<api::LSearch> search;             // convergence without L: L holds its whole ladder
  std::optional<api::AccuracyTarget> accuracy;    // accuracy: L holds its one L, n_d the ladder
  std::string method_choice = "auto";             // accuracy: "auto" or a method's name
  std::optional<std::size_t> accuracy_start;      // accuracy: index in n_d of its first mesh
  std::optional<int> priority;
  std::optional<bool> fresh;
  nlohmann::json body; // the request as received
};

struct StudyRequestParse {
  std::optional<StudyRequest> request;
  std::vector<api::FieldError> errors;
};

// Limits that keep one request from flooding the queue.
constexpr std::size_t max_study_L = 50;
constexpr std::size_t max_study_n_d = 20;
constexpr std::size_t max_study_runs = 400;

StudyRequestParse parse_study_request(const nlohmann::json& body);

// How many tags /base/tags holds (each run carries them first, then the study's).
std::size_t base_tag_count(const StudyRequest& request);

// The job document of one run: base, then the regime's overrides (JSON merge patch), then
// friction.L and geometry.nodes_per_meter; name "<study name> L=<L> n_d=<n_d>" unless the
// base names its runs; tags: the base's, the study's and "study:<id>".
nlohmann::json run_document(const StudyRequest& request, const std::string& study_id,
                            const nlohmann::json& overrides, const std::string& regime, double L,
                            double n_d);

// An L search's unregularised runs (docs/studies-api.md "L search"): their regime ("coulomb",
// the name it has had since the paper's law, whose unregularised limit is plain Coulomb) and
// the merge patch that takes the regularisation of the base's friction away, keeping its
// coefficient (api::unregularized_patch: prakash_clifton -> coulomb, another law's
// regularization -> "none").
constexpr const char* coulomb_regime = "coulomb";
nlohmann::json coulomb_overrides(const nlohmann::json& base);
// What those runs are called for the reader: "plain Coulomb", or "<law> without
// regularisation" (api::unregularized_label of the base's friction).
std::string companion_label(const nlohmann::json& base);

// The default convergence ladder.
const std::vector<double>& default_ladder();

} // namespace slipfront::server
