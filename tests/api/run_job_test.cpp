// run_job with the real solver on small jobs: result file kept only for a finished run.
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
  EXPECT_EQ(output.result_path, path);
  ASSERT_TRUE(fs::exists(path));
  EXPECT_EQ(output.result_size, fs::file_size(path));
  EXPECT_EQ(output.result_sha256, slipfront::api::sha256_file(path));
  EXPECT_EQ(output.metrics["steps"], output.result.metrics.steps);
  EXPECT_EQ(output.metrics["method"], "fe");
  EXPECT_NE(output.metrics["method_description"].get<std::string>().find("top boundary: traction"),
            std::string::npos);
  EXPECT_EQ(own_sink.begins, 1);
  EXPECT_GT(own_sink.samples, 10);
  fs::remove(path);
}

TEST(RunJob, WithoutOutputPathWritesNothing) {
  const auto output = slipfront::api::run_job(small_job(), "");
  EXPECT_TRUE(output.result_path.empty());
  EXPECT_EQ(output.result_size, 0u);
  EXPECT_TRUE(output.result_sha256.empty());
  EXPECT_TRUE(output.metrics.contains("outcome"));
}

TEST(RunJob, CancelledRunLeavesNoFile) {
  const std::string path = temp_path("cancelled.h5");
  std::atomic<bool> cancel{true};
  slipfront::RunHooks hooks;
  hooks.cancel = &cancel;
  const auto output = slipfront::api::run_job(small_job(), path, hooks);
  EXPECT_TRUE(output.result.cancelled);
  EXPECT_TRUE(output.result_path.empty());
  EXPECT_FALSE(anything_left(path));
}

TEST(RunJob, DivergedRunLeavesNoFileButReturnsMetrics) {
  const std::string path = temp_path("diverged.h5");
  const auto job = small_job({{"friction", {{"L", 1e-7}, {"strength_update", "explicit_euler"}}}});
  const auto output = slipfront::api::run_job(job, path);
  EXPECT_EQ(output.metrics["outcome"], "diverged");
  EXPECT_FALSE(output.metrics["message"].get<std::string>().empty());
  EXPECT_TRUE(output.result_path.empty());
  EXPECT_FALSE(anything_left(path));
}
