// `slipfront validate JOB.json [--threads N] [--max-memory SIZE]`: the job checked as `run`
// would check it, and its mesh and memory estimate.
#include "app/commands.hpp"
#include "app/job_input.hpp"
#include "app/options.hpp"

#include "api/memory_size.hpp"
#include "solver/methods.hpp"

#include <cmath>
#include <iostream>
#include <memory>

namespace slipfront::app {

namespace {

struct ValidateOptions {
  std::string job_path;
  std::optional<int> threads;
  api::ValidationLimits limits;
};

int validate(const ValidateOptions& options);

} // namespace

Command add_validate_command(CLI::App& slipfront) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* command = add_command(
      slipfront, "validate",
      "Check a job without running it, as run would: prints \"ok\", its spec hash, memory "
      "estimate and mesh, or every error as \"pointer: reason\" on stderr.",
      "exit codes: 0 valid, 2 invalid job or command line. The job JSON: docs/api-job-spec.md.");
  add_job_file(*command, options->job_path);
  add_threads(*command, options->threads);
  add_max_memory(*command, options->limits.max_memory_bytes, "8G");
  return {command, [options] { return validate(*options); }};
}

namespace {

int validate(const ValidateOptions& options) {
  const std::optional<api::JobSpec> job =
      load_job("slipfront validate", options.job_path, options.threads, options.limits);
  if (!job) return exit_code::bad_input;

  // The mesh (and the lower solid's) as the method describes it (solver/methods.hpp).
  std::cout << "ok\n"
            << "spec_sha256: " << job->sha256 << '\n'
            << "memory_estimate_bytes: " << std::llround(job->memory_estimate_bytes) << " ("
            << api::byte_size_text(job->memory_estimate_bytes) << ")\n"
            << method_entry(job->params.method).mesh_summary(job->params);
  return exit_code::success;
}

} // namespace

} // namespace slipfront::app
