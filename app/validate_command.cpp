// `slipfront validate JOB.json [--max-memory SIZE]`
#include "app/commands.hpp"
#include "app/job_input.hpp"

#include "solver/mesh_size.hpp"
#include "solver/simulation.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace slipfront::app {

int validate_command(const std::vector<std::string>& args) {
  if (wants_help(args)) {
    print_validate_usage(std::cout);
    return exit_code::success;
  }
  api::ValidationLimits limits;
  std::vector<std::string> jobs;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--max-memory" && i + 1 < args.size()) {
      const std::optional<double> bytes = parse_memory_size(args[++i]);
      if (!bytes) {
        std::cerr << "slipfront validate: --max-memory needs a size such as 8G or 500M, got \""
                  << args[i] << "\"\n";
        return exit_code::bad_input;
      }
      limits.max_memory_bytes = *bytes;
    } else {
      jobs.push_back(args[i]);
    }
  }
  if (jobs.size() != 1) {
    std::cerr
        << "slipfront validate: expects exactly one JOB.json (see slipfront validate --help)\n";
    return exit_code::bad_input;
  }
  const std::optional<api::JobSpec> job = load_job(jobs[0], std::nullopt, limits);
  if (!job) return exit_code::bad_input;

  const Geometry& g = job->params.geometry;
  char mesh[200];
  if (job->params.method == Method::spectral_bi) {
    std::snprintf(mesh, sizeof mesh,
                  "%ld interface nodes, dx = %g m, half-space (spectral boundary integral)",
                  std::lround(g.width * g.nodes_per_meter), 1.0 / g.nodes_per_meter);
  } else {
    const double height = resolved_height(job->params);
    std::snprintf(mesh, sizeof mesh, "%ld x %ld nodes, dx = %g m, height = %g m%s",
                  std::lround(g.width * g.nodes_per_meter),
                  std::lround(height * g.nodes_per_meter) + 1, 1.0 / g.nodes_per_meter, height,
                  g.auto_height ? " (auto)" : "");
  }
  std::cout << "ok\n"
            << "spec_sha256: " << job->sha256 << '\n'
            << "memory_estimate_bytes: " << std::llround(job->memory_estimate_bytes) << " ("
            << job->memory_estimate_bytes / 1e6 << " MB)\n"
            << "mesh: " << mesh << '\n';
  const LowerSolid& lower = job->params.lower;
  if (lower.elastic() && job->params.method == Method::finite_element) {
    const MeshSize m = lower_mesh_size(job->params);
    std::cout << "lower block: " << m.nx << " x " << m.ny << " nodes, height = " << m.height << " m"
              << (lower.auto_height ? " (auto)" : "") << '\n';
  } else if (lower.elastic()) {
    std::cout << "lower solid: elastic half-space\n";
  }
  return exit_code::success;
}

} // namespace slipfront::app
