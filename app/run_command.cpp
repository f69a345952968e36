// `slipfront run JOB.json [--output RESULT.h5] [--threads N] [--max-memory SIZE] [--quiet]
//                        [--progress-file F] [--report-file F]`
#include "app/commands.hpp"
#include "app/job_input.hpp"
#include "app/progress_display.hpp"

#include "api/result_xdmf.hpp"
#include "api/run_files.hpp"
#include "api/run_job.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>
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

// Parses the arguments; prints the problem and returns nothing if they are wrong.
std::optional<RunOptions> parse_options(const std::vector<std::string>& args) {
  RunOptions options;
  bool have_job = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool has_value = i + 1 < args.size();
    if (arg == "--output" && has_value) {
      options.output_path = args[++i];
    } else if (arg == "--threads" && has_value) {
      try {
        std::size_t used = 0;
        options.threads = std::stoi(args[++i], &used);
        if (used != args[i].size()) throw std::invalid_argument("trailing characters");
      } catch (const std::exception&) {
        std::cerr << "slipfront run: --threads needs an integer, got \"" << args[i] << "\"\n";
        return std::nullopt;
      }
    } else if (arg == "--max-memory" && has_value) {
      const std::optional<double> bytes = parse_memory_size(args[++i]);
      if (!bytes) {
        std::cerr << "slipfront run: --max-memory needs a size such as 8G or 500M, got \""
                  << args[i] << "\"\n";
        return std::nullopt;
      }
      options.limits.max_memory_bytes = *bytes;
    } else if (arg == "--progress-file" && has_value) {
      options.progress_path = args[++i];
    } else if (arg == "--report-file" && has_value) {
      options.report_path = args[++i];
    } else if (arg == "--quiet") {
      options.quiet = true;
    } else if ((arg.starts_with("-") && arg != "-") || have_job) {
      std::cerr << "slipfront run: unexpected argument \"" << arg
                << "\" (see slipfront run --help)\n";
      return std::nullopt;
    } else {
      options.job_path = arg;
      have_job = true;
    }
  }
  if (!have_job) {
    std::cerr << "slipfront run: missing JOB.json (see slipfront run --help)\n";
    return std::nullopt;
  }
  return options;
}

} // namespace

int run_command(const std::vector<std::string>& args) {
  if (wants_help(args)) {
    print_run_usage(std::cout);
    return exit_code::success;
  }
  const std::optional<RunOptions> options = parse_options(args);
  if (!options) return exit_code::bad_input;
  const std::optional<api::JobSpec> job =
      load_job(options->job_path, options->threads, options->limits);
  if (!job) return exit_code::bad_input;

  ProgressDisplay display(std::cerr, ::isatty(STDERR_FILENO) == 1);
  RunHooks hooks;
  hooks.cancel = &interrupted;
  std::string progress_error; // reported once: the run goes on without the file
  hooks.on_progress = [&](const Progress& p) {
    if (!options->quiet) display.update(p);
    if (options->progress_path.empty()) return;
    try {
      api::write_json_atomically(options->progress_path, api::progress_json(p), false);
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
    output = api::run_job(*job, options->output_path, hooks);
  } catch (const std::exception& e) {
    display.finish();
    std::cerr << "slipfront run: " << e.what() << '\n';
    return exit_code::failure;
  }
  display.finish();
  if (!options->quiet && !output.result.cancelled)
    std::cerr << format_final(output.result.metrics, job->params.time.duration) << std::endl;

  if (output.result.cancelled) {
    std::cerr << "slipfront run: interrupted at t = " << output.result.metrics.simulated_time
              << " s; no result file written\n";
    return exit_code::interrupted;
  }

  if (!options->report_path.empty()) {
    try {
      api::write_json_atomically(options->report_path, api::run_report_json(output));
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
  std::cout << printed.dump() << std::endl;

  if (output.result.metrics.outcome == Outcome::diverged) {
    std::cerr << "slipfront run: the run diverged: " << output.result.metrics.message
              << (options->output_path.empty() ? "" : "; no result file written") << '\n';
    return exit_code::diverged;
  }
  return exit_code::success;
}

} // namespace slipfront::app
