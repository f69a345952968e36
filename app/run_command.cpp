// `slipfront run JOB.json [--output RESULT.h5] [--threads N] [--max-memory SIZE] [--quiet]
//                        [--progress-file F] [--report-file F]`
#include "app/commands.hpp"
#include "app/job_input.hpp"
#include "app/options.hpp"
#include "app/progress_display.hpp"

#include "api/json_number.hpp"
#include "api/result_xdmf.hpp"
#include "api/run_files.hpp"
#include "api/run_job.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace slipfront::app {

namespace {

std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void on_sigint(int) {
  interrupted.store(true);
}

// The first SIGINT asks the run to stop (within one step); a second one kills the process.
void install_sigint_handler() {
  struct sigaction action {};
  action.sa_handler = on_sigint;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
}

struct RunOptions {
  std::string job_path;
  std::string output_path;
  std::optional<int> threads;
  api::ValidationLimits limits;
  bool quiet = false;
  std::string progress_path; // rewritten at every progress callback (api/run_files.hpp)
  std::string report_path;   // written once the run has a result (or diverged)
};

int run(const RunOptions& options);

} // namespace

Command add_run_command(CLI::App& slipfront) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* command = add_command(
      slipfront, "run",
      "Run one job in the foreground; progress on stderr (a bar on a terminal, a line every "
      "few seconds otherwise, and a final line with the outcome, arrest position and wall "
      "time), the metrics as one JSON object on stdout.",
      "exit codes: 0 success, 1 the run failed, 2 invalid job or command line, 3 diverged, "
      "130 interrupted (SIGINT). The job JSON: docs/api-job-spec.md.");
  add_job_file(*command, options->job_path);
  command
      ->add_option("--output", options->output_path,
                   "write the HDF5 result file (docs/hdf5-layout.md) and its XDMF sidecar "
                   "RESULT.xdmf (ParaView, VisIt); written only when the run ends with a result")
      ->type_name("RESULT.h5");
  add_threads(*command, options->threads);
  add_max_memory(*command, options->limits.max_memory_bytes, "8G");
  add_quiet(*command, options->quiet);
  command
      ->add_option("--progress-file", options->progress_path,
                   "rewrite F about twice a second with the progress as JSON (fraction, time, "
                   "duration, steps, eta_s, wall_s), written to F.tmp and renamed: what the "
                   "server's SLURM executor follows (docs/cluster.md)")
      ->type_name("F");
  command
      ->add_option("--report-file", options->report_path,
                   "write F once the run has a result or diverged: metrics, front, result "
                   "file (docs/api-job-spec.md \"The CLI\")")
      ->type_name("F");
  return {command, [options] { return run(*options); }};
}

namespace {

int run(const RunOptions& options) {
  const std::optional<api::JobSpec> job =
      load_job("slipfront run", options.job_path, options.threads, options.limits);
  if (!job) return exit_code::bad_input;

  ProgressDisplay display(std::cerr, ::isatty(STDERR_FILENO) == 1);
  RunHooks hooks;
  hooks.cancel = &interrupted;
  std::string progress_error; // reported once: the run goes on without the file
  hooks.on_progress = [&](const Progress& p) {
    if (!options.quiet) display.update(p);
    if (options.progress_path.empty()) return;
    try {
      api::write_json_atomically(options.progress_path, api::progress_json(p), false);
    } catch (const std::exception& e) {
      if (progress_error.empty()) {
        progress_error = e.what();
        std::cerr << "slipfront run: progress file: " << progress_error << '\n';
      }
    }
  };
  install_sigint_handler();

  api::JobOutput output;
  try {
    output = api::run_job(*job, options.output_path, hooks);
  } catch (const std::exception& e) {
    display.finish();
    std::cerr << "slipfront run: " << e.what() << '\n';
    return exit_code::failure;
  }
  display.finish();
  if (!options.quiet && !output.result.cancelled)
    std::cerr << format_final(output.result.metrics, job->params.time.duration) << std::endl;

  if (output.result.cancelled) {
    std::cerr << "slipfront run: interrupted at t = " << output.result.metrics.simulated_time
              << " s; no result file written\n";
    return exit_code::interrupted;
  }

  if (!options.report_path.empty()) {
    try {
      api::write_json_atomically(options.report_path, api::run_report_json(output));
    } catch (const std::exception& e) {
      std::cerr << "slipfront run: report file: " << e.what() << '\n';
      return exit_code::failure;
    }
  }

  nlohmann::json printed = output.record.metrics;
  printed["spec_sha256"] = job->sha256;
  if (!output.record.result.path.empty()) {
    // The XDMF sidecar (ParaView, VisIt) beside the HDF5 file: RESULT.xdmf.
    const std::string xdmf_path =
        std::filesystem::path(output.record.result.path).replace_extension(".xdmf").string();
    try {
      api::write_result_xdmf(output.record.result.path, xdmf_path);
    } catch (const std::exception& e) {
      std::cerr << "slipfront run: writing the XDMF sidecar " << xdmf_path << ": " << e.what()
                << '\n';
      return exit_code::failure;
    }
    printed["result_file"] = {{"path", output.record.result.path},
                              {"bytes", output.record.result.size},
                              {"sha256", output.record.result.sha256},
                              {"xdmf", xdmf_path}};
  }
  api::whole_numbers_as_integers(printed); // "nodes_per_meter": 10, not 10.0
  std::cout << printed.dump() << std::endl;

  if (output.result.metrics.outcome == Outcome::diverged) {
    std::cerr << "slipfront run: the run diverged: " << output.result.metrics.message
              << (options.output_path.empty() ? "" : "; no result file written") << '\n';
    return exit_code::diverged;
  }
  return exit_code::success;
}

} // namespace

} // namespace slipfront::app
