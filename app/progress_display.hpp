// The progress of a run on stderr: a bar redrawn in place (about twice a second) when
// stderr is a terminal, otherwise one plain line every few seconds (logs, pipes).
#pragma once

#include "solver/run/metrics.hpp"
#include "solver/run/run_hooks.hpp"

#include <chrono>
#include <iosfwd>
#include <string>

namespace slipfront::app {

// One line: "[#####.....]  42.0%  t = 6.72 / 16 s  step 934 / 2224  1234 steps/s  wall 0:01
// ETA 0:01" (steps/s and the ETA from the rate since the last report).
std::string format_progress(const Progress& progress);

// The last line of a run, also when it stopped early on arrest: "done: arrested at
// x1 = 12.5 m; t = 9.41 of 16 s simulated (stopped on arrest); 5123 steps; wall 5.1 s".
std::string format_final(const Metrics& metrics, double duration);

class ProgressDisplay {
public:
  ProgressDisplay(std::ostream& out, bool terminal);
  void update(const Progress& progress);
  void finish(); // ends the bar's line on a terminal

private:
  std::ostream& out_;
  bool terminal_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_line_;
};

} // namespace slipfront::app
