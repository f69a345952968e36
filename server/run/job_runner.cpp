#include "server/run/job_runner.hpp"

#include "api/job_spec.hpp"
#include "api/run_job.hpp"

#include <stdexcept>

namespace slipfront::server {

RunRecord SolverJobRunner::run(const Job& job, const std::string& output_path,
                               const RunHooks& hooks) {
  // The limits were checked at submission; the stored spec is re-read as it was accepted.
  api::ValidationLimits no_limit;
  no_limit.max_memory_bytes = 1e300;
  auto parsed = api::parse_job(job.spec, no_limit);
  if (!parsed.ok()) {
    std::string what = "stored spec of job " + job.id + " no longer validates:";
    for (const auto& e : parsed.errors)
      what += " " + e.pointer + ": " + e.reason + ";";
    throw std::runtime_error(what);
  }
  return api::run_job(*parsed.spec, output_path, hooks).record;
}

} // namespace slipfront::server
