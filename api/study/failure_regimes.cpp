#include "api/study/failure_regimes.hpp"

#include "api/job_methods.hpp"
#include "api/number_text.hpp"
#include "api/study/run_rules.hpp"

#include <algorithm>

namespace slipfront::api {

const std::vector<Regime>& failure_regimes() {
  static const std::vector<Regime> regimes = {
      {"regularised",
       "simplified Prakash-Clifton, L = 5e-5 m (the paper's reference)",
       "well-posed: results agree under refinement",
       nlohmann::json::object(),
       5e-5,
       {10, 20}},
      {"coulomb",
       "plain Coulomb friction (friction.law = coulomb)",
       "ill-posed: no mesh convergence (paper §3)",
       {{"friction", {{"law", "coulomb"}}}},
       5e-5,
       {10, 20, 40}},
      {"explicit_euler",
       "explicit Euler strength update at small L (friction.strength_update = explicit_euler, "
       "L = 5e-6 m)",
       "unstable once dt (|V| + V*) / L > 2: diverged",
       {{"friction", {{"strength_update", "explicit_euler"}}}},
       5e-6,
       {10, 20}},
      {"unstable_time_step",
       "time step above the stable one (time.safety_factor = 1.2)",
       "central differences are unstable: diverged",
       {{"time", {{"safety_factor", 1.2}}}},
       5e-5,
       {10, 20}},
      {"mu_1.2",
       "friction coefficient mu = 1.2 (loading kept below mu |normal_stress|)",
       "ill-posed for a deformable-rigid interface (flutter/Adams-type instability); the run "
       "may not detect it: judged only by refinement",
       {{"friction", {{"mu", 1.2}}}},
       5e-5,
       {10, 20}},
      {"bimaterial_coulomb",
       "plain Coulomb friction between two different elastic solids (friction.law = coulomb, "
       "lower.solid = elastic with young_modulus 3.5: c_s 18 % above the upper solid's, as in "
       "the bimaterial presets)",
       "ill-posed between dissimilar solids (Adams 1995; Ranjith & Rice 2001): slip "
       "perturbations grow at a rate proportional to 1/dx, no mesh convergence",
       {{"friction", {{"law", "coulomb"}}},
        {"lower", {{"solid", "elastic"}, {"young_modulus", 3.5}}}},
       5e-5,
       {10, 20, 40}},
  };
  return regimes;
}

nlohmann::json regime_patch(const Regime& regime, const nlohmann::json& base) {
  nlohmann::json patch = regime.overrides;
  // A block method: the lower block as high as the base's upper one.
  const MethodEntry* method = find_method(method_name_of(base));
  const bool blocks = (method != nullptr ? *method : default_method()).supports.block_height;
  const auto geometry = base.find("geometry");
  if (patch.contains("lower") && blocks && geometry != base.end() && geometry->is_object() &&
      geometry->contains("height"))
    patch["lower"]["height"] = (*geometry)["height"];
  return patch;
}

std::string regime_finding(const std::vector<StudyRun>& runs,
                           const std::vector<RunConvergence>& statuses) {
  using Status = ConvergenceStatus;
  int diverged = 0, converged = 0, pending = 0, failed = 0;
  double finest = 0.0, converged_n_d = 0.0;
  for (const RunConvergence& s : statuses) {
    if (s.status == Status::diverged) ++diverged;
    if (s.status == Status::pending) ++pending;
    if (s.status == Status::failed) ++failed;
    if (s.status == Status::converged && (converged_n_d == 0.0 || s.n_d < converged_n_d))
      converged_n_d = s.n_d;
    if (s.status == Status::converged) ++converged;
    finest = std::max(finest, s.n_d);
  }
  const int n = static_cast<int>(statuses.size());
  if (pending > 0) return std::to_string(pending) + " of " + std::to_string(n) + " runs pending";
  if (diverged == n)
    return "detected: every run diverged (outcome diverged, job failed, no result file)";
  if (diverged > 0)
    return "detected: " + std::to_string(diverged) + " of " + std::to_string(n) + " runs diverged";
  const auto no_rupture = std::count_if(runs.begin(), runs.end(), [](const StudyRun& run) {
    return study_rules::outcome_of(run) == "no_rupture";
  });
  if (no_rupture == n)
    return "no rupture on any mesh: the meshes agree on 'nothing happens' (converged), so this "
           "run neither exercises nor detects an instability";
  if (converged > 0) return "mesh-converged at n_d = " + number_text(converged_n_d);
  if (failed == n) return "every run failed without a result";
  return "no mesh convergence up to n_d = " + number_text(finest) +
         " (not_converged/unknown): nothing flagged the run itself";
}

} // namespace slipfront::api
