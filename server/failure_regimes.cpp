#include "server/failure_regimes.hpp"

namespace slipfront::server {

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
  };
  return regimes;
}

} // namespace slipfront::server
