// The "failure_regimes" preset of POST /studies (docs/studies-api.md): the ways a rupture
// simulation fails, run next to the regularised reference so that the study shows what
// the service detects and what it does not.
#pragma once

#include "api/study/convergence.hpp"
#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slipfront::api {

struct Regime {
  std::string name;         // "regularised", "coulomb", ...
  std::string description;  // what is changed
  std::string expected;     // what the literature / the paper expects
  nlohmann::json overrides; // merged into the study's base spec (JSON merge patch)
  double L = 5e-5;          // friction.L of its runs
  std::vector<double> n_d;  // its meshes
};

// regularised (L = 5e-5, n_d 10/20), coulomb (n_d 10/20/40), explicit_euler (L = 5e-6,
// n_d 10/20), unstable_time_step (safety factor 1.2, n_d 10/20), mu_1.2 (n_d 10/20),
// bimaterial_coulomb (n_d 10/20/40).
const std::vector<Regime>& failure_regimes();

// The patch a regime's runs apply to the study's base: its overrides, and for a regime with a
// lower solid run by FE the lower block as high as the base's upper one (the schema's default
// height would make a small base's runs several times dearer than the others).
nlohmann::json regime_patch(const Regime& regime, const nlohmann::json& base);

// What the runs of one regime show, in one sentence, from the data only: `statuses` are
// convergence_statuses(runs), in the same order.
std::string regime_finding(const std::vector<StudyRun>& runs,
                           const std::vector<RunConvergence>& statuses);

} // namespace slipfront::api
