// The cost model of the estimates (api/cost_estimate.hpp): the work each method counts before
// a run (a law of the slip rate adds its solves, predictor and corrector, and, by FE, makes the
// whole interface a source), the fit recovering known coefficients, and a model file of an older
// slipfront.
#include "api/cost_estimate.hpp"
#include "api/job_spec.hpp"
#include "solver/mesh_size.hpp"
#include "solver/simulation.hpp"

#include <gtest/gtest.h>

using nlohmann::json;
using slipfront::RunWork;
using slipfront::SimulationParams;
namespace api = slipfront::api;

namespace {

SimulationParams params_of(const json& job) {
  const api::ParseResult r = api::parse_job(job);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].pointer + ": " + r.errors[0].reason);
  return r.spec->params;
}

// The rate-and-state preset, and the same scene with slip weakening (its stresses, an
// overstressed patch: bench/rsf_step_cost.py's pair).
json rate_state_scene(const std::string& method) {
  return {{"preset", "rsf_slip_law_inplane"}, {"method", method}, {"time", {{"duration", 1.0}}}};
}
json slip_weakening_scene(const std::string& method) {
  json j = rate_state_scene(method);
  j["friction"] = {{"law", "slip_weakening"},
                   {"mu_s", 0.677},
                   {"mu_d", 0.525},
                   {"D_c", 0.4},
                   {"a", nullptr},
                   {"b", nullptr},
                   {"f0", nullptr},
                   {"v_star", nullptr},
                   {"theta", nullptr},
                   {"initial_slip_rate", nullptr},
                   {"state_evolution", nullptr},
                   {"initial_state", nullptr}};
  j["profiles"] =
      json::array({{{"x1_min", -9999.999}, {"x1_max", 9999.999}, {"shear_stress", 70e6}}});
  j["nucleation"] = {{"enabled", true},
                     {"type", "overstressed_patch"},
                     {"x1_min", -1499.999},
                     {"x1_max", 1499.999},
                     {"shear_stress", 81.6e6}};
  return j;
}

} // namespace

TEST(CostWork, ARateLawCountsItsSolvesInThePredictorAndEachCorrectorPass) {
  const RunWork fe = slipfront::estimated_work(params_of(rate_state_scene("fe")));
  EXPECT_EQ(fe.rate_solves, 2 * fe.interface_steps);
  const SimulationParams bi_params = params_of(rate_state_scene("spectral_bi"));
  const RunWork bi = slipfront::estimated_work(bi_params);
  EXPECT_EQ(bi.rate_solves, bi.interface_steps * (1 + bi_params.spectral.corrector_passes));
  for (const std::string method : {"fe", "spectral_bi"})
    EXPECT_EQ(slipfront::estimated_work(params_of(slip_weakening_scene(method))).rate_solves, 0)
        << method;
}

TEST(CostWork, ByFeALawThatSlidesFromTheStartLeavesNoQuietFarField) {
  // The same mesh and steps: slip weakening sweeps the nodes the patch's waves reach, rate and
  // state every node its own waves reach from the whole interface (over the whole 60 km width).
  const RunWork sw = slipfront::estimated_work(params_of(slip_weakening_scene("fe")));
  const SimulationParams p = params_of(rate_state_scene("fe"));
  const RunWork rs = slipfront::estimated_work(p);
  ASSERT_EQ(sw.steps, rs.steps);
  EXPECT_GT(rs.node_steps, 1.5 * sw.node_steps);
  // Both blocks are as high as the waves reach in the run ("auto"), so on average about half
  // of their rows, every column, is swept.
  const double all_nodes = double(slipfront::mesh_size(p).nx) *
                           (slipfront::mesh_size(p).ny + slipfront::lower_mesh_size(p).ny);
  EXPECT_LT(rs.node_steps, all_nodes * rs.steps);
  EXPECT_GT(rs.node_steps, 0.4 * all_nodes * rs.steps);
}

TEST(CostModel, TheFitRecoversTheCoefficientsOfExactTimings) {
  // Timings made from known coefficients: the fit (least squares, each >= 0) gives them back.
  const std::array<double, 5> truth{0.05, 4e-9, 0.0, 2e-7, 5e-7};
  std::vector<api::CostSample> samples;
  for (const json& job : {json{{"geometry", {{"nodes_per_meter", 10}}}},
                          json{{"geometry", {{"nodes_per_meter", 20}}}},
                          json{{"geometry", {{"nodes_per_meter", 40}}}}, rate_state_scene("fe"),
                          slip_weakening_scene("fe")}) {
    api::CostSample s;
    s.method = "fe";
    s.threads = 1;
    s.work = slipfront::estimated_work(params_of(job));
    const double x[5] = {1.0, s.work.node_steps, s.work.row_steps, s.work.interface_steps,
                         s.work.rate_solves};
    for (int t = 0; t < 5; ++t)
      s.wall_time_s += truth[t] * x[t];
    samples.push_back(s);
  }
  const api::CostModel model = api::fit_cost_model(samples);
  const auto k = model.at("fe", 1);
  ASSERT_TRUE(k);
  for (int t = 0; t < 5; ++t)
    EXPECT_NEAR(k->seconds[t], truth[t], 1e-6 * truth[t] + 1e-15) << "term " << t;
}

TEST(CostModel, AFileOfAnOlderSlipfrontTakesTheTermsItLacksFromTheBuiltInModel) {
  // Written before rate_solve_s and transform_step_s existed.
  const json old_file = {{"machine", "old"},
                         {"calibrated_at", "2026-11-01T00:00:00Z"},
                         {"coefficients",
                          {{"fe",
                            {{"1",
                              {{"setup_s", 0.5},
                               {"node_step_s", 1e-9},
                               {"row_step_s", 0.0},
                               {"interface_step_s", 1e-7}}}}},
                           {"spectral_bi",
                            {{"1",
                              {{"setup_s", 0.0},
                               {"lag_step_s", 1e-9},
                               {"lower_lag_step_s", 1e-9},
                               {"interface_step_s", 0.0}}}}}}}};
  std::string error;
  const auto model = api::CostModel::from_json(old_file, error);
  ASSERT_TRUE(model) << error;
  EXPECT_TRUE(model->outdated);
  const auto built_in = api::CostModel::built_in();
  EXPECT_EQ(model->at("fe", 1)->seconds[0], 0.5);                              // from the file
  EXPECT_EQ(model->at("fe", 1)->seconds[4], built_in.at("fe", 1)->seconds[4]); // rate_solve_s
  EXPECT_EQ(model->at("spectral_bi", 1)->seconds[2], built_in.at("spectral_bi", 1)->seconds[2]);

  json current = old_file;
  current["coefficients"]["fe"]["1"]["rate_solve_s"] = 1e-7;
  current["coefficients"]["spectral_bi"]["1"]["transform_step_s"] = 1e-8;
  current["coefficients"]["spectral_bi"]["1"]["rate_solve_s"] = 1e-7;
  const auto complete = api::CostModel::from_json(current, error);
  ASSERT_TRUE(complete) << error;
  EXPECT_FALSE(complete->outdated);
  EXPECT_EQ(complete->at("fe", 1)->seconds[4], 1e-7);
}
