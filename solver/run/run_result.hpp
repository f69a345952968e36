// What a run returns: the metrics (docs/metrics.md), the front profile, the probe, station
// and energy records, the discretisation that was run, and whether it was cancelled.
#pragma once

#include "solver/mesh_info.hpp"
#include "solver/run/metrics.hpp"
#include "solver/run/records.hpp"

namespace slipfront {

struct RunResult {
  Metrics metrics;
  FrontProfile front;
  ProbeRecords probes;
  StationRecords stations;
  EnergyRecords energy;
  MeshInfo mesh;
  bool cancelled = false;
};

} // namespace slipfront
