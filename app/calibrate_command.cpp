// `slipfront calibrate [--data-dir DIR] [--output F] [--thread-count N]...`: times a set of short
// runs of both methods on this machine and fits the cost model of the estimates
// (api/cost_estimate.hpp, docs/performance.md "Cost estimate"): the server reads it from its
// data dir at start, `validate --cost-model F` from the file. With --compare JOB.json..., runs
// those jobs and prints their wall times against the model's estimates instead.
#include "app/commands.hpp"
#include "app/job_input.hpp"
#include "app/options.hpp"

#include "api/cost_estimate.hpp"
#include "api/job_spec.hpp"
#include "api/number_text.hpp"
#include "api/presets.hpp"
#include "api/run_job.hpp"
#include "server/core/clock.hpp"
#include "solver/simulation.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

namespace slipfront::app {

namespace {

struct CalibrateOptions {
  std::string data_dir;
  std::string output;
  std::vector<int> threads;
  std::vector<std::string> compare; // jobs to time against an existing model, not calibrate
  std::string cost_model;
};

// The timed runs: of both methods, one and two solids, damped and not, small and large meshes,
// slip weakening and rate and state, from a fraction of a second to several seconds, so that
// the fit sees each term of the model vary (each three times: about two and a half minutes per
// thread count on the development machine).
std::vector<nlohmann::json> calibration_jobs() {
  const nlohmann::json run_through = {{"stop_on_arrest", false}};
  const api::Preset& rock_preset = *api::find_preset("rock_patch_nd2");
  const nlohmann::json rock = api::preset_job(rock_preset, "fe");
  const nlohmann::json rock_bi = api::preset_job(rock_preset, "spectral_bi");
  const auto with = [](nlohmann::json job, const nlohmann::json& patch) {
    job.merge_patch(patch);
    job.erase("name");
    job.erase("tags");
    return job;
  };
  return {
      {{"geometry", {{"nodes_per_meter", 10}}}, {"time", run_through}},
      {{"geometry", {{"nodes_per_meter", 20}}}, {"time", run_through}},
      {{"geometry", {{"nodes_per_meter", 40}}},
       {"time", {{"duration", 5}, {"stop_on_arrest", false}}}},
      {{"geometry", {{"nodes_per_meter", 40}}},
       {"time", {{"duration", 10}, {"stop_on_arrest", false}}}},
      {{"geometry", {{"nodes_per_meter", 20}}},
       {"fe", {{"mesh_damping", 0.1}}},
       {"time", {{"duration", 8}, {"stop_on_arrest", false}}}},
      with(rock, {{"time", run_through}}),
      {{"preset", "scec_tpv3_2d"}, {"time", {{"duration", 8}}}},
      {{"preset", "bimaterial_slip_weakening"},
       {"geometry", {{"nodes_per_meter", 5}}},
       {"time", {{"duration", 0.02}}}},
      {{"preset", "bimaterial_prakash_clifton"}, {"geometry", {{"nodes_per_meter", 2}}}},
      {{"preset", "rsf_slip_law_inplane"}, {"time", {{"duration", 0.25}}}},
      {{"method", "spectral_bi"}, {"geometry", {{"nodes_per_meter", 10}}}, {"time", run_through}},
      {{"method", "spectral_bi"}, {"geometry", {{"nodes_per_meter", 20}}}, {"time", run_through}},
      {{"method", "spectral_bi"}, {"geometry", {{"nodes_per_meter", 40}}}, {"time", run_through}},
      {{"preset", "bimaterial_prakash_clifton"},
       {"method", "spectral_bi"},
       {"geometry", {{"nodes_per_meter", 2}}},
       {"time", {{"duration", 0.05}}}},
      {{"preset", "bimaterial_slip_weakening"},
       {"method", "spectral_bi"},
       {"geometry", {{"nodes_per_meter", 5}}},
       {"time", {{"duration", 0.05}}}},
      {{"preset", "scec_tpv3_2d"}, {"method", "spectral_bi"}},
      {{"preset", "scec_tpv3_2d"},
       {"method", "spectral_bi"},
       {"geometry", {{"nodes_per_meter", 0.04}}},
       {"time", {{"duration", 1}}}},
      {{"preset", "rsf_slip_law_inplane"},
       {"method", "spectral_bi"},
       {"time", {{"duration", 0.5}}}},
      with(rock_bi, {{"time", run_through}}),
  };
}

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? name : "unknown host";
}

// --compare: each job run once with its result file (its threads as given, else 1: the
// server's), its wall time
// against the model's estimate for the whole duration and for the simulated time it reached
// (a run that stops on arrest ends early). The table of docs/performance.md "Cost estimate".
int compare(const CalibrateOptions& options) {
  const api::CostModel model = options.cost_model.empty()
                                   ? api::CostModel::built_in()
                                   : api::CostModel::read_file(options.cost_model);
  std::printf("%-34s %8s %11s %11s %11s %7s\n", "job", "steps", "est. whole", "est. run",
              "measured", "ratio");
  for (const std::string& path : options.compare) {
    nlohmann::json job = nlohmann::json::parse(read_job_text(path));
    if (!job.contains("threads")) job["threads"] = 1;
    const api::ParseResult parsed = api::parse_job(job);
    if (!parsed.ok())
      throw std::runtime_error(path + ": " + parsed.errors[0].pointer + ": " +
                               parsed.errors[0].reason);
    const SimulationParams& p = parsed.spec->params;
    const std::string method = std::string(p.method.name());
    // With its result file, as the server writes one (and as the calibration runs).
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("slipfront-compare-" + std::to_string(::getpid()) + ".h5"))
                                 .string();
    const RunResult r = api::run_job(*parsed.spec, file).result;
    std::filesystem::remove(file);
    const double whole = api::modelled_wall_time(model, method, p.threads, estimated_work(p));
    const double ran = api::modelled_wall_time(model, method, p.threads,
                                               estimated_work(p, r.metrics.simulated_time));
    std::printf("%-34s %8ld %10.3gs %10.3gs %10.3gs %7.2f\n",
                std::filesystem::path(path).filename().c_str(), r.metrics.steps, whole, ran,
                r.metrics.wall_time_s, ran / r.metrics.wall_time_s);
    std::fflush(stdout);
  }
  return exit_code::success;
}

int calibrate(const CalibrateOptions& options) {
  if (!options.compare.empty()) return compare(options);
  constexpr int repeats = 3; // each job, the median timed
  namespace fs = std::filesystem;
  const std::string path = !options.output.empty() ? options.output
                           : !options.data_dir.empty()
                               ? (fs::path(options.data_dir) / "cost_model.json").string()
                               : "cost_model.json";
  std::vector<int> threads = options.threads;
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  if (threads.empty()) threads = cores > 1 ? std::vector<int>{1, cores} : std::vector<int>{1};
  const fs::path scratch =
      fs::temp_directory_path() / ("slipfront-calibrate-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  std::vector<api::CostSample> samples;
  std::printf("%-8s %-12s %8s %10s %10s\n", "threads", "method", "steps", "wall [s]", "job");
  for (const int t : threads) {
    int index = 0;
    for (nlohmann::json job : calibration_jobs()) {
      job["threads"] = t;
      const api::ParseResult parsed = api::parse_job(job);
      if (!parsed.ok())
        throw std::logic_error("calibration job " + job.dump() + ": " + parsed.errors[0].pointer +
                               ": " + parsed.errors[0].reason);
      // With its result file, as the server writes one; the median of a few runs, so that a
      // moment of load on a shared machine does not set a coefficient.
      const std::string file = (scratch / ("run" + std::to_string(index++) + ".h5")).string();
      std::vector<double> walls;
      double reached = 0;
      for (int k = 0; k < repeats; ++k) {
        const api::JobOutput out = api::run_job(*parsed.spec, file);
        fs::remove(file);
        walls.push_back(out.result.metrics.wall_time_s);
        reached = out.result.metrics.simulated_time;
      }
      std::sort(walls.begin(), walls.end());
      api::CostSample s;
      s.method = std::string(parsed.spec->params.method.name());
      s.threads = t;
      s.work = estimated_work(parsed.spec->params, reached);
      s.wall_time_s = walls[walls.size() / 2];
      samples.push_back(s);
      std::printf("%-8d %-12s %8.0f %10.3f %10d\n", t, s.method.c_str(), s.work.steps,
                  s.wall_time_s, index);
      std::fflush(stdout);
    }
  }
  fs::remove_all(scratch);
  api::CostModel model = api::fit_cost_model(samples);
  model.machine = host_name() + ", " + std::to_string(cores) + " hardware threads";
  model.calibrated_at = server::now_iso8601();
  std::printf("\nthe model against the runs (estimate / measured):\n");
  for (const api::CostSample& s : samples) {
    const double wall = api::modelled_wall_time(model, s.method, s.threads, s.work);
    std::printf("  %-12s threads %d: %8.3f / %8.3f s = %.2f\n", s.method.c_str(), s.threads, wall,
                s.wall_time_s, wall / s.wall_time_s);
  }
  const std::string temp = path + ".tmp";
  {
    std::ofstream out(temp);
    out << model.to_json().dump(2) << '\n';
    if (!out) throw std::runtime_error("cannot write " + temp);
  }
  fs::rename(temp, path);
  std::printf("cost model written to %s\n", path.c_str());
  return exit_code::success;
}

} // namespace

Command add_calibrate_command(CLI::App& slipfront) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* command = add_command(
      slipfront, "calibrate",
      "Time a set of short runs of both methods on this machine (each three times; about two "
      "minutes per thread count) and fit the cost model of the wall-time estimates "
      "(docs/performance.md \"Cost "
      "estimate\"); writes it where the server reads it (DATA_DIR/cost_model.json) or to "
      "--output.",
      "exit codes: 0 written, 1 a run or the file failed, 2 invalid command line. Run it on an "
      "idle machine: the estimates are as good as its timings.");
  command->add_option("--data-dir", options->data_dir, "the server's data dir")->type_name("DIR");
  command->add_option("--output", options->output, "write the model here instead")->type_name("F");
  command
      ->add_option("--thread-count", options->threads,
                   "a thread count to time (repeatable; default 1, the server's per job, and "
                   "all cores, the CLI's)")
      ->type_name("N")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command
      ->add_option("--compare", options->compare,
                   "instead of calibrating: run these jobs (their threads, else 1) and print "
                   "each one's wall time against the estimate of --cost-model (repeatable)")
      ->type_name("JOB.json")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  add_cost_model(*command, options->cost_model, "the built-in model");
  return {command, [options] { return calibrate(*options); }};
}

} // namespace slipfront::app
