// `slipfront validate JOB.json [--threads N] [--max-memory SIZE]`: the job checked as `run`
// would check it, and its mesh and memory estimate.
#include "app/commands.hpp"
#include "app/job_input.hpp"
#include "app/options.hpp"

#include "api/cost_estimate.hpp"
#include "api/memory_size.hpp"
#include "api/number_text.hpp"
#include "solver/methods.hpp"
#include "solver/simulation.hpp"

#include <cmath>
#include <iostream>
#include <memory>

namespace slipfront::app {

namespace {

struct ValidateOptions {
  std::string job_path;
  std::optional<int> threads;
  api::ValidationLimits limits;
  std::string cost_model;
};

// The model of --cost-model F, else the built-in one.
api::CostModel cost_model(const std::string& path) {
  return path.empty() ? api::CostModel::built_in() : api::CostModel::read_file(path);
}

int validate(const ValidateOptions& options);

} // namespace

Command add_validate_command(CLI::App& slipfront) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* command = add_command(
      slipfront, "validate",
      "Check a job without running it, as run would: prints \"ok\", its spec hash, memory "
      "estimate, mesh and cost estimate (steps, dt, wall time), the values it takes that it did "
      "not give, and its warnings on stderr; or every error as \"pointer: reason\" on stderr.",
      "exit codes: 0 valid, 2 invalid job or command line. The job JSON: docs/api-job-spec.md.");
  add_job_file(*command, options->job_path);
  add_threads(*command, options->threads);
  add_max_memory(*command, options->limits.max_memory_bytes, "8G");
  add_cost_model(*command, options->cost_model, "the built-in model");
  return {command, [options] { return validate(*options); }};
}

namespace {

int validate(const ValidateOptions& options) {
  const std::optional<api::JobSpec> job =
      load_job("slipfront validate", options.job_path, options.threads, options.limits);
  if (!job) return exit_code::bad_input;
  api::CostModel model;
  try {
    model = cost_model(options.cost_model);
  } catch (const std::exception& e) {
    std::cerr << "slipfront validate: --cost-model " << e.what() << '\n';
    return exit_code::bad_input;
  }

  // The mesh (and the lower solid's) as the method describes it (solver/methods.hpp).
  std::cout << "ok\n"
            << "spec_sha256: " << job->sha256 << '\n'
            << "memory_estimate_bytes: " << std::llround(job->memory_estimate_bytes) << " ("
            << api::byte_size_text(job->memory_estimate_bytes) << ")\n"
            << method_entry(job->params.method).mesh_summary(job->params);
  const api::CostEstimate e = api::estimate_cost(job->params, job->memory_estimate_bytes, model);
  std::cout << "estimate: " << api::number_text(e.steps, 6)
            << " steps of dt = " << api::number_text(e.dt, 4) << " s, " << e.threads << " thread"
            << (e.threads == 1 ? "" : "s") << ", about " << api::wall_time_text(e.wall_time_s)
            << (e.stops_on_arrest ? " at most (the run ends earlier once the rupture arrests)" : "")
            << " (" << e.model << ")\n";
  // The values with a unit the job did not give, and where they came from.
  for (const api::ValueSource& v : job->provenance)
    if (v.source.rfind("derived", 0) == 0)
      std::cout << "derived: " << v.pointer << " = " << api::number_text(v.value, 6) << " "
                << v.unit << " (" << v.source.substr(std::string("derived: ").size()) << ")\n";
  return exit_code::success;
}

} // namespace

} // namespace slipfront::app
