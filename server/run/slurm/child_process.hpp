// Runs a program (no shell) and collects its exit status and output, with a time bound:
// how the SLURM executor calls sbatch, squeue, sacct and scancel.
#pragma once

#include <string>
#include <vector>

namespace slipfront::server {

struct ProgramResult {
  int exit_code = -1;     // the exit status; 128 + N if killed by signal N
  bool timed_out = false; // killed after the time bound
  std::string out, err;   // standard output and error (each at most 1 MiB kept)
  // "sbatch exited with 1: <first line of stderr>" and the like, for error messages.
  std::string describe(const std::string& program) const;
};

// Runs argv[0] (searched in PATH) with the arguments. Throws std::runtime_error if it
// cannot be started at all (the message names the program and the system error).
ProgramResult run_program(const std::vector<std::string>& argv, double timeout_s);

} // namespace slipfront::server
