#include "server/run/slurm/slurm_state.hpp"

#include <set>
#include <sstream>
#include <vector>

namespace slipfront::server {

namespace {

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(line);
  while (std::getline(in, part, sep))
    parts.push_back(part);
  if (!line.empty() && line.back() == sep) parts.emplace_back();
  return parts;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

// sacct writes "CANCELLED by 0"; squeue "CANCELLED".
std::string first_word(const std::string& s) {
  const auto t = trim(s);
  return t.substr(0, t.find(' '));
}

} // namespace

SlurmPhase slurm_phase(const std::string& state) {
  static const std::set<std::string> waiting = {"PENDING",     "CONFIGURING",  "REQUEUED",
                                                "REQUEUE_FED", "REQUEUE_HOLD", "RESV_DEL_HOLD",
                                                "RESIZING",    "SPECIAL_EXIT", "POWER_UP_NODE"};
  static const std::set<std::string> running = {"RUNNING",   "COMPLETING", "SUSPENDED", "STOPPED",
                                                "SIGNALING", "STAGE_OUT",  "UPDATE_DB"};
  if (waiting.count(state)) return SlurmPhase::waiting;
  if (running.count(state)) return SlurmPhase::running;
  return SlurmPhase::ended; // COMPLETED, FAILED, TIMEOUT, OUT_OF_MEMORY, CANCELLED, ...
}

std::string describe_slurm_state(const SlurmJobState& s) {
  std::string text = s.state;
  if (!s.reason.empty() && s.reason != "None") text += " (" + s.reason + ")";
  if (slurm_phase(s.state) == SlurmPhase::running && !s.node.empty()) text += " on " + s.node;
  return text;
}

std::string slurm_failure_reason(const SlurmJobState& s) {
  const std::string head = "SLURM job " + s.job_id + " ended " + s.state;
  const std::string node = s.node.empty() ? "" : " on " + s.node;
  if (s.state == "TIMEOUT") return head + ": it ran past its time limit (--slurm-time-limit)";
  if (s.state == "OUT_OF_MEMORY")
    return head +
           ": it used more memory than it requested (--mem from the job's memory "
           "estimate)" +
           node;
  if (s.state == "NODE_FAIL") return head + ": its node failed" + node;
  if (s.state == "BOOT_FAIL") return head + ": its node failed to boot" + node;
  if (s.state == "CANCELLED")
    return head + ": cancelled outside slipfront (scancel by a user or an administrator)";
  if (s.state == "PREEMPTED") return head + ": preempted by a higher-priority job";
  if (s.state == "DEADLINE") return head + ": it reached its deadline";
  if (s.state == "COMPLETED")
    return head + " but left no report file (is the shared directory "
                  "shared with the compute nodes?)";
  std::string text = head;
  if (!s.reason.empty() && s.reason != "None") text += " (" + s.reason + ")";
  return text + node;
}

std::map<std::string, SlurmJobState> parse_squeue_output(const std::string& text) {
  std::map<std::string, SlurmJobState> states;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    auto parts = split(line, '|');
    if (parts.size() != 4 || trim(parts[0]).empty() || trim(parts[1]).empty()) continue;
    SlurmJobState s{trim(parts[0]), first_word(parts[1]), trim(parts[2]), trim(parts[3])};
    states[s.job_id] = s;
  }
  return states;
}

std::map<std::string, SlurmJobState> parse_sacct_output(const std::string& text) {
  std::map<std::string, SlurmJobState> states;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    auto parts = split(line, '|');
    if (parts.size() < 2 || trim(parts[0]).empty() || trim(parts[1]).empty()) continue;
    SlurmJobState s{trim(parts[0]), first_word(parts[1]), "",
                    parts.size() > 2 ? trim(parts[2]) : ""};
    states[s.job_id] = s;
  }
  return states;
}

} // namespace slipfront::server
