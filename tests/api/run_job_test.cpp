// run_job with the real solver on small jobs: result file kept only for a finished run.
#include "api/run_files.hpp"
#include "api/run_job.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

slipfront::api::JobSpec small_job(json overrides = json::object()) {
  json job = {{"geometry", {{"nodes_per_meter", 10}}}, {"time", {{"duration", 2.0}}}};
  job.merge_patch(overrides);
  auto parsed = slipfront::api::parse_job(job);
  EXPECT_TRUE(parsed.ok());
  return *parsed.spec;
}

std::string temp_path(const std::string& name) {
  const fs::path directory = fs::path(::testing::TempDir()) / "run_job_test";
  fs::create_directories(directory);
  const fs::path path = directory / name;
  fs::remove(path);
  return path.string();
}

bool anything_left(const std::string& path) {
  for (const auto& entry : fs::directory_iterator(fs::path(path).parent_path())) {
    if (entry.path().string().starts_with(path)) return true;
  }
  return false;
}

// Counts what the solver streams, to check that a caller's own sink still gets the samples.
struct CountingSink : slipfront::SampleSink {
  int begins = 0;
  int samples = 0;
  void begin(const slipfront::InterfaceLayout&) override { ++begins; }
  void write(const slipfront::InterfaceSample&) override { ++samples; }
};

} // namespace

TEST(RunJob, WritesTheResultFileAndReportsItsDigest) {
  const std::string path = temp_path("finished.h5");
  CountingSink own_sink;
  slipfront::RunHooks hooks;
  hooks.sink = &own_sink;
  const auto output = slipfront::api::run_job(small_job(), path, hooks);
  EXPECT_FALSE(output.result.cancelled);
  EXPECT_EQ(output.record.status, slipfront::api::JobStatus::succeeded);
  EXPECT_TRUE(output.record.error.empty());
  EXPECT_EQ(output.record.front, slipfront::api::front_json(output.result));
  EXPECT_EQ(output.record.result.path, path);
  ASSERT_TRUE(fs::exists(path));
  EXPECT_EQ(output.record.result.size, fs::file_size(path));
  EXPECT_EQ(output.record.result.sha256, slipfront::api::sha256_file(path));
  EXPECT_EQ(output.record.metrics["steps"], output.result.metrics.steps);
  EXPECT_EQ(output.record.metrics["method"], "fe");
  EXPECT_NE(
      output.record.metrics["method_description"].get<std::string>().find("top boundary: traction"),
      std::string::npos);
  EXPECT_EQ(own_sink.begins, 1);
  EXPECT_GT(own_sink.samples, 10);
  fs::remove(path);
}

TEST(RunJob, WithoutOutputPathWritesNothing) {
  const auto output = slipfront::api::run_job(small_job(), "");
  EXPECT_TRUE(output.record.result.path.empty());
  EXPECT_EQ(output.record.result.size, 0u);
  EXPECT_TRUE(output.record.result.sha256.empty());
  EXPECT_TRUE(output.record.metrics.contains("outcome"));
}

TEST(RunJob, CancelledRunLeavesNoFile) {
  const std::string path = temp_path("cancelled.h5");
  std::atomic<bool> cancel{true};
  slipfront::RunHooks hooks;
  hooks.cancel = &cancel;
  const auto output = slipfront::api::run_job(small_job(), path, hooks);
  EXPECT_TRUE(output.result.cancelled);
  EXPECT_EQ(output.record.status, slipfront::api::JobStatus::cancelled);
  EXPECT_TRUE(output.record.result.path.empty());
  EXPECT_FALSE(anything_left(path));
}

TEST(RunJob, DivergedRunLeavesNoFileButReturnsMetrics) {
  const std::string path = temp_path("diverged.h5");
  const auto job = small_job({{"friction", {{"L", 1e-7}, {"strength_update", "explicit_euler"}}}});
  const auto output = slipfront::api::run_job(job, path);
  EXPECT_EQ(output.record.metrics["outcome"], "diverged");
  EXPECT_FALSE(output.record.metrics["message"].get<std::string>().empty());
  EXPECT_EQ(output.record.status, slipfront::api::JobStatus::failed);
  EXPECT_EQ(output.record.error, "diverged: " + output.result.metrics.message);
  EXPECT_TRUE(output.record.result.path.empty());
  EXPECT_FALSE(anything_left(path));
}

// The report file (what `slipfront run` writes on a SLURM compute node) carries the run
// record: read back, it is the record run_job returned, for a finished and a diverged run.
TEST(RunJob, TheReportCarriesTheRunRecord) {
  const std::string path = temp_path("reported.h5");
  const auto finished = slipfront::api::run_job(small_job(), path);
  const auto diverged = slipfront::api::run_job(
      small_job({{"friction", {{"L", 1e-7}, {"strength_update", "explicit_euler"}}}}), "");
  for (const auto* output : {&finished, &diverged}) {
    const json report = json::parse(slipfront::api::run_report_json(*output).dump());
    const auto record = slipfront::api::run_record_of_report(report);
    EXPECT_EQ(record.status, output->record.status);
    EXPECT_EQ(record.error, output->record.error);
    EXPECT_EQ(record.metrics, output->record.metrics);
    EXPECT_EQ(record.front, output->record.front);
    EXPECT_EQ(record.result.path, output->record.result.path);
    EXPECT_EQ(record.result.size, output->record.result.size);
    EXPECT_EQ(record.result.sha256, output->record.result.sha256);
  }
  EXPECT_EQ(finished.record.result.path, path);
  EXPECT_EQ(diverged.record.status, slipfront::api::JobStatus::failed);
  fs::remove(path);
}
