// Reads the slip-velocity record at the spectrum probe (default x1 = 6 m) from a result
// file: /probes/time and /probes/slip_velocity_spectrum (docs/hdf5-layout.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

struct ProbeRecord {
  std::vector<double> time;
  std::vector<double> slip_velocity;
  double x1 = 0.0; // the node's x1 (attribute spectrum_x1 of /probes)
};

// nullopt when the file is missing or lacks the datasets; the reason goes to `why`.
std::optional<ProbeRecord> read_probe_record(const std::string& path, std::string& why);

} // namespace slipfront::server
