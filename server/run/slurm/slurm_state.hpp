// What a SLURM job state means for a slipfront job. SLURM's states (squeue %T, sacct State)
// fall in three groups: still waiting (PENDING, CONFIGURING, REQUEUED, ...), running
// (RUNNING, COMPLETING, SUSPENDED, ...) and ended (COMPLETED, FAILED, TIMEOUT,
// OUT_OF_MEMORY, CANCELLED, NODE_FAIL, PREEMPTED, BOOT_FAIL, DEADLINE). An ended job is
// collected: its report file decides when there is one; otherwise the state gives the reason.
#pragma once

#include <map>
#include <optional>
#include <string>

namespace slipfront::server {

enum class SlurmPhase { waiting, running, ended };

struct SlurmJobState {
  std::string job_id;
  std::string state;  // e.g. "RUNNING", "TIMEOUT" (sacct's "CANCELLED by 0" is cut to "CANCELLED")
  std::string reason; // squeue's %r: "Resources", "TimeLimit", "None"; "" if unknown
  std::string node;   // where it runs or ran; "" if not yet
};

SlurmPhase slurm_phase(const std::string& state);

// "PENDING (Resources)", "RUNNING on node12", "TIMEOUT (TimeLimit)": the job's `slurm_state`.
std::string describe_slurm_state(const SlurmJobState& state);

// Why an ended SLURM job left no result, for the job's `error`, e.g. "SLURM job 12 ended
// TIMEOUT: it ran past its time limit (--slurm-time-limit)".
std::string slurm_failure_reason(const SlurmJobState& state);

// Lines "ID|STATE|REASON|NODES" (squeue -h -o "%i|%T|%r|%N") keyed by job id. Lines that do
// not have this shape are skipped.
std::map<std::string, SlurmJobState> parse_squeue_output(const std::string& text);

// Lines "ID|STATE" (sacct -n -P -X -o JobID,State), keyed by job id.
std::map<std::string, SlurmJobState> parse_sacct_output(const std::string& text);

} // namespace slipfront::server
