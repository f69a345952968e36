#include "server/core/job_id.hpp"
#include "server/db/database.hpp"
#include "server/db/job_store.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace slipfront::server;
namespace fs = std::filesystem;
using slipfront::server::testing::TempDir;

namespace {

Job make_job(const std::string& name, double L = 5e-5, double n_d = 10) {
  Job job;
  job.id = new_job_id();
  job.name = name;
  job.tags = {"sweep", name};
  job.spec = {{"name", name}, {"friction", {{"L", L}}}};
  job.spec_sha256 = std::string("hash-").append(name);
  job.submitted_by = "alice";
  job.L = L;
  job.n_d = n_d;
  job.created_at = "2024-01-01T00:00:00.000Z";
  return job;
}

RunRecord success() {
  RunRecord r;
  r.status = JobStatus::succeeded;
  r.metrics = {{"arrest_position", 12.5},
               {"propagation_distance", 12.0},
               {"arrival_time_at_probe", 7.0},
               {"max_rupture_speed", 1.6},
               {"mean_rupture_speed", 1.2},
               {"max_slip_velocity", 0.008},
               {"outcome", "arrested"},
               {"energy_error", 1e-3},
               {"wall_time_s", 0.5},
               {"steps", 1000},
               {"dt", 0.01}};
  r.front = {
      {"x1", {0.0, 1.0}}, {"arrival_time", {0.5, nullptr}}, {"rupture_speed", {1.0, nullptr}}};
  r.result = {"results/x.h5", 1234, "abc"};
  r.wall_time_s = 0.5;
  r.finished_at = "2024-01-01T00:00:01.000Z";
  return r;
}

} // namespace

TEST(JobStore, FreshDatabaseIsAtLatestSchemaInWalMode) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("db.sqlite"));
  EXPECT_EQ(store.user_version(), JobStore::schema_version);
  EXPECT_EQ(static_cast<int>(schema_migrations().size()), JobStore::schema_version);
  Database raw(dir.file("db.sqlite"));
  auto s = raw.prepare("PRAGMA journal_mode");
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.text(0), "wal");
}

TEST(JobStore, MigratesAnOlderSchemaKeepingItsJobs) {
  TempDir dir("slipfront-store-");
  const auto path = dir.file("db.sqlite");
  {
    Database raw(path); // a database written by a build at schema version 1
    raw.exec(schema_migrations()[0].sql);
    raw.set_user_version(1);
    raw.exec("INSERT INTO jobs (id, status, spec, spec_sha256, created_at) VALUES "
             "('0123456789abcdef0123456789abcdef', 'queued', '{}', 'h', '2024')");
  }
  JobStore store(path);
  EXPECT_EQ(store.user_version(), JobStore::schema_version);
  auto job = store.get("0123456789abcdef0123456789abcdef");
  ASSERT_TRUE(job);
  EXPECT_EQ(job->status, JobStatus::queued);
  Database raw(path);
  auto s = raw.prepare("SELECT COUNT(*) FROM sqlite_master WHERE name = 'jobs_name'");
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.integer(0), 1); // migration 1 -> 2 ran
}

TEST(JobStore, RefusesANewerSchema) {
  TempDir dir("slipfront-store-");
  const auto path = dir.file("db.sqlite");
  {
    Database raw(path);
    raw.set_user_version(99);
  }
  EXPECT_THROW(JobStore store(path), std::runtime_error);
}

TEST(JobStore, StateTransitionsAreConditional) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("db.sqlite"));
  Job job = make_job("a");
  store.insert(job);
  EXPECT_FALSE(store.finish(job.id, success())) << "queued cannot jump to succeeded";
  EXPECT_FALSE(store.requeue(job.id)) << "only running jobs are re-queued";
  EXPECT_TRUE(store.mark_running(job.id, "t1", "host", "v1"));
  EXPECT_FALSE(store.mark_running(job.id, "t1", "host", "v1"));
  EXPECT_FALSE(store.cancel_queued(job.id, "t2"));
  EXPECT_TRUE(store.finish(job.id, success()));
  EXPECT_FALSE(store.finish(job.id, success())) << "final states never change";
  EXPECT_FALSE(store.requeue(job.id));
  EXPECT_FALSE(store.cancel_queued(job.id, "t3"));
  auto done = store.get(job.id);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->status, JobStatus::succeeded);
  EXPECT_EQ(done->attempts, 1);
  EXPECT_EQ(done->host, "host");
  EXPECT_EQ(done->code_version, "v1");
  EXPECT_EQ(done->result.size, 1234u);
  EXPECT_EQ(done->metrics["outcome"].get<std::string>(), "arrested");
  EXPECT_DOUBLE_EQ(done->progress.fraction, 1.0);

  Job other = make_job("b");
  store.insert(other);
  EXPECT_TRUE(store.cancel_queued(other.id, "t4"));
  EXPECT_FALSE(store.mark_running(other.id, "t5", "h", "v")) << "a cancelled job never runs";
  EXPECT_EQ(store.get(other.id)->status, JobStatus::cancelled);
}

TEST(JobStore, MetricsAreQueryableColumns) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("db.sqlite"));
  Job job = make_job("a", 1e-4, 20);
  store.insert(job);
  store.mark_running(job.id, "t", "h", "v");
  store.finish(job.id, success());
  Database raw(dir.file("db.sqlite"));
  auto s = raw.prepare("SELECT arrest_position, outcome, steps, L, n_d, max_rupture_speed "
                       "FROM metrics WHERE job_id = ?1");
  s.bind(1, job.id);
  ASSERT_TRUE(s.step());
  EXPECT_DOUBLE_EQ(s.real(0), 12.5);
  EXPECT_EQ(s.text(1), "arrested");
  EXPECT_EQ(s.integer(2), 1000);
  EXPECT_DOUBLE_EQ(s.real(3), 1e-4);
  EXPECT_DOUBLE_EQ(s.real(4), 20);
  EXPECT_DOUBLE_EQ(s.real(5), 1.6);
  auto front = store.front(job.id);
  ASSERT_TRUE(front);
  EXPECT_TRUE((*front)["arrival_time"][1].is_null());
}

TEST(JobStore, RecoveryRequeuesRunningJobsOnly) {
  TempDir dir("slipfront-store-");
  const auto path = dir.file("db.sqlite");
  std::string running_id, queued_id, done_id;
  {
    JobStore store(path);
    Job a = make_job("a"), b = make_job("b"), c = make_job("c");
    store.insert(a);
    store.insert(b);
    store.insert(c);
    store.mark_running(a.id, "t", "h", "v");
    JobProgress p{0.5, 1.0, 2.0, 100, 1.0, "t2"};
    store.update_progress(a.id, p);
    EXPECT_DOUBLE_EQ(store.get(a.id)->progress.fraction, 0.5);
    store.mark_running(c.id, "t", "h", "v");
    store.finish(c.id, success());
    running_id = a.id;
    queued_id = b.id;
    done_id = c.id;
  } // the "crash": the store goes away with a job running
  JobStore store(path);
  EXPECT_EQ(store.requeue_all_running(), 1);
  auto a = store.get(running_id);
  EXPECT_EQ(a->status, JobStatus::queued);
  EXPECT_DOUBLE_EQ(a->progress.fraction, 0.0);
  EXPECT_TRUE(a->started_at.empty());
  EXPECT_EQ(store.get(done_id)->status, JobStatus::succeeded);
  auto queued = store.queued_jobs();
  ASSERT_EQ(queued.size(), 2u);
  EXPECT_EQ(queued[0].id, running_id); // submission order
  EXPECT_EQ(queued[1].id, queued_id);
  EXPECT_TRUE(store.mark_running(running_id, "t3", "h", "v"));
  EXPECT_EQ(store.get(running_id)->attempts, 2);
}

TEST(JobStore, QueuedJobsByPriorityThenSubmission) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("db.sqlite"));
  Job a = make_job("a"), b = make_job("b"), c = make_job("c");
  b.priority = 3;
  store.insert(a);
  store.insert(b);
  store.insert(c);
  auto q = store.queued_jobs();
  ASSERT_EQ(q.size(), 3u);
  EXPECT_EQ(q[0].id, b.id);
  EXPECT_EQ(q[1].id, a.id);
  EXPECT_EQ(q[2].id, c.id);
}

TEST(JobStore, ListFiltersAndPaginatesNewestFirst) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("db.sqlite"));
  std::vector<std::string> ids;
  for (int i = 0; i < 7; ++i) {
    Job j = make_job(std::string("job").append(std::to_string(i % 2)), i < 4 ? 1e-5 : 1e-4, 5 + i);
    store.insert(j);
    ids.push_back(j.id);
  }
  JobFilter f;
  f.limit = 3;
  auto page1 = store.list(f);
  ASSERT_EQ(page1.jobs.size(), 3u);
  EXPECT_EQ(page1.jobs[0].id, ids[6]);
  ASSERT_TRUE(page1.next_cursor);
  f.before_seq = page1.next_cursor;
  auto page2 = store.list(f);
  ASSERT_EQ(page2.jobs.size(), 3u);
  EXPECT_EQ(page2.jobs[0].id, ids[3]);
  f.before_seq = page2.next_cursor;
  auto page3 = store.list(f);
  ASSERT_EQ(page3.jobs.size(), 1u);
  EXPECT_FALSE(page3.next_cursor);

  JobFilter by_name;
  by_name.name = "job1";
  EXPECT_EQ(store.list(by_name).jobs.size(), 3u);
  JobFilter by_tag;
  by_tag.tag = "job0";
  EXPECT_EQ(store.list(by_tag).jobs.size(), 4u);
  JobFilter by_range;
  by_range.L_min = 5e-5;
  by_range.n_d_max = 10;
  EXPECT_EQ(store.list(by_range).jobs.size(), 2u); // i = 4, 5
  JobFilter by_status;
  by_status.statuses = {JobStatus::running};
  EXPECT_EQ(store.list(by_status).jobs.size(), 0u);
  store.mark_running(ids[0], "t", "h", "v");
  store.finish(ids[0], success());
  JobFilter by_outcome;
  by_outcome.outcome = "arrested";
  auto arrested = store.list(by_outcome);
  ASSERT_EQ(arrested.jobs.size(), 1u);
  EXPECT_EQ(arrested.jobs[0].id, ids[0]);
}

TEST(JobStore, ReuseNeedsTheSameOutputSettings) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("db.sqlite"));
  const nlohmann::json fine = {{"interval", 0.05}, {"space_stride", 1}};
  const nlohmann::json coarse = {{"interval", 0.2}, {"space_stride", 1}};
  Job a = make_job("a");
  a.spec["output"] = fine;
  store.insert(a);
  store.mark_running(a.id, "t", "h", "v");
  store.finish(a.id, success());

  auto same = store.find_reusable(a.spec_sha256, "v", {{"space_stride", 1}, {"interval", 0.05}});
  ASSERT_TRUE(same) << "same settings, whatever the key order";
  EXPECT_EQ(same->id, a.id);
  EXPECT_FALSE(store.find_reusable(a.spec_sha256, "v", coarse)) << "another interval";
  EXPECT_FALSE(store.find_reusable(a.spec_sha256, "v", {{"interval", 0.05}, {"space_stride", 2}}))
      << "another stride";
  EXPECT_FALSE(store.find_reusable(a.spec_sha256, "v", nlohmann::json()));

  Job b = make_job("a"); // same physics hash, coarser sampling, newer
  b.spec["output"] = coarse;
  store.insert(b);
  store.mark_running(b.id, "t", "h", "v");
  store.finish(b.id, success());
  EXPECT_EQ(store.find_reusable(a.spec_sha256, "v", fine)->id, a.id);
  EXPECT_EQ(store.find_reusable(a.spec_sha256, "v", coarse)->id, b.id);
}

TEST(JobStore, ReuseAndIdempotencyLookups) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("db.sqlite"));
  Job a = make_job("a");
  a.idempotency_key = "key-1";
  store.insert(a);
  const nlohmann::json no_output;
  EXPECT_FALSE(store.find_reusable(a.spec_sha256, "v", no_output)) << "not succeeded yet";
  store.mark_running(a.id, "t", "h", "v");
  store.finish(a.id, success());
  auto reusable = store.find_reusable(a.spec_sha256, "v", no_output);
  ASSERT_TRUE(reusable);
  EXPECT_EQ(reusable->id, a.id);
  EXPECT_FALSE(store.find_reusable(a.spec_sha256, "other-version", no_output));

  Job copy = make_job("a");
  copy.status = JobStatus::succeeded;
  copy.cached_from = a.id;
  copy.result = reusable->result;
  store.insert(copy);
  auto got = store.get(copy.id);
  EXPECT_EQ(got->metrics["outcome"].get<std::string>(), "arrested")
      << "metrics copied with the reuse";

  auto same = store.find_by_idempotency_key("alice", "key-1");
  ASSERT_TRUE(same);
  EXPECT_EQ(same->id, a.id);
  EXPECT_FALSE(store.find_by_idempotency_key("bob", "key-1"));
  Job dup = make_job("a");
  dup.idempotency_key = "key-1";
  EXPECT_THROW(store.insert(dup), SqliteError) << "the key is unique per user";
}

TEST(JobStore, MigrationToSixAddsTheSearchIndexes) {
  TempDir dir("slipfront-store-");
  const auto path = dir.file("db.sqlite");
  Job job = make_job("indexed");
  {
    Database raw(path); // a database written by a build at schema version 5
    for (int v = 0; v < 5; ++v)
      raw.exec(schema_migrations()[static_cast<std::size_t>(v)].sql);
    raw.set_user_version(5);
    raw.exec("INSERT INTO jobs (id, status, spec, spec_sha256, created_at) VALUES ('" + job.id +
             "', 'succeeded', '{}', 'h', '2024')");
    raw.exec("INSERT INTO metrics (job_id, arrest_position, metrics_json) VALUES ('" + job.id +
             "', 12.5, '{}')");
  }
  JobStore store(path);
  EXPECT_EQ(store.user_version(), JobStore::schema_version);
  Database raw(path);
  const std::pair<const char*, const char*> indexes[] = {
      {"metrics_arrest_position", "metrics"},
      {"metrics_propagation_distance", "metrics"},
      {"metrics_arrival_time_at_probe", "metrics"},
      {"jobs_wall_time_s", "jobs"},
      {"jobs_created_at", "jobs"},
      {"jobs_finished_at", "jobs"}};
  for (const auto& [name, table] : indexes) {
    auto s = raw.prepare("SELECT tbl_name FROM sqlite_master WHERE type = 'index' AND name = ?1");
    s.bind(1, std::string(name));
    ASSERT_TRUE(s.step()) << name;
    EXPECT_EQ(s.text(0), table) << name;
  }
  ASSERT_TRUE(store.get(job.id));
}

// The SQL of GET /jobs?where=metrics.arrest_position>10 (JobStore::list with that condition)
// is answered through the index on metrics.arrest_position, not by a scan of every job.
TEST(JobStore, SearchOnArrestPositionUsesItsIndex) {
  TempDir dir("slipfront-store-");
  const auto path = dir.file("db.sqlite");
  JobStore store(path);
  for (int i = 0; i < 20; ++i) {
    Job job = make_job("run" + std::to_string(i));
    store.insert(job);
    ASSERT_TRUE(store.mark_running(job.id, "2024-01-01T00:00:00.000Z", "h", "v"));
    RunRecord r = success();
    r.metrics["arrest_position"] = i;
    ASSERT_TRUE(store.finish(job.id, r));
  }
  JobFilter filter;
  filter.conditions = parse_where("metrics.arrest_position>10");
  const auto page = store.list(filter);
  EXPECT_EQ(page.jobs.size(), 9u);
  const ListQuery query = list_query(filter); // the very SELECT list() ran
  Database raw(path);
  auto s = raw.prepare("EXPLAIN QUERY PLAN " + query.sql);
  bind_all(s, query.params);
  std::string plan;
  while (s.step()) {
    plan += s.text("detail");
    plan += '\n';
  }
  EXPECT_NE(plan.find("metrics_arrest_position"), std::string::npos) << plan;
}

// An import's rows go in together with the end of its intent, or nothing does (services/
// run_import.cpp relies on it: the intent names the files to remove after a failure).
TEST(JobStore, ImportedRunsAreInsertedAllOrNone) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("jobs.db"));
  Job taken = make_job("here");
  store.insert(taken);
  std::vector<JobStore::FinishedRun> runs;
  for (const char* name : {"first", "second"}) {
    JobStore::FinishedRun run{make_job(name), success()};
    run.job.status = JobStatus::succeeded;
    run.job.result = {result_relative_path(run.job.id), 1234, "abc"};
    run.record.result = run.job.result;
    runs.push_back(run);
  }
  const auto intent =
      store.record_file_intent("import", {runs[0].job.result.path, runs[1].job.result.path});
  auto clash = runs;
  clash[1].job.id = taken.id; // taken meanwhile: the whole import is refused
  EXPECT_FALSE(store.insert_finished(clash, intent));
  EXPECT_FALSE(store.get(runs[0].job.id).has_value());
  ASSERT_EQ(store.file_intents().size(), 1u);
  EXPECT_EQ(store.file_intents()[0].paths.size(), 2u);
  EXPECT_EQ(store.result_references().paths.count(runs[0].job.result.path), 0u);

  EXPECT_TRUE(store.insert_finished(runs, intent));
  EXPECT_TRUE(store.file_intents().empty());
  for (const auto& run : runs) {
    auto got = store.get(run.job.id);
    ASSERT_TRUE(got.has_value());
    EXPECT_EQ(got->status, JobStatus::succeeded);
    EXPECT_EQ(got->result.path, run.job.result.path);
    EXPECT_EQ(store.result_references().paths.count(run.job.result.path), 1u);
  }
}

// A delete whose result file goes with the row records, in the same transaction, the intent
// to remove that file: a crash before the file is gone leaves the intent for start-up.
TEST(JobStore, DeletingTheLastRunOfAResultRecordsTheIntentToRemoveIt) {
  TempDir dir("slipfront-store-");
  JobStore store(dir.file("jobs.db"));
  JobStore::FinishedRun own{make_job("own"), success()};
  own.job.status = JobStatus::succeeded;
  own.job.result = {result_relative_path(own.job.id), 1234, "abc"};
  own.record.result = own.job.result;
  JobStore::FinishedRun sharer = own; // a cache hit of it: the same file
  sharer.job.id = new_job_id();
  ASSERT_TRUE(store.insert_finished({own, sharer}, 0));

  auto first = store.remove(own.job.id);
  EXPECT_EQ(first.kind, JobStore::Removal::Kind::removed);
  EXPECT_TRUE(first.orphaned_result.empty()); // the cache hit still refers to it
  EXPECT_EQ(first.intent, 0);
  EXPECT_TRUE(store.file_intents().empty());

  auto last = store.remove(sharer.job.id);
  EXPECT_EQ(last.orphaned_result, own.job.result.path);
  ASSERT_NE(last.intent, 0);
  const auto intents = store.file_intents();
  ASSERT_EQ(intents.size(), 1u);
  EXPECT_EQ(intents[0].kind, "delete");
  EXPECT_EQ(intents[0].paths, std::vector<std::string>{own.job.result.path});
  EXPECT_EQ(store.result_references().paths.count(own.job.result.path), 0u);
  store.forget_file_intent(last.intent);
  EXPECT_TRUE(store.file_intents().empty());
}

// An imported result (and a cache hit of it) is a cache source for its importer only, and only
// when users are authenticated; a database of version 10 learns who imported its results.
TEST(JobStore, AnImportedResultIsReusedByItsImporterOnly) {
  TempDir dir("slipfront-store-");
  const auto path = dir.file("db.sqlite");
  JobStore::FinishedRun imported{make_job("imported"), success()};
  imported.job.status = JobStatus::succeeded;
  imported.job.code_version = "v";
  imported.job.result = {result_relative_path(imported.job.id), 1234, "abc"};
  imported.record.result = imported.job.result;
  imported.job.imported_from = {{"id", "elsewhere"}};
  imported.job.result_imported_by = "alice";
  JobStore::FinishedRun hit = imported; // a cache hit of it: its result, and its importer
  hit.job.id = new_job_id();
  hit.job.imported_from = nullptr;
  hit.job.cached_from = imported.job.id;
  {
    JobStore store(path);
    ASSERT_TRUE(store.insert_finished({imported, hit}, 0));
    const auto& hash = imported.job.spec_sha256;
    EXPECT_FALSE(store.find_reusable(hash, "v", nullptr)) << "anonymous";
    EXPECT_FALSE(store.find_reusable(hash, "v", nullptr, {"alice", false})) << "no tokens";
    EXPECT_FALSE(store.find_reusable(hash, "v", nullptr, {"bob", true}));
    ASSERT_TRUE(store.find_reusable(hash, "v", nullptr, {"alice", true}));
  }
  {
    Database raw(path); // as a build at schema version 10 left it
    raw.exec("ALTER TABLE jobs DROP COLUMN result_imported_by");
    raw.exec("ALTER TABLE jobs DROP COLUMN validation"); // added at version 12
    raw.exec("ALTER TABLE studies DROP COLUMN note");    // added at version 13
    raw.exec("ALTER TABLE studies DROP COLUMN archived_at");
    raw.set_user_version(10);
  }
  JobStore store(path);
  for (const auto& id : {imported.job.id, hit.job.id})
    EXPECT_EQ(store.get(id)->result_imported_by, "alice") << id;
}
