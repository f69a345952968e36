#include "server/run/slurm/slurm_client.hpp"

#include "server/run/slurm/child_process.hpp"

#include <algorithm>
#include <cctype>

namespace slipfront::server {

bool is_transient_slurm_error(const std::string& message) {
  static const char* permanent[] = {"Invalid",       "invalid",           "not exist",
                                    "not available", "violates",          "not permitted",
                                    "Access denied", "Unable to allocate"};
  return std::none_of(std::begin(permanent), std::end(permanent),
                      [&](const char* p) { return message.find(p) != std::string::npos; });
}

std::vector<std::string> SlurmClient::sbatch_command(const SbatchRequest& r) const {
  std::vector<std::string> cmd = {
      "sbatch", "--parsable", "--job-name=" + r.job_name, "--chdir=" + r.working_dir,
      "--output=" + r.log_path, "--ntasks=1",
      // threads 0 (all hardware threads) takes a whole node.
      r.cpus > 0 ? "--cpus-per-task=" + std::to_string(r.cpus) : std::string("--exclusive"),
      "--mem=" + std::to_string(std::max<std::int64_t>(1, r.memory_mb)) + "M",
      // A node failure comes back to the server, which re-queues
      // the job itself (and counts the attempt).
      "--no-requeue"};
  if (!settings_.partition.empty()) cmd.push_back("--partition=" + settings_.partition);
  if (!settings_.account.empty()) cmd.push_back("--account=" + settings_.account);
  if (!settings_.time_limit.empty()) cmd.push_back("--time=" + settings_.time_limit);
  cmd.insert(cmd.end(), settings_.extra_sbatch_args.begin(), settings_.extra_sbatch_args.end());
  cmd.push_back(r.script_path);
  return cmd;
}

std::string SlurmClient::submit(const SbatchRequest& request) const {
  ProgramResult r = run_program(sbatch_command(request), settings_.command_timeout_s);
  if (r.timed_out || r.exit_code != 0) {
    const std::string what = r.describe("sbatch");
    throw SlurmError(what, r.timed_out || is_transient_slurm_error(what));
  }
  // --parsable: "ID" or "ID;CLUSTER".
  std::string id = r.out.substr(0, r.out.find_first_of(";\n"));
  if (id.empty() || !std::all_of(id.begin(), id.end(),
                                 [](unsigned char c) { return std::isdigit(c) || c == '_'; }))
    throw SlurmError("sbatch answered \"" + r.out.substr(0, 200) + "\" instead of a job id", false);
  return id;
}

std::map<std::string, SlurmJobState> SlurmClient::query() const {
  ProgramResult r = run_program({"squeue", "--me", "-h", "-t", "all", "-o", "%i|%T|%r|%N"},
                                settings_.command_timeout_s);
  if (r.timed_out || r.exit_code != 0) throw SlurmError(r.describe("squeue"), true);
  return parse_squeue_output(r.out);
}

std::map<std::string, SlurmJobState>
SlurmClient::query_accounting(const std::vector<std::string>& ids) const {
  if (ids.empty()) return {};
  std::string list;
  for (const auto& id : ids)
    list += (list.empty() ? "" : ",") + id;
  ProgramResult r =
      run_program({"sacct", "-n", "-P", "-X", "-j", list, "-o", "JobID,State,NodeList"},
                  settings_.command_timeout_s);
  if (r.timed_out || r.exit_code != 0) return {}; // accounting off or unreachable
  return parse_sacct_output(r.out);
}

void SlurmClient::cancel(const std::string& job_id) const {
  ProgramResult r = run_program({"scancel", job_id}, settings_.command_timeout_s);
  if (r.timed_out || r.exit_code != 0) throw SlurmError(r.describe("scancel " + job_id), true);
}

} // namespace slipfront::server
