// The studies schema (migrations 2 -> 3 -> 4, 7 -> 8) and StudyStore.
#include "api/job_spec.hpp"
#include "api/study_analysis.hpp"
#include "server/core/job_id.hpp"
#include "server/db/database.hpp"
#include "server/db/job_store.hpp"
#include "server/db/study_store.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace slipfront::server;
namespace api = slipfront::api;
namespace fs = std::filesystem;
using slipfront::server::testing::TempDir;

namespace {

nlohmann::json spec(double L, double n_d, double mu, const std::string& name) {
  return {{"name", name},
          {"tags", {"t"}},
          {"threads", 1},
          {"friction", {{"L", L}, {"mu", mu}, {"law", "prakash_clifton"}}},
          {"geometry", {{"nodes_per_meter", n_d}, {"width", 40.0}}}};
}

Job make_job(const nlohmann::json& s, const std::string& status = "queued") {
  Job job;
  job.id = new_job_id();
  job.name = s["name"];
  job.spec = s;
  job.spec_sha256 = slipfront::api::spec_hash(s);
  job.scene_hash = slipfront::api::scene_hash(s);
  job.L = s["friction"]["L"];
  job.n_d = s["geometry"]["nodes_per_meter"];
  job.created_at = "2024-01-01T00:00:00.000Z";
  job.status = status == "succeeded" ? JobStatus::succeeded : JobStatus::queued;
  return job;
}

} // namespace

TEST(StudySchema, MigrationFillsTheSceneHashOfExistingJobs) {
  TempDir dir("slipfront-study-");
  const auto path = dir.file("db.sqlite");
  const auto a = spec(1e-5, 10, 0.75, "a"), b = spec(5e-5, 20, 0.75, "b"),
             c = spec(1e-5, 10, 0.6, "c");
  {
    Database raw(path); // a database written by a build at schema version 2
    raw.exec(schema_migrations()[0].sql);
    raw.exec(schema_migrations()[1].sql);
    raw.set_user_version(2);
    auto s = raw.prepare("INSERT INTO jobs (id, status, spec, spec_sha256, created_at) VALUES "
                         "(?1, 'succeeded', ?2, 'h', '2024')");
    int i = 0;
    for (const auto& x : {a, b, c}) {
      s.bind(1, std::string(31, '0') + std::to_string(i++)).bind(2, x.dump()).run();
      s.reset();
    }
  }
  JobStore store(path);
  EXPECT_EQ(store.user_version(), JobStore::schema_version);
  auto ja = store.get(std::string(31, '0') + "0"), jb = store.get(std::string(31, '0') + "1"),
       jc = store.get(std::string(31, '0') + "2");
  ASSERT_TRUE(ja && jb && jc);
  EXPECT_EQ(ja->scene_hash, slipfront::api::scene_hash(a));
  EXPECT_EQ(ja->scene_hash.size(), 64u);
  EXPECT_EQ(ja->scene_hash, jb->scene_hash); // differ only in L, n_d, name
  EXPECT_NE(ja->scene_hash, jc->scene_hash); // another mu: another scene
  JobFilter f;
  f.scene_hash = ja->scene_hash;
  EXPECT_EQ(store.list(f).jobs.size(), 2u);
  Database raw(path);
  auto s = raw.prepare("SELECT COUNT(*) FROM sqlite_master WHERE name IN ('studies', 'study_runs', "
                       "'jobs_scene_hash')");
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.integer(0), 3);
}

TEST(StudySchema, MigrationToFourKeepsStudiesAndTheirRunsAndAllowsCancelled) {
  TempDir dir("slipfront-study-");
  const auto path = dir.file("db.sqlite");
  const std::string study_id(32, 'a'), job_id(32, 'b');
  {
    Database raw(path); // a database written by a build at schema version 3
    raw.exec("PRAGMA foreign_keys = ON");
    for (int v = 0; v < 3; ++v)
      raw.exec(schema_migrations()[static_cast<std::size_t>(v)].sql);
    raw.set_user_version(3);
    raw.exec("INSERT INTO jobs (id, status, spec, spec_sha256, created_at, study_id) VALUES ('" +
             job_id + "', 'running', '{}', 'h', '2024', '" + study_id + "')");
    raw.exec("INSERT INTO studies (id, kind, base_spec, request, scene_hash, created_at, "
             "runs_total, result) VALUES ('" +
             study_id + "', 'grid', '{}', '{}', 's', '2024', 1, '{\"x\": 1}')");
    raw.exec("INSERT INTO study_runs (study_id, job_id, L, n_d) VALUES ('" + study_id + "', '" +
             job_id + "', 1e-5, 10)");
    EXPECT_THROW(raw.exec("UPDATE studies SET status = 'cancelled'"), std::exception);
  }
  JobStore jobs(path);
  EXPECT_EQ(jobs.user_version(), JobStore::schema_version);
  StudyStore studies(jobs);
  auto study = studies.get(study_id);
  ASSERT_TRUE(study);
  EXPECT_EQ(study->status, api::StudyStatus::running);
  EXPECT_EQ(study->result["x"], 1);
  EXPECT_EQ(study->idempotency_key, "");        // migration 7: none for the studies before it
  ASSERT_EQ(studies.runs(study_id).size(), 1u); // the rebuild did not cascade to study_runs
  EXPECT_EQ(studies.study_of_job(job_id), study_id);

  studies.set_status(study_id, api::StudyStatus::cancelled, "2025");
  EXPECT_EQ(studies.get(study_id)->status, api::StudyStatus::cancelled);
  EXPECT_EQ(studies.get(study_id)->updated_at, "2025");
  EXPECT_TRUE(studies.running_ids().empty());
  EXPECT_EQ(studies.list(10, std::nullopt, api::StudyStatus::cancelled).size(), 1u);
  // Its run is not final: the next start-up must settle it.
  EXPECT_EQ(studies.unsettled_cancelled_ids(), std::vector<std::string>{study_id});
  // Foreign keys hold again after the migration.
  EXPECT_THROW(jobs.db().with_db([&](Database& db) {
    db.exec("INSERT INTO study_runs (study_id, job_id, L, n_d) VALUES ('" + std::string(32, 'c') +
            "', '" + job_id + "', 1e-5, 20)");
  }),
               std::exception);
}

TEST(StudySchema, MigrationToEightKeepsStudiesKeysAndRunsAndAllowsAccuracy) {
  TempDir dir("slipfront-study-");
  const auto path = dir.file("db.sqlite");
  const std::string study_id(32, 'a'), job_id(32, 'b');
  {
    Database raw(path); // a database written by a build at schema version 7
    raw.exec("PRAGMA foreign_keys = ON");
    for (int v = 0; v < 7; ++v)
      raw.exec(schema_migrations()[static_cast<std::size_t>(v)].sql);
    raw.set_user_version(7);
    raw.exec("INSERT INTO jobs (id, status, spec, spec_sha256, created_at, study_id) VALUES ('" +
             job_id + "', 'succeeded', '{}', 'h', '2024', '" + study_id + "')");
    raw.exec("INSERT INTO studies (id, kind, base_spec, request, scene_hash, created_at, "
             "runs_total, idempotency_key, submitted_by) VALUES ('" +
             study_id + "', 'convergence', '{}', '{}', 's', '2024', 1, 'key-1', 'ana')");
    raw.exec("INSERT INTO study_runs (study_id, job_id, regime, L, n_d) VALUES ('" + study_id +
             "', '" + job_id + "', 'coulomb', 5e-5, 10)");
    EXPECT_THROW(raw.exec("UPDATE studies SET kind = 'accuracy'"), std::exception);
  }
  JobStore jobs(path);
  EXPECT_EQ(jobs.user_version(), JobStore::schema_version);
  StudyStore studies(jobs);
  ASSERT_TRUE(studies.find_by_idempotency_key("ana", "key-1"));
  ASSERT_EQ(studies.runs(study_id).size(), 1u);
  EXPECT_EQ(studies.runs(study_id)[0].regime, "coulomb");
  jobs.db().with_db([&](Database& db) { db.exec("UPDATE studies SET kind = 'accuracy'"); });
  EXPECT_EQ(studies.get(study_id)->kind, "accuracy");
  // The idempotency key stays unique per submitter after the rebuild.
  EXPECT_THROW(jobs.db().with_db([&](Database& db) {
    db.exec("INSERT INTO studies (id, kind, base_spec, request, scene_hash, created_at, "
            "idempotency_key, submitted_by) VALUES ('" +
            std::string(32, 'c') + "', 'grid', '{}', '{}', 's', '2024', 'key-1', 'ana')");
  }),
               std::exception);
}

// POST /studies' Idempotency-Key: found per submitter, unique per submitter, and a study
// inserted inside a transaction that rolls back is not there (StudyService::create).
TEST(StudyStore, FindsAStudyByItsIdempotencyKeyPerSubmitter) {
  TempDir dir("slipfront-study-");
  JobStore jobs(dir.file("db.sqlite"));
  StudyStore studies(jobs);
  StudyRecord st;
  st.id = new_job_id();
  st.kind = "grid";
  st.base = st.request = nlohmann::json::object();
  st.submitted_by = "alice";
  st.idempotency_key = "k";
  st.created_at = "2024";
  studies.insert(st);
  ASSERT_TRUE(studies.find_by_idempotency_key("alice", "k"));
  EXPECT_EQ(studies.find_by_idempotency_key("alice", "k")->id, st.id);
  EXPECT_FALSE(studies.find_by_idempotency_key("bob", "k"));
  EXPECT_FALSE(studies.find_by_idempotency_key("alice", "other"));

  StudyRecord again = st;
  again.id = new_job_id();
  EXPECT_THROW(studies.insert(again), std::exception); // the same key twice for alice
  again.submitted_by = "bob";
  EXPECT_FALSE(jobs.db().in_transaction([&] {
    studies.insert(again);
    EXPECT_TRUE(studies.find_by_idempotency_key("bob", "k"));
    return false; // rolled back
  }));
  EXPECT_FALSE(studies.find_by_idempotency_key("bob", "k"));
  EXPECT_FALSE(studies.get(again.id));
}

TEST(StudyStore, StoresStatusesAndLcAndListsSceneRuns) {
  TempDir dir("slipfront-study-");
  JobStore jobs(dir.file("db.sqlite"));
  StudyStore studies(jobs);
  StudyRecord st;
  st.id = new_job_id();
  st.name = "sweep";
  st.tags = {"x"};
  st.kind = "grid";
  st.base = nlohmann::json::object();
  st.request = {{"grid", {{"L", {1e-5}}, {"n_d", {10, 20}}}}};
  st.scene_hash = slipfront::api::scene_hash(spec(1e-5, 10, 0.75, "a"));
  st.submitted_by = "alice";
  st.created_at = "2024";
  studies.insert(st);

  Job coarse = make_job(spec(1e-5, 10, 0.75, "a"));
  coarse.study_id = st.id;
  Job fine = make_job(spec(1e-5, 20, 0.75, "b"), "succeeded");
  fine.study_id = st.id;
  jobs.insert(coarse);
  jobs.insert(fine);
  Job copy = make_job(spec(1e-5, 20, 0.75, "b"), "succeeded");
  copy.cached_from = fine.id;
  jobs.insert(copy);
  studies.add_run(st.id, coarse.id, "", 1e-5, 10);
  studies.add_run(st.id, fine.id, "", 1e-5, 20);
  EXPECT_EQ(studies.study_of_job(fine.id), st.id);
  EXPECT_EQ(studies.study_of_job(copy.id), "");

  auto rows = studies.runs(st.id);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].job_status, "queued");
  rows[0].convergence_status = "converged";
  rows[0].partner_n_d = 20;
  rows[0].propagation_distance_change = 0.001;
  st.status = api::StudyStatus::finished;
  st.runs_done = 1;
  st.runs_total = 2;
  st.L_c = 1e-5;
  st.result = {{"convergence_map", {{"L", {1e-5}}}}};
  st.updated_at = st.finished_at = "2025";
  studies.save_analysis(st, rows);

  auto back = studies.get(st.id);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->status, api::StudyStatus::finished);
  EXPECT_DOUBLE_EQ(back->L_c, 1e-5);
  EXPECT_TRUE(std::isnan(back->spectral_critical_length));
  EXPECT_EQ(back->result["convergence_map"]["L"][0], 1e-5);
  auto stored = studies.runs(st.id);
  EXPECT_EQ(stored[0].convergence_status, "converged");
  EXPECT_DOUBLE_EQ(stored[0].partner_n_d, 20);
  EXPECT_EQ(stored[1].convergence_status, "pending");
  EXPECT_TRUE(studies.running_ids().empty());
  EXPECT_EQ(studies.list(10, std::nullopt, api::StudyStatus::finished).size(), 1u);

  // The scene's finished jobs, reused copies left out.
  auto scene = studies.scene_runs(st.scene_hash);
  ASSERT_EQ(scene.size(), 1u);
  EXPECT_EQ(scene[0].job_id, fine.id);
}

// Migration 12 -> 13 gives existing studies an empty note and no archive time; a study is
// deleted with its runs only once it is over and every run is final, a run another study
// also lists stays, and the result files left without a row are named with the intent.
TEST(StudyStore, MigrationToThirteenThenArchiveAndDeleteWithItsRuns) {
  TempDir dir("slipfront-study-");
  const auto path = dir.file("db.sqlite");
  const std::string old_id(32, 'a');
  {
    Database raw(path); // a database written by a build at schema version 12
    for (int v = 0; v < 12; ++v)
      raw.exec(schema_migrations()[static_cast<std::size_t>(v)].sql);
    raw.set_user_version(12);
    raw.exec("INSERT INTO studies (id, kind, base_spec, request, scene_hash, created_at, "
             "status) VALUES ('" +
             old_id + "', 'grid', '{}', '{}', 's', '2024', 'finished')");
  }
  JobStore jobs(path);
  EXPECT_EQ(jobs.user_version(), JobStore::schema_version);
  StudyStore studies(jobs);
  ASSERT_TRUE(studies.get(old_id));
  EXPECT_EQ(studies.get(old_id)->note, "");
  EXPECT_EQ(studies.get(old_id)->archived_at, "");
  ASSERT_TRUE(studies.set_archived(old_id, "2025-01-01T00:00:00.000Z"));
  EXPECT_TRUE(studies.list(10, std::nullopt, std::nullopt, ArchivedRuns::exclude).empty());
  EXPECT_EQ(studies.list(10, std::nullopt, std::nullopt, ArchivedRuns::only).size(), 1u);
  auto after = studies.annotate(old_id, {std::nullopt, {"fig-3"}, {}}, std::string("kept"));
  ASSERT_TRUE(after && !after->error);
  EXPECT_EQ(studies.get(old_id)->tags, std::vector<std::string>{"fig-3"});
  EXPECT_EQ(studies.get(old_id)->note, "kept");

  StudyRecord st;
  st.id = new_job_id();
  st.kind = "grid";
  st.base = st.request = nlohmann::json::object();
  st.created_at = "2024";
  studies.insert(st); // running
  Job own = make_job(spec(1e-5, 10, 0.75, "own"), "succeeded");
  own.study_id = st.id;
  own.result.path = "results/" + own.id + ".h5";
  Job shared = make_job(spec(1e-5, 20, 0.75, "shared"), "succeeded");
  shared.study_id = st.id;
  shared.result.path = "results/" + shared.id + ".h5";
  Job hit = make_job(spec(1e-5, 20, 0.75, "shared"), "succeeded"); // another user's hit
  hit.cached_from = shared.id;
  hit.result.path = shared.result.path;
  Job queued = make_job(spec(1e-5, 40, 0.75, "queued"));
  queued.study_id = st.id;
  for (const Job* j : {&own, &shared, &hit, &queued})
    jobs.insert(*j);
  studies.add_run(st.id, own.id, "", 1e-5, 10);
  studies.add_run(st.id, shared.id, "", 1e-5, 20);
  studies.add_run(st.id, queued.id, "", 1e-5, 40);
  studies.add_run(old_id, own.id, "", 1e-5, 10); // the other study lists it too
  using Kind = StudyStore::Removal::Kind;
  EXPECT_EQ(studies.remove(st.id).kind, Kind::running);
  studies.set_status(st.id, api::StudyStatus::cancelled, "2025");
  EXPECT_EQ(studies.remove(st.id).kind, Kind::runs_not_final);
  EXPECT_TRUE(jobs.get(queued.id)) << "a refused delete changed nothing";
  ASSERT_TRUE(jobs.cancel_queued(queued.id, "2025"));
  const auto removal = studies.remove(st.id);
  ASSERT_EQ(removal.kind, Kind::removed);
  EXPECT_EQ(std::set<std::string>(removal.job_ids.begin(), removal.job_ids.end()),
            (std::set<std::string>{shared.id, queued.id}));
  EXPECT_TRUE(removal.orphaned_results.empty()) << "the hit still shares the file";
  EXPECT_FALSE(studies.get(st.id));
  EXPECT_FALSE(jobs.get(shared.id));
  EXPECT_FALSE(jobs.get(queued.id));
  EXPECT_TRUE(jobs.get(own.id)) << "another study lists it";
  EXPECT_TRUE(jobs.get(hit.id));
  EXPECT_EQ(studies.remove(st.id).kind, Kind::not_found);
}
