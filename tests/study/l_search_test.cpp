// The L search's decisions (api/study/l_search.hpp, docs/studies-api.md "L search") on
// synthetic runs: each L has two meshes that agree (mesh-converged) unless said otherwise.
#include "api/study/l_search.hpp"

#include <gtest/gtest.h>

#include <cmath>

using nlohmann::json;
using namespace slipfront::api;

namespace {

StudyRun finished(const std::string& id, double L, double n_d, double distance, double arrival) {
  json metrics = {{"outcome", "arrested"},
                  {"propagation_distance", distance},
                  {"arrival_time_at_probe", arrival}};
  return {id, L, n_d, JobStatus::succeeded, metrics, 1.0, 1e6};
}

// One L at n_d 10 and 20: converged when `converges`, else the meshes differ by 10 %.
void add_L(std::vector<StudyRun>& runs, double L, double distance, bool converges = true) {
  const std::string id = std::to_string(runs.size());
  runs.push_back(finished(id, L, 10, converges ? distance : 1.1 * distance, 5.0));
  runs.push_back(finished(std::to_string(runs.size()), L, 20, distance, 5.0));
}

const LSearch search{4e-5, 2.0, 1e-6, 2, std::nullopt};

} // namespace

TEST(LSearch, LadderGoesDownByTheFactorToTheFloor) {
  const auto ladder = search_ladder(search, 50);
  ASSERT_EQ(ladder.size(), 6u); // 4e-5 ... 1.25e-6; 6.25e-7 is below the floor
  EXPECT_DOUBLE_EQ(ladder[0], 4e-5);
  EXPECT_DOUBLE_EQ(ladder[5], 1.25e-6);
  EXPECT_EQ(search_ladder(LSearch{1e-5, 10.0, 1e-7, 2, std::nullopt}, 50).size(),
            3u); // the floor itself
  EXPECT_EQ(search_ladder(search, 3).size(), 3u);
}

TEST(LSearch, WaitsWhileMeshesAreRefined) {
  std::vector<StudyRun> runs;
  add_L(runs, 4e-5, 12.0);
  const auto v = search_verdict(search, search_ladder(search, 50), 1, false, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::refining);
}

TEST(LSearch, GoesDownWhileTheSmallestLDisagree) {
  const auto ladder = search_ladder(search, 50);
  std::vector<StudyRun> runs;
  add_L(runs, 4e-5, 12.0);
  auto v = search_verdict(search, ladder, 1, true, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::next_L);
  EXPECT_DOUBLE_EQ(v.next_L, 2e-5);
  add_L(runs, 2e-5, 10.0); // 20 % away
  v = search_verdict(search, ladder, 2, true, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::next_L);
  EXPECT_DOUBLE_EQ(v.next_L, 1e-5);
  ASSERT_EQ(v.steps.size(), 1u);
  EXPECT_FALSE(v.steps[0]["agree"].get<bool>());
}

TEST(LSearch, FoundWhenTheSmallestAgreeAndALargerOneDoesNot) {
  const auto ladder = search_ladder(search, 50);
  std::vector<StudyRun> runs;
  add_L(runs, 4e-5, 12.0);
  add_L(runs, 2e-5, 10.0);
  add_L(runs, 1e-5, 10.001); // agrees with 2e-5 (0.01 %)
  const auto v = search_verdict(search, ladder, 3, true, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::found);
  EXPECT_DOUBLE_EQ(v.L_c, 2e-5);
  EXPECT_NE(v.reason.find("L_c = 2e-05"), std::string::npos) << v.reason;
}

TEST(LSearch, AGroupThatAgreesFromTheStartIsNotAnAnswerBeforeTheFloor) {
  // A plateau at large L (the bimaterial study's): 4e-5 and 2e-5 agree, nothing disagrees
  // yet, so the search goes on down.
  const auto ladder = search_ladder(search, 50);
  std::vector<StudyRun> runs;
  add_L(runs, 4e-5, 12.0);
  add_L(runs, 2e-5, 12.001);
  auto v = search_verdict(search, ladder, 2, true, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::next_L);
  for (std::size_t i = 2; i < ladder.size(); ++i)
    add_L(runs, ladder[i], 12.0);
  v = search_verdict(search, ladder, ladder.size(), true, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::all_agree);
  EXPECT_DOUBLE_EQ(v.L_c, 4e-5);
}

TEST(LSearch, FloorWhenTheSmallestStillDisagree) {
  const auto ladder = search_ladder(search, 50);
  std::vector<StudyRun> runs;
  for (std::size_t i = 0; i < ladder.size(); ++i)
    add_L(runs, ladder[i], 10.0 + double(i)); // every step changes the distance by ~10 %
  const auto v = search_verdict(search, ladder, ladder.size(), true, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::floor);
  EXPECT_NE(v.reason.find("floor L = 1.25e-06"), std::string::npos) << v.reason;
}

TEST(LSearch, MeshCapWhenTheSmallestLNeverConverge) {
  const auto ladder = search_ladder(search, 50);
  std::vector<StudyRun> runs;
  add_L(runs, 4e-5, 12.0);
  add_L(runs, 2e-5, 10.0, false);
  add_L(runs, 1e-5, 9.0, false);
  const auto v = search_verdict(search, ladder, 3, true, runs);
  EXPECT_EQ(v.state, SearchVerdict::State::mesh_cap);
  EXPECT_NE(v.reason.find("smallest mesh-converged L is 4e-05"), std::string::npos) << v.reason;
}

TEST(LSearch, StopsWhereTheRegularisedRunsMeetPlainCoulomb) {
  LSearch with_coulomb = search;
  with_coulomb.coulomb = true;
  const auto ladder = search_ladder(with_coulomb, 50);
  std::vector<StudyRun> runs;
  add_L(runs, 4e-5, 12.0);
  add_L(runs, 2e-5, 10.3);
  std::vector<StudyRun> coulomb_runs;
  add_L(coulomb_runs, 4e-5, 10.3); // Coulomb (its runs carry the search's first L)
  const auto reference = coulomb_reference(4e-5, coulomb_runs, {10, 20}, 20);
  ASSERT_NE(reference.run, nullptr);
  EXPECT_NE(reference.status.find("mesh-converged from n_d = 10"), std::string::npos)
      << reference.status;
  // Two L only, so the pair rule cannot be met yet; 2e-5 agrees with Coulomb: stop there.
  const auto v = search_verdict(with_coulomb, ladder, 2, true, runs, reference);
  EXPECT_EQ(v.state, SearchVerdict::State::meets_coulomb);
  EXPECT_DOUBLE_EQ(v.L_c, 2e-5);
  EXPECT_NE(v.reason.find("in [2e-05, 4e-05)"), std::string::npos) << v.reason;
  EXPECT_NE(v.reason.find("meets plain Coulomb ("), std::string::npos) << v.reason;
  // Another law's unregularised companion is named as itself, never as Coulomb.
  LSearch rate_state = with_coulomb;
  rate_state.companion = "rate and state without regularisation";
  const auto named = search_verdict(rate_state, ladder, 2, true, runs, reference);
  EXPECT_NE(named.reason.find("meets rate and state without regularisation ("), std::string::npos)
      << named.reason;
  EXPECT_EQ(named.reason.find("Coulomb"), std::string::npos) << named.reason;
  ASSERT_EQ(v.coulomb["steps"].size(), 2u);
  EXPECT_FALSE(v.coulomb["steps"][0]["agree"].get<bool>());
  EXPECT_TRUE(v.coulomb["steps"][1]["agree"].get<bool>());
  // While Coulomb is still refining there is no reference: the search goes on down.
  std::vector<StudyRun> refining = {coulomb_runs.front()};
  const auto pending = coulomb_reference(4e-5, refining, {10, 20}, 20);
  EXPECT_EQ(pending.run, nullptr);
  EXPECT_EQ(search_verdict(with_coulomb, ladder, 2, true, runs, pending).state,
            SearchVerdict::State::next_L);
}

TEST(LSearch, CoulombIsNotComparedWhenSwitchedOff) {
  const auto ladder = search_ladder(search, 50); // search.coulomb unset
  std::vector<StudyRun> runs, coulomb_runs;
  add_L(runs, 4e-5, 12.0);
  add_L(runs, 2e-5, 10.3);
  add_L(coulomb_runs, 4e-5, 10.3);
  const auto v = search_verdict(search, ladder, 2, true, runs,
                                coulomb_reference(4e-5, coulomb_runs, {10, 20}, 20));
  EXPECT_EQ(v.state, SearchVerdict::State::next_L);
  EXPECT_TRUE(v.coulomb.is_null());
}
