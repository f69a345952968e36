// The progress of a run on stderr: a bar redrawn in place (about twice a second) when
// stderr is a terminal, otherwise one plain line every few seconds (logs, pipes).
#pragma once

#include "solver/simulation.hpp"

#include <chrono>
#include <iosfwd>
#include <string>

namespace slipfront::app {

// One line: "[#####.....]  42.0%  t = 6.72 / 16 s  1234 steps/s  ETA 0:12".
std::string format_progress(const Progress& progress);

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
