// The SLURM executor's pieces that need no cluster: squeue/sacct parsing, the meaning of
// each SLURM state, the sbatch command line, the batch script, and the store's SLURM
// columns (migration 4 -> 5, re-attach and recovery). The executor itself runs against a
// real single-host SLURM in test_slurm.py.
#include "server/core/job_id.hpp"
#include "server/db/database.hpp"
#include "server/db/job_store.hpp"
#include "server/http/job_json.hpp"
#include "server/run/slurm/slurm_client.hpp"
#include "server/run/slurm/slurm_job_dir.hpp"
#include "server/run/slurm/slurm_state.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace slipfront::server;
using slipfront::server::testing::TempDir;

TEST(SlurmState, SqueueLinesAreParsedAndMalformedOnesSkipped) {
  auto states = parse_squeue_output("12|RUNNING|None|node3\n"
                                    "13|PENDING|Resources|\n"
                                    "garbage line\n"
                                    "14|TIMEOUT|TimeLimit|node1\n");
  ASSERT_EQ(states.size(), 3u);
  EXPECT_EQ(states["12"].state, "RUNNING");
  EXPECT_EQ(states["12"].node, "node3");
  EXPECT_EQ(states["13"].reason, "Resources");
  EXPECT_EQ(describe_slurm_state(states["13"]), "PENDING (Resources)");
  EXPECT_EQ(describe_slurm_state(states["12"]), "RUNNING on node3");
  EXPECT_EQ(describe_slurm_state(states["14"]), "TIMEOUT (TimeLimit)");
}

TEST(SlurmState, SacctCancelledByIsCutToTheState) {
  auto states = parse_sacct_output("20|CANCELLED by 0|n1\n21|OUT_OF_MEMORY|n2\n");
  EXPECT_EQ(states["20"].state, "CANCELLED");
  EXPECT_EQ(states["21"].state, "OUT_OF_MEMORY");
}

TEST(SlurmState, EveryStateOfTheIssueHasItsPhase) {
  EXPECT_EQ(slurm_phase("PENDING"), SlurmPhase::waiting);
  EXPECT_EQ(slurm_phase("RUNNING"), SlurmPhase::running);
  EXPECT_EQ(slurm_phase("COMPLETING"), SlurmPhase::running);
  for (const char* ended :
       {"COMPLETED", "FAILED", "TIMEOUT", "OUT_OF_MEMORY", "CANCELLED", "NODE_FAIL"})
    EXPECT_EQ(slurm_phase(ended), SlurmPhase::ended) << ended;
}

TEST(SlurmState, FailureReasonsSayWhatHappened) {
  auto reason = [](const char* state) {
    return slurm_failure_reason(SlurmJobState{"7", state, "", "n1"});
  };
  EXPECT_NE(reason("TIMEOUT").find("time limit"), std::string::npos);
  EXPECT_NE(reason("OUT_OF_MEMORY").find("memory"), std::string::npos);
  EXPECT_NE(reason("NODE_FAIL").find("node failed on n1"), std::string::npos);
  EXPECT_NE(reason("CANCELLED").find("outside slipfront"), std::string::npos);
  EXPECT_EQ(reason("TIMEOUT").rfind("SLURM job 7 ended TIMEOUT", 0), 0u);
}

TEST(SlurmClient, SbatchAsksForThreadsMemoryAndTheConfiguredLimits) {
  SlurmSettings settings;
  settings.partition = "compute";
  settings.account = "geo";
  settings.time_limit = "2:00:00";
  settings.extra_sbatch_args = {"--qos=long"};
  SlurmClient client(settings);
  auto cmd = client.sbatch_command(
      {"slipfront-abc", "/s/jobs/abc/job.sh", "/s/jobs/abc", "/s/jobs/abc/slurm.out", 4, 1500});
  auto has = [&](const std::string& arg) {
    return std::find(cmd.begin(), cmd.end(), arg) != cmd.end();
  };
  EXPECT_EQ(cmd.front(), "sbatch");
  EXPECT_EQ(cmd.back(), "/s/jobs/abc/job.sh");
  for (const char* arg : {"--parsable", "--job-name=slipfront-abc", "--cpus-per-task=4",
                          "--mem=1500M", "--partition=compute", "--account=geo", "--time=2:00:00",
                          "--qos=long", "--no-requeue", "--chdir=/s/jobs/abc"})
    EXPECT_TRUE(has(arg)) << arg;
  auto whole_node = SlurmClient(SlurmSettings{}).sbatch_command({"n", "s", "d", "l", 0, 100});
  EXPECT_NE(std::find(whole_node.begin(), whole_node.end(), "--exclusive"), whole_node.end())
      << "threads 0 (all hardware threads) takes a whole node";
}

TEST(SlurmClient, ControllerTroubleIsTransientARefusalIsNot) {
  EXPECT_TRUE(is_transient_slurm_error("sbatch exited with 1: sbatch: error: Batch job "
                                       "submission failed: Unable to contact slurm controller"));
  EXPECT_FALSE(is_transient_slurm_error("sbatch exited with 1: sbatch: error: Batch job "
                                        "submission failed: Invalid partition name specified"));
  EXPECT_FALSE(is_transient_slurm_error("sbatch: error: Batch job submission failed: Requested "
                                        "node configuration is not available"));
}

TEST(SlurmJobDir, MemoryRequestCoversTheEstimate) {
  EXPECT_EQ(slurm_memory_mb(0.0), 256);
  EXPECT_GE(slurm_memory_mb(8.0e9) * 1024.0 * 1024.0, 8.0e9 * 1.25);
}

TEST(SlurmJobDir, BatchScriptRunsTheJobAndRecordsItsExitCode) {
  TempDir dir("slipfront-slurm-");
  Job job;
  job.id = new_job_id();
  job.name = "it's quoted";
  job.spec = {{"method", "spectral_bi"}, {"threads", 1}};
  SlurmJobDir files(dir.str(), job.id);
  files.prepare(job, "/opt/slip front/slipfront", 2.0e9);
  std::ifstream in(files.script());
  std::stringstream script;
  script << in.rdbuf();
  EXPECT_NE(script.str().find("'/opt/slip front/slipfront' run spec.json --output result.h5"),
            std::string::npos)
      << script.str();
  EXPECT_NE(script.str().find("--progress-file progress.json --report-file report.json"),
            std::string::npos);
  EXPECT_NE(script.str().find("> exit_code.tmp && mv exit_code.tmp exit_code"), std::string::npos);
  std::ifstream spec(files.spec());
  EXPECT_EQ(nlohmann::json::parse(spec)["method"], "spectral_bi");
  EXPECT_FALSE(files.read_report());
  EXPECT_FALSE(files.read_progress());
  EXPECT_FALSE(files.read_exit_code());
  std::ofstream(files.exit_code()) << "3\n";
  EXPECT_EQ(files.read_exit_code(), 3);
  std::ofstream(files.report()) << "{\"not\": \"a report\"}";
  EXPECT_THROW(files.read_report(), std::runtime_error);
  EXPECT_EQ(shell_quote("a'b"), "'a'\\''b'");
}

namespace {
std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
} // namespace

// The job's name used to be written into a comment line of the script, so a
// name holding a newline ran commands on the compute node or added #SBATCH options.
TEST(SlurmJobDir, BatchScriptHoldsNoTextFromTheClient) {
  TempDir dir("slipfront-slurm-");
  Job plain;
  plain.id = new_job_id();
  plain.spec = {{"method", "spectral_bi"}};
  SlurmJobDir files(dir.str(), plain.id);
  files.prepare(plain, "/opt/slipfront", 2.0e9);
  const std::string expected = read_text(files.script());

  const std::vector<std::string> hostile = {
      "x)\nid > INJECTED\n# (", "x\n#SBATCH --wrap=INJECTED\n",
      "x\r\ntouch INJECTED",    "$(touch INJECTED) `touch INJECTED` ; touch INJECTED",
      "x\u2028touch INJECTED",
  };
  for (const std::string& text : hostile) {
    Job job = plain;
    job.name = text;
    job.tags = {text, "tag-INJECTED"};
    job.spec["name"] = text;
    job.spec["tags"] = job.tags;
    files.prepare(job, "/opt/slipfront", 2.0e9);
    const std::string script = read_text(files.script());
    EXPECT_EQ(script, expected) << "the name changed the script: " << text;
    EXPECT_EQ(script.find("INJECTED"), std::string::npos) << script;
    EXPECT_EQ(script.find("#SBATCH"), std::string::npos) << script;
    // The run still gets the name: in spec.json, which only `slipfront run` reads, as JSON.
    EXPECT_EQ(nlohmann::json::parse(read_text(files.spec()))["name"], text);
  }
}

TEST(SlurmJobDir, NoScriptForAnIdTheServerDidNotMake) {
  TempDir dir("slipfront-slurm-");
  Job job;
  job.id = "x\ntouch INJECTED";
  job.spec = nlohmann::json::object();
  EXPECT_THROW(SlurmJobDir(dir.str(), job.id).prepare(job, "/opt/slipfront", 1e9),
               std::runtime_error);
}

namespace {
Job queued_job(JobStore& store) {
  Job job;
  job.id = new_job_id();
  job.spec = nlohmann::json::object();
  job.spec_sha256.append("h"); // (append: GCC 12 -Wrestrict misfires on = "h" here)
  job.created_at = "2024-01-01T00:00:00.000Z";
  store.insert(job);
  return job;
}
} // namespace

TEST(SlurmStore, SlurmJobIsStoredAndKeptThroughRecoveryButNotThroughRequeue) {
  TempDir dir("slipfront-slurm-");
  JobStore store(dir.file("db.sqlite"));
  Job in_slurm = queued_job(store), not_yet = queued_job(store), local = queued_job(store);
  ASSERT_TRUE(store.mark_running(in_slurm.id, "t", "", "v", "slurm"));
  ASSERT_TRUE(store.set_slurm_job(in_slurm.id, "4242", "PENDING"));
  store.update_slurm_state(in_slurm.id, "RUNNING on n7", "n7");
  ASSERT_TRUE(store.mark_running(not_yet.id, "t", "", "v", "slurm")); // crashed before sbatch
  ASSERT_TRUE(store.mark_running(local.id, "t", "h", "v"));

  auto job = store.get(in_slurm.id);
  EXPECT_EQ(job->executor, "slurm");
  EXPECT_EQ(job->slurm_job_id, "4242");
  EXPECT_EQ(job->slurm_state, "RUNNING on n7");
  EXPECT_EQ(job->host, "n7");
  EXPECT_EQ(store.get(local.id)->executor, "local");
  auto json = job_to_json(*job);
  EXPECT_EQ(json["slurm_job_id"], "4242");
  EXPECT_EQ(json["executor"], "slurm");

  // Start-up with the SLURM executor: only the jobs without a SLURM job are queued again.
  EXPECT_EQ(store.requeue_all_running(true), 2);
  auto reattach = store.running_slurm_jobs();
  ASSERT_EQ(reattach.size(), 1u);
  EXPECT_EQ(reattach[0].id, in_slurm.id);
  EXPECT_EQ(reattach[0].attempts, 1);
  // A re-queue forgets the SLURM job: the next start submits a new one.
  EXPECT_TRUE(store.requeue(in_slurm.id));
  EXPECT_TRUE(store.get(in_slurm.id)->slurm_job_id.empty());
  EXPECT_TRUE(store.running_slurm_jobs().empty());
}

TEST(SlurmStore, MigrationFromFourAddsTheSlurmColumnsToExistingJobs) {
  TempDir dir("slipfront-slurm-");
  const auto path = dir.file("db.sqlite");
  const std::string id(32, 'c');
  {
    Database raw(path); // written by a build at schema version 4
    for (int v = 0; v < 4; ++v)
      raw.exec(schema_migrations()[static_cast<std::size_t>(v)].sql);
    raw.set_user_version(4);
    raw.exec("INSERT INTO jobs (id, status, spec, spec_sha256, created_at) VALUES ('" + id +
             "', 'running', '{}', 'h', '2024')");
  }
  JobStore store(path);
  EXPECT_EQ(store.user_version(), JobStore::schema_version);
  auto job = store.get(id);
  ASSERT_TRUE(job);
  EXPECT_TRUE(job->executor.empty());
  EXPECT_TRUE(job->slurm_job_id.empty());
  EXPECT_EQ(store.requeue_all_running(true), 1) << "a job of an older build was never in SLURM";
}
