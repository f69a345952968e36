// The study analysis (docs/metrics.md "Convergence status", "Critical length") on small synthetic
// metric sets (docs/studies.md). Over 400 lines on purpose: one short TEST per rule of
// docs/studies.md, grouped by section (scene hash, status, map, L_c, speed/accuracy, L2 error,
// refinement, cross-method).
#include "api/study_analysis.hpp"

#include "api/job_spec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using nlohmann::json;
using namespace slipfront::api;

namespace {

constexpr double never = not_available; // arrival_time_at_probe: front never reached the probe

// A finished run with the metrics the analysis reads; arrival NaN = front never reached.
StudyRun finished(const std::string& id, double L, double n_d, double distance, double arrival,
                  const std::string& outcome = "arrested") {
  json metrics = {{"outcome", outcome},
                  {"propagation_distance", distance},
                  {"arrival_time_at_probe", nullptr},
                  {"spectral_critical_length", nullptr}};
  if (std::isfinite(arrival)) metrics["arrival_time_at_probe"] = arrival;
  return {id, L, n_d, JobStatus::succeeded, metrics, 10.0 * n_d, 1e6 * n_d};
}

StudyRun without_result(const std::string& id, double L, double n_d, const std::string& status) {
  return {id, L, n_d, parse_status(status).value(), std::nullopt, 0.0, 0.0};
}

// As the server stores it: job failed, metrics with outcome "diverged".
StudyRun diverged(const std::string& id, double L, double n_d) {
  StudyRun run = finished(id, L, n_d, never, never, "diverged");
  run.status = JobStatus::failed;
  return run;
}

StudyRun no_rupture(const std::string& id, double L, double n_d) {
  return finished(id, L, n_d, 0.4, never, "no_rupture");
}

const RunConvergence& status_of(const std::vector<RunConvergence>& all, const std::string& id) {
  for (const RunConvergence& s : all)
    if (s.run_id == id) return s;
  throw std::runtime_error("no status for " + id);
}

ConvergenceStatus status(const std::vector<StudyRun>& runs, const std::string& id) {
  return status_of(convergence_statuses(runs), id).status;
}

// Paper §3.1 (Fig. 3): L = 5e-5 at n_d 20/40/80. 20 -> 40 changes the arrival time by
// 0.28 %; 40 -> 80 changes it by 0.055 % and the distance by 0.18 %.
std::vector<StudyRun> paper_like_runs() {
  const double d80 = 14.0, t80 = 9.0;
  const double d40 = d80 * 1.0018, t40 = t80 * 1.00055;
  return {finished("r20", 5e-5, 20, d40 * 1.001, t40 * 1.0028), finished("r40", 5e-5, 40, d40, t40),
          finished("r80", 5e-5, 80, d80, t80)};
}

// A converged pair (n_d 20, 40) for L with the given metrics of the finer mesh.
std::vector<StudyRun> converged_pair(const std::string& tag, double L, double distance,
                                     double arrival, const std::string& outcome = "arrested") {
  return {finished(tag + "-20", L, 20, distance * 1.001, arrival * 1.0002, outcome),
          finished(tag + "-40", L, 40, distance, arrival, outcome)};
}

std::vector<StudyRun> joined(std::initializer_list<std::vector<StudyRun>> parts) {
  std::vector<StudyRun> all;
  for (const auto& part : parts)
    all.insert(all.end(), part.begin(), part.end());
  return all;
}

json canonical(const json& job) {
  const auto parsed = parse_job(job);
  EXPECT_TRUE(parsed.ok());
  return parsed.ok() ? parsed.spec->canonical : json();
}

} // namespace

// ---- scene_hash -------------------------------------------------------------------------------

TEST(SceneHash, IgnoresLMeshOutputNameTagsThreads) {
  const std::string base = scene_hash(canonical(json::object()));
  EXPECT_EQ(base.size(), 64u);
  EXPECT_EQ(scene_hash(canonical({{"friction", {{"L", 1e-5}}},
                                  {"geometry", {{"nodes_per_meter", 80}}},
                                  {"output", {{"interval", 0.1}}},
                                  {"name", "other"},
                                  {"tags", {"a"}},
                                  {"threads", 2}})),
            base);
}

TEST(SceneHash, PhysicsOutsideLAndMeshChangesIt) {
  const std::string base = scene_hash(canonical(json::object()));
  EXPECT_NE(scene_hash(canonical({{"friction", {{"mu", 0.7}}}})), base);
  EXPECT_NE(scene_hash(canonical({{"geometry", {{"width", 30}}}})), base);
  EXPECT_NE(scene_hash(canonical({{"probe", {{"arrival_x1", 10}}}})), base);
  EXPECT_NE(scene_hash(canonical({{"friction", {{"v_star", 2e-4}}}})), base);
}

TEST(SceneHash, DiffersFromSpecHashWhichKeepsL) {
  const json spec = canonical(json::object());
  EXPECT_NE(scene_hash(spec), spec_hash(spec));
}

// ---- convergence status ---------------------------------------------------------------------

TEST(ConvergenceStatus, NamesAreThoseOfTheApi) {
  EXPECT_EQ(to_string(ConvergenceStatus::converged), "converged");
  EXPECT_EQ(to_string(ConvergenceStatus::not_converged), "not_converged");
  EXPECT_EQ(to_string(ConvergenceStatus::unknown), "unknown");
  EXPECT_EQ(to_string(ConvergenceStatus::diverged), "diverged");
  EXPECT_EQ(to_string(ConvergenceStatus::pending), "pending");
  EXPECT_EQ(to_string(ConvergenceStatus::failed), "failed");
}

TEST(ConvergenceStatus, PaperLikeLadder) {
  const auto all = convergence_statuses(paper_like_runs());
  ASSERT_EQ(all.size(), 3u);
  const auto& r20 = status_of(all, "r20");
  EXPECT_EQ(r20.status, ConvergenceStatus::not_converged) << r20.reason;
  EXPECT_EQ(r20.partner_n_d, 40);
  EXPECT_EQ(r20.partner_id, "r40");
  EXPECT_NEAR(r20.arrival_time_change, 0.0028, 1e-12);
  EXPECT_NEAR(r20.propagation_distance_change, 0.001, 1e-12);

  const auto& r40 = status_of(all, "r40");
  EXPECT_EQ(r40.status, ConvergenceStatus::converged) << r40.reason;
  EXPECT_EQ(r40.partner_n_d, 80);
  EXPECT_NEAR(r40.arrival_time_change, 0.00055, 1e-12);
  EXPECT_NEAR(r40.propagation_distance_change, 0.0018, 1e-12);

  const auto& r80 = status_of(all, "r80");
  EXPECT_EQ(r80.status, ConvergenceStatus::unknown);
  EXPECT_TRUE(std::isnan(r80.partner_n_d));
  EXPECT_TRUE(std::isnan(r80.arrival_time_change));
}

TEST(ConvergenceStatus, ResultIsInTheOrderOfTheRuns) {
  auto runs = paper_like_runs();
  std::swap(runs[0], runs[2]);
  const auto all = convergence_statuses(runs);
  EXPECT_EQ(all[0].run_id, "r80");
  EXPECT_EQ(all[2].run_id, "r20");
  EXPECT_EQ(all[2].status, ConvergenceStatus::not_converged);
}

TEST(ConvergenceStatus, DistanceAloneCanFailTheCriterion) {
  const std::vector<StudyRun> runs = {finished("a", 1e-4, 20, 14.0 * 1.006, 9.0),
                                      finished("b", 1e-4, 40, 14.0, 9.0)};
  EXPECT_EQ(status(runs, "a"), ConvergenceStatus::not_converged);
}

TEST(ConvergenceStatus, TolerancesAreTheCallers) {
  const std::vector<StudyRun> runs = {finished("a", 1e-4, 20, 14.0 * 1.006, 9.0),
                                      finished("b", 1e-4, 40, 14.0, 9.0)};
  ConvergenceTolerances loose;
  loose.propagation_distance = 0.01;
  EXPECT_EQ(status_of(convergence_statuses(runs, loose), "a").status, ConvergenceStatus::converged);
}

TEST(ConvergenceStatus, PartnerIsTheNextFinerMeshPresentOfTheSameL) {
  const std::vector<StudyRun> runs = {
      finished("a20", 1e-4, 20, 14.0, 9.0), finished("b40", 5e-5, 40, 14.0, 9.0), // other L
      finished("a160", 1e-4, 160, 15.0, 9.5), finished("a80", 1e-4, 80, 14.0, 9.0)};
  const auto a20 = status_of(convergence_statuses(runs), "a20");
  EXPECT_EQ(a20.partner_id, "a80");
  EXPECT_EQ(a20.status, ConvergenceStatus::converged);
  EXPECT_EQ(status(runs, "b40"), ConvergenceStatus::unknown);
  EXPECT_EQ(status(runs, "a80"), ConvergenceStatus::not_converged);
}

TEST(ConvergenceStatus, QueuedOrRunningIsPendingAndMakesItsCoarserPartnerUnknown) {
  const std::vector<StudyRun> runs = {
      finished("a20", 1e-4, 20, 14.0, 9.0), without_result("a40", 1e-4, 40, "running"),
      without_result("a80", 1e-4, 80, "queued"), finished("a160", 1e-4, 160, 14.0, 9.0)};
  const auto all = convergence_statuses(runs);
  EXPECT_EQ(status_of(all, "a40").status, ConvergenceStatus::pending);
  EXPECT_EQ(status_of(all, "a80").status, ConvergenceStatus::pending);
  const auto& a20 = status_of(all, "a20");
  EXPECT_EQ(a20.status, ConvergenceStatus::unknown); // not judged against 160 meanwhile
  EXPECT_EQ(a20.partner_n_d, 40);
}

TEST(ConvergenceStatus, FailedOrCancelledIsFailedAndSkippedAsPartner) {
  const std::vector<StudyRun> runs = {
      finished("a20", 1e-4, 20, 14.0, 9.0), without_result("a40", 1e-4, 40, "failed"),
      without_result("a40b", 1e-4, 40, "cancelled"), finished("a80", 1e-4, 80, 14.0, 9.0)};
  const auto all = convergence_statuses(runs);
  EXPECT_EQ(status_of(all, "a40").status, ConvergenceStatus::failed);
  EXPECT_EQ(status_of(all, "a40b").status, ConvergenceStatus::failed);
  EXPECT_EQ(status_of(all, "a20").partner_n_d, 80);
  EXPECT_EQ(status_of(all, "a20").status, ConvergenceStatus::converged);
}

TEST(ConvergenceStatus, DivergedRunIsDivergedAndItsCoarserPartnerNotConverged) {
  const std::vector<StudyRun> runs = {finished("a20", 1e-6, 20, 14.0, 9.0),
                                      diverged("a40", 1e-6, 40),
                                      finished("a80", 1e-6, 80, 14.0, 9.0)};
  const auto all = convergence_statuses(runs);
  EXPECT_EQ(status_of(all, "a40").status, ConvergenceStatus::diverged);
  EXPECT_EQ(status_of(all, "a20").status, ConvergenceStatus::not_converged);
  EXPECT_EQ(status_of(all, "a20").partner_n_d, 40); // a diverged run is a result, not skipped
}

TEST(ConvergenceStatus, DivergedWhateverItsPartner) {
  const std::vector<StudyRun> runs = {diverged("a20", 1e-6, 20),
                                      finished("a40", 1e-6, 40, 14.0, 9.0)};
  EXPECT_EQ(status(runs, "a20"), ConvergenceStatus::diverged);
}

TEST(ConvergenceStatus, NoRuptureInBothIsConverged) {
  const std::vector<StudyRun> runs = {no_rupture("a20", 1e-3, 20), no_rupture("a40", 1e-3, 40)};
  EXPECT_EQ(status(runs, "a20"), ConvergenceStatus::converged);
}

TEST(ConvergenceStatus, RuptureOnOneSideOfTheNoRuptureSeamIsNotConverged) {
  const std::vector<StudyRun> coarse_ruptures = {finished("a20", 5e-4, 20, 3.0, never),
                                                 no_rupture("a40", 5e-4, 40)};
  EXPECT_EQ(status(coarse_ruptures, "a20"), ConvergenceStatus::not_converged);
  const std::vector<StudyRun> fine_ruptures = {no_rupture("a20", 5e-4, 20),
                                               finished("a40", 5e-4, 40, 3.0, never)};
  EXPECT_EQ(status(fine_ruptures, "a20"), ConvergenceStatus::not_converged);
}

TEST(ConvergenceStatus, FrontNeverAtTheProbeInEitherIsJudgedOnDistance) {
  const std::vector<StudyRun> agree = {finished("a", 2e-4, 20, 8.0 * 1.002, never),
                                       finished("b", 2e-4, 40, 8.0, never)};
  const auto a = status_of(convergence_statuses(agree), "a");
  EXPECT_EQ(a.status, ConvergenceStatus::converged) << a.reason;
  EXPECT_TRUE(std::isnan(a.arrival_time_change));
  const std::vector<StudyRun> differ = {finished("a", 2e-4, 20, 8.0 * 1.01, never),
                                        finished("b", 2e-4, 40, 8.0, never)};
  EXPECT_EQ(status(differ, "a"), ConvergenceStatus::not_converged);
}

TEST(ConvergenceStatus, FrontAtTheProbeInOneRunOnlyIsNotConverged) {
  const std::vector<StudyRun> runs = {finished("a", 2e-4, 20, 12.0, 10.9),
                                      finished("b", 2e-4, 40, 12.0, never)};
  EXPECT_EQ(status(runs, "a"), ConvergenceStatus::not_converged);
}

TEST(ConvergenceStatus, ArrestedVersusRunningAtEndIsNotConverged) {
  const std::vector<StudyRun> runs = {finished("a", 2e-4, 20, 12.0, 9.0, "running_at_end"),
                                      finished("b", 2e-4, 40, 12.0, 9.0, "arrested")};
  EXPECT_EQ(status(runs, "a"), ConvergenceStatus::not_converged);
}

TEST(ConvergenceStatus, SucceededWithoutMetricsIsFailed) {
  const std::vector<StudyRun> runs = {without_result("a", 2e-4, 20, "succeeded")};
  EXPECT_EQ(status(runs, "a"), ConvergenceStatus::failed);
}

// ---- convergence map ----------------------------------------------------------------------

TEST(ConvergenceMap, GridCellsAndCoarsestConvergedMesh) {
  auto runs = paper_like_runs();
  runs.push_back(finished("s20", 5e-6, 20, 13.0, 8.0));
  runs.push_back(finished("s10", 5e-6, 10, 13.5, 8.5));
  runs.push_back(finished("zdup40", 5e-5, 40, 99.0, 99.0)); // duplicate: larger id loses
  const json map = convergence_map(runs);
  EXPECT_EQ(map["L"], json({5e-6, 5e-5}));
  EXPECT_EQ(map["n_d"], json({10, 20, 40, 80}));
  ASSERT_EQ(map["cells"].size(), 5u); // (5e-6, 40) and (5e-6, 80) were not run: omitted
  const json& first = map["cells"][0];
  EXPECT_EQ(first["L"], 5e-6);
  EXPECT_EQ(first["n_d"], 10);
  EXPECT_EQ(first["status"], "not_converged");
  const json& cell40 = map["cells"][3];
  EXPECT_EQ(cell40["n_d"], 40);
  EXPECT_EQ(cell40["run_id"], "r40");
  EXPECT_EQ(cell40["run_ids"], json({"r40", "zdup40"}));
  EXPECT_EQ(cell40["status"], "converged");
  EXPECT_NEAR(cell40["changes"]["arrival_time"].get<double>(), 0.00055, 1e-12);
  EXPECT_EQ(map["cells"][4]["status"], "unknown");
  EXPECT_TRUE(map["cells"][4]["changes"]["arrival_time"].is_null());
  EXPECT_EQ(map["converged_n_d"]["5e-05"], 40); // keyed by the JSON text of L
  EXPECT_TRUE(map["converged_n_d"][json(5e-6).dump()].is_null());
}

TEST(ConvergenceMap, EmptyStudy) {
  const json map = convergence_map({});
  EXPECT_EQ(map["cells"], json::array());
  EXPECT_EQ(map["L"], json::array());
}

// ---- critical length ----------------------------------------------------------------------

TEST(CriticalLength, FoundWhereTheLargerLDiffers) {
  auto runs =
      joined({converged_pair("a", 5e-6, 14.00, 9.000), converged_pair("b", 1e-5, 14.03, 9.005),
              converged_pair("c", 5e-5, 14.50, 9.100)});
  runs[1].metrics->operator[]("spectral_critical_length") = 1.7e-5;
  const json result = critical_length(runs);
  EXPECT_EQ(result["L_c"], 1e-5) << result.dump(2);
  EXPECT_EQ(result["next_larger_L"], 5e-5);
  EXPECT_EQ(result["spectral_critical_length"], 1.7e-5);
  EXPECT_EQ(result["spectral_from_L"], 5e-6);
  EXPECT_EQ(result["spectral_run_id"], "a-40");
  ASSERT_EQ(result["references"].size(), 3u);
  EXPECT_EQ(result["references"][0]["run_id"], "a-40"); // the finest run of the L
  EXPECT_EQ(result["references"][1]["agrees_with_every_smaller_L"], true);
  EXPECT_EQ(result["references"][2]["agrees_with_every_smaller_L"], false);
  ASSERT_EQ(result["comparisons"].size(), 3u); // every pair
  EXPECT_EQ(result["comparisons"][0]["smaller_L"], 5e-6);
  EXPECT_EQ(result["comparisons"][0]["agree"], true);
  EXPECT_NEAR(result["comparisons"][0]["changes"]["propagation_distance"].get<double>(),
              0.03 / 14.0, 1e-12); // relative to the smaller L
}

TEST(CriticalLength, LWithoutConvergedRunIsExcluded) {
  auto runs =
      joined({converged_pair("a", 5e-6, 14.00, 9.000), converged_pair("b", 1e-5, 14.03, 9.005),
              converged_pair("c", 5e-5, 14.50, 9.100)});
  runs.push_back(finished("d", 1e-6, 80, 20.0, 5.0)); // alone: unknown, would disagree
  runs.push_back(finished("e", 1e-4, 20, 14.0, 9.0));
  runs.push_back(finished("e2", 1e-4, 40, 15.0, 9.5)); // not converged
  const json result = critical_length(runs);
  EXPECT_EQ(result["L_c"], 1e-5);
  ASSERT_EQ(result["excluded"].size(), 2u);
  EXPECT_EQ(result["excluded"][0]["L"], 1e-6);
  EXPECT_EQ(result["excluded"][1]["L"], 1e-4);
  EXPECT_EQ(result["spectral_from_L"], 5e-6);
}

TEST(CriticalLength, ReferenceIsTheFinestResultOfAConvergedL) {
  auto runs = paper_like_runs(); // 40 converged against 80: the reference is 80
  runs.push_back(diverged("r160", 5e-5, 160));
  const json result = critical_length(runs);
  EXPECT_EQ(result["references"][0]["run_id"], "r80");
}

TEST(CriticalLength, AgreementMustHoldAmongEverySmallerL) {
  // 5e-6 ~ 1e-5; 2e-5 differs from 5e-6 by 0.6 % (though only 0.3 % from 1e-5); 5e-5 is
  // within 0.4 % of all three. L <= L_c must all agree pairwise: L_c = 1e-5.
  const auto runs =
      joined({converged_pair("a", 5e-6, 14.000, 9.0), converged_pair("b", 1e-5, 14.042, 9.0),
              converged_pair("c", 2e-5, 14.084, 9.0), converged_pair("d", 5e-5, 14.049, 9.0)});
  const json result = critical_length(runs);
  EXPECT_EQ(result["L_c"], 1e-5) << result.dump(2);
  EXPECT_EQ(result["next_larger_L"], 2e-5);
  EXPECT_EQ(result["references"][3]["agrees_with_every_smaller_L"], true);
}

TEST(CriticalLength, NoRuptureAtLargeLDiffers) {
  const auto runs =
      joined({converged_pair("a", 5e-6, 14.0, 9.0), converged_pair("b", 1e-5, 14.0, 9.0),
              converged_pair("c", 1e-3, 0.4, never, "no_rupture")});
  const json result = critical_length(runs);
  EXPECT_EQ(result["L_c"], 1e-5);
  EXPECT_EQ(result["comparisons"][1]["reason"], "outcome no_rupture vs arrested");
}

TEST(CriticalLength, NullWhenTheTwoSmallestDisagree) {
  const auto runs =
      joined({converged_pair("a", 5e-6, 14.0, 9.0), converged_pair("b", 1e-5, 14.5, 9.0)});
  const json result = critical_length(runs);
  EXPECT_TRUE(result["L_c"].is_null());
  EXPECT_EQ(result["next_larger_L"], 1e-5);
}

TEST(CriticalLength, NullWithOneConvergedL) {
  const json result = critical_length(converged_pair("a", 5e-6, 14.0, 9.0));
  EXPECT_TRUE(result["L_c"].is_null());
  EXPECT_NE(result["reason"].get<std::string>().find("at least two"), std::string::npos);
  EXPECT_EQ(result["spectral_from_L"], 5e-6);
}

TEST(CriticalLength, EveryLAgreeingGivesTheLargestAsALowerBound) {
  const auto runs =
      joined({converged_pair("a", 5e-6, 14.0, 9.0), converged_pair("b", 1e-5, 14.01, 9.001)});
  const json result = critical_length(runs);
  EXPECT_EQ(result["L_c"], 1e-5);
  EXPECT_TRUE(result["next_larger_L"].is_null());
  EXPECT_NE(result["reason"].get<std::string>().find("at least"), std::string::npos);
}

// ---- speed / accuracy ---------------------------------------------------------------------

TEST(SpeedAccuracy, ErrorsRelativeToTheFinestRunOfAConvergedL) {
  auto runs = paper_like_runs();
  runs.push_back(finished("u20", 1e-6, 20, 10.0, 9.0)); // L without a converged run
  runs.push_back(without_result("q", 1e-6, 40, "queued"));
  runs.push_back(diverged("x", 1e-6, 80));
  const json list = speed_accuracy(runs);
  ASSERT_EQ(list.size(), 5u); // the queued run has no result
  EXPECT_EQ(list[0]["id"], "r20");
  EXPECT_EQ(list[0]["reference_run_id"], "r80");
  EXPECT_EQ(list[0]["wall_time_s"], 200.0);
  EXPECT_EQ(list[0]["memory_bytes"], 2e7);
  EXPECT_NEAR(list[0]["errors"]["arrival_time"].get<double>(), 1.00055 * 1.0028 - 1.0, 1e-12);
  EXPECT_NEAR(list[1]["errors"]["propagation_distance"].get<double>(), 0.0018, 1e-12);
  EXPECT_EQ(list[2]["errors"]["arrival_time"], 0.0);
  EXPECT_TRUE(list[3]["reference_run_id"].is_null());
  EXPECT_TRUE(list[3]["errors"]["arrival_time"].is_null());
  EXPECT_EQ(list[4]["outcome"], "diverged");
  EXPECT_TRUE(list[4]["errors"]["propagation_distance"].is_null());
}

TEST(SpeedAccuracy, NoRuptureAgainstNoRuptureHasNoDistanceError) {
  // no_rupture runs may carry the slip of the nucleation patch (0.4 m here, 0.5 m in the
  // reference): that is not a propagation distance to compare.
  std::vector<StudyRun> runs = {no_rupture("n10", 1e-3, 10), no_rupture("n20", 1e-3, 20)};
  runs[1].metrics->at("propagation_distance") = 0.5;
  const json list = speed_accuracy(runs);
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["reference_run_id"], "n20");
  EXPECT_EQ(list[0]["errors"]["propagation_distance"], 0.0);
  EXPECT_TRUE(list[0]["errors"]["arrival_time"].is_null());
}

// ---- relative L2 error --------------------------------------------------------------------

TEST(RelativeL2Error, ScaledRecordOnADifferentGrid) {
  // v_ref = sin(t) on a fine grid, v_a = 1.1 v_ref on a coarse grid: the reference is
  // linearly interpolated, so the error is 0.1 up to the interpolation error O(h^2).
  std::vector<double> t_ref, v_ref, t_a, v_a;
  for (int i = 0; i <= 3000; ++i) {
    t_ref.push_back(0.001 * i);
    v_ref.push_back(std::sin(t_ref.back()));
  }
  for (int i = 1; i <= 29; ++i) {
    t_a.push_back(0.1 * i + 0.0005);
    v_a.push_back(1.1 * std::sin(t_a.back()));
  }
  EXPECT_NEAR(relative_l2_error(t_a, v_a, t_ref, v_ref), 0.1, 1e-6);
}

TEST(RelativeL2Error, LinearReferenceIsInterpolatedExactly) {
  const std::vector<double> t_ref = {0.0, 1.0, 2.0, 3.0}, v_ref = {0.0, 2.0, 4.0, 6.0};
  const std::vector<double> t_a = {0.25, 0.5, 1.5, 2.75}, v_a = {0.5, 1.0, 3.0, 5.5};
  EXPECT_EQ(relative_l2_error(t_a, v_a, t_ref, v_ref), 0.0);
}

TEST(RelativeL2Error, ConstantOffset) {
  // v_ref = 2, v_a = 2.5: ||0.5|| / ||2|| = 0.25 whatever the grids.
  const std::vector<double> t_ref = {0.0, 0.7, 3.0}, v_ref = {2.0, 2.0, 2.0};
  const std::vector<double> t_a = {0.1, 0.2, 1.3, 2.9}, v_a = {2.5, 2.5, 2.5, 2.5};
  EXPECT_DOUBLE_EQ(relative_l2_error(t_a, v_a, t_ref, v_ref), 0.25);
}

TEST(RelativeL2Error, OnlyTheCommonTimeRangeCounts) {
  // Reference on [0, 2]; the record agrees there and is wildly off after t = 2.
  const std::vector<double> t_ref = {0.0, 1.0, 2.0}, v_ref = {1.0, 3.0, 5.0};
  const std::vector<double> t_a = {0.0, 1.0, 2.0, 3.0, 4.0}, v_a = {1.0, 3.0, 5.0, 100.0, -50.0};
  EXPECT_EQ(relative_l2_error(t_a, v_a, t_ref, v_ref), 0.0);
}

TEST(RelativeL2Error, UndefinedCasesAreNaN) {
  const std::vector<double> t = {0.0, 1.0}, zero = {0.0, 0.0}, one = {1.0, 1.0};
  EXPECT_TRUE(std::isnan(relative_l2_error(t, one, t, zero)));         // ||v_ref|| = 0
  EXPECT_TRUE(std::isnan(relative_l2_error({5.0, 6.0}, one, t, one))); // no overlap
  EXPECT_TRUE(std::isnan(relative_l2_error({}, {}, t, one)));          // empty
}

TEST(RelativeL2Error, RejectsBadRecords) {
  const std::vector<double> t = {0.0, 1.0}, v = {1.0, 1.0};
  EXPECT_THROW(relative_l2_error(t, {1.0}, t, v), std::invalid_argument);
  EXPECT_THROW(relative_l2_error({1.0, 0.0}, v, t, v), std::invalid_argument);
  EXPECT_THROW(relative_l2_error(t, v, {0.0, 0.0}, v), std::invalid_argument);
}

// ---- refinement plan ----------------------------------------------------------------------

namespace {
const std::vector<double> ladder = {10, 20, 40, 80, 160};
}

TEST(RefinementPlan, StartsAtTheCoarsestMesh) {
  const RefinementPlan plan = refinement_plan(5e-5, {}, ladder, 160);
  EXPECT_EQ(plan.state, RefinementPlan::State::run_next);
  EXPECT_EQ(plan.next_n_d, 10);
}

TEST(RefinementPlan, RefinesPastTheFinestMeshUntilTwoSuccessiveAgree) {
  auto runs = paper_like_runs();
  runs.pop_back();                                        // 20 and 40: not converged, 80 is next
  runs.push_back(finished("other", 1e-5, 160, 1.0, 1.0)); // another L: ignored
  const RefinementPlan plan = refinement_plan(5e-5, runs, ladder, 160);
  EXPECT_EQ(to_string(plan.state), "run_next");
  EXPECT_EQ(plan.next_n_d, 80);
}

TEST(RefinementPlan, ConvergedReportsTheCoarsestConvergedMesh) {
  const RefinementPlan plan = refinement_plan(5e-5, paper_like_runs(), ladder, 160);
  EXPECT_EQ(plan.state, RefinementPlan::State::converged);
  EXPECT_EQ(plan.converged_n_d, 40);
  EXPECT_TRUE(std::isnan(plan.next_n_d));
}

TEST(RefinementPlan, WaitsForPendingRuns) {
  auto runs = paper_like_runs();
  runs.pop_back();
  runs.push_back(without_result("r80", 5e-5, 80, "running"));
  const RefinementPlan plan = refinement_plan(5e-5, runs, ladder, 160);
  EXPECT_EQ(plan.state, RefinementPlan::State::waiting);
  EXPECT_TRUE(std::isnan(plan.next_n_d));
}

TEST(RefinementPlan, StopsAtTheCap) {
  auto runs = paper_like_runs();
  runs.pop_back(); // 20, 40 not converged; cap 40
  const RefinementPlan plan = refinement_plan(5e-5, runs, ladder, 40);
  EXPECT_EQ(plan.state, RefinementPlan::State::not_converged_at_cap);
  EXPECT_EQ(to_string(plan.state), "not_converged_at_cap");
  EXPECT_NE(plan.reason.find("not converged at cap"), std::string::npos);
}

TEST(RefinementPlan, FailedMeshCountsAsTried) {
  const std::vector<StudyRun> runs = {finished("a", 5e-5, 10, 14.0, 9.0),
                                      without_result("b", 5e-5, 20, "failed")};
  EXPECT_EQ(refinement_plan(5e-5, runs, ladder, 160).next_n_d, 40);
}

TEST(CriticalLength, WhenNoLMeetsTheRuleTheVerdictSaysSoWithTheChangePerStepInL) {
  // Every step in L changes the propagation distance by ~2 % (the BI ladder of the paper's
  // scene): no L_c, and the reason lists each step's changes.
  auto runs =
      joined({converged_pair("a", 1e-6, 12.50, 9.050), converged_pair("b", 5e-6, 12.80, 9.057),
              converged_pair("c", 1e-5, 13.05, 9.095)});
  const json result = critical_length(runs);
  EXPECT_TRUE(result["L_c"].is_null());
  ASSERT_EQ(result["steps_in_L"].size(), 2u);
  EXPECT_EQ(result["steps_in_L"][0]["from_L"], 1e-6);
  EXPECT_EQ(result["steps_in_L"][0]["to_L"], 5e-6);
  EXPECT_NEAR(result["steps_in_L"][0]["changes"]["propagation_distance"].get<double>(),
              0.30 / 12.50, 1e-12);
  EXPECT_EQ(result["steps_in_L"][1]["agree"], false);
  const std::string reason = result["reason"];
  EXPECT_EQ(reason.rfind("no L meets the rule", 0), 0u) << reason;
  EXPECT_NE(reason.find("1e-06 -> 5e-06: 2.4 %"), std::string::npos) << reason;
}

TEST(CrossMethod, SameLByBothMethodsWithTheirReferencesAndDifferences) {
  const auto fe = joined(
      {converged_pair("fe-a", 5e-5, 14.25, 9.0467), converged_pair("fe-b", 1e-4, 15.00, 9.120)});
  auto bi = joined({converged_pair("bi-a", 5e-5, 14.25, 9.0439)});
  bi.push_back(finished("bi-x", 1e-3, 20, 0.0, never, "no_rupture"));
  const json table = slipfront::api::cross_method_table({"fe", fe}, {"spectral_bi", bi});
  ASSERT_EQ(table.size(), 3u); // every L of either method, ascending
  EXPECT_EQ(table[0]["L"], 5e-5);
  EXPECT_EQ(table[0]["fe"]["run_id"], "fe-a-40");
  EXPECT_EQ(table[0]["spectral_bi"]["run_id"], "bi-a-40");
  EXPECT_NEAR(table[0]["differences"]["arrival_time_at_probe"].get<double>(),
              (9.0467 - 9.0439) / 9.0439, 1e-12);
  EXPECT_EQ(table[0]["agree"], true);
  EXPECT_EQ(table[1]["L"], 1e-4);
  EXPECT_TRUE(table[1]["spectral_bi"].is_null());
  EXPECT_EQ(table[1]["reason"], "no mesh-converged run of this L by spectral_bi");
  EXPECT_TRUE(table[2]["fe"].is_null()); // 1e-3: one BI run, no partner: not converged
  EXPECT_EQ(table[2]["reason"], "no mesh-converged run of this L by either method");
}

TEST(CrossMethod, CounterpartSceneSwapsTheMethodAndDropsItsOwnFields) {
  using slipfront::api::counterpart_scene_hash;
  using slipfront::api::parse_job;
  using slipfront::api::scene_hash;
  const auto fe = parse_job({{"geometry", {{"height", 10}, {"nodes_per_meter", 20}}}});
  const auto bi = parse_job({{"method", "spectral_bi"}, {"geometry", {{"nodes_per_meter", 80}}}});
  ASSERT_TRUE(fe.ok() && bi.ok());
  EXPECT_EQ(counterpart_scene_hash(fe.spec->canonical), scene_hash(bi.spec->canonical));
  EXPECT_EQ(counterpart_scene_hash(bi.spec->canonical),
            scene_hash(parse_job(json::object()).spec->canonical)); // FE at its defaults
  EXPECT_NE(scene_hash(fe.spec->canonical), scene_hash(bi.spec->canonical));
}

TEST(CrossMethod, SpeedAccuracyAcrossMethodsUsesTheFinerReferenceOfEitherMethod) {
  // FE converged up to 40, BI up to 80: the BI n_d = 80 run is the reference of every run.
  auto fe = joined({converged_pair("fe", 5e-5, 14.25, 9.0467)});
  auto bi = joined({converged_pair("bi", 5e-5, 14.25, 9.0439)});
  bi.push_back(finished("bi-80", 5e-5, 80, 14.25, 9.0440));
  const json list = slipfront::api::speed_accuracy_across_methods({"fe", fe}, {"spectral_bi", bi});
  ASSERT_EQ(list.size(), 5u);
  for (const json& e : list) {
    EXPECT_EQ(e["reference_run_id"], "bi-80") << e.dump();
    EXPECT_EQ(e["reference_method"], "spectral_bi");
  }
  EXPECT_EQ(list[0]["method"], "fe");
  EXPECT_EQ(list[4]["method"], "spectral_bi");
  EXPECT_NEAR(list[1]["errors"]["arrival_time"].get<double>(), (9.0467 - 9.0440) / 9.0440, 1e-12);
  // With FE finer than BI, FE's reference wins.
  fe.push_back(finished("fe-160", 5e-5, 160, 14.25, 9.0445));
  const json again = slipfront::api::speed_accuracy_across_methods({"fe", fe}, {"spectral_bi", bi});
  EXPECT_EQ(again[0]["reference_run_id"], "fe-160");
  EXPECT_EQ(again[0]["reference_method"], "fe");
}
