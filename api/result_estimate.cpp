#include "api/result_estimate.hpp"

#include "solver/mesh_size.hpp"
#include "solver/run/station_recorder.hpp"
#include "solver/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slipfront::api {

double estimated_result_bytes(const SimulationParams& params) {
  const MeshSize m = mesh_size(params);
  const double steps = step_count_bound(params); // as in the memory estimate
  const double samples = std::min(params.time.duration / params.output.interval, steps) + 1.0;
  const double stored_nodes = std::ceil(double(m.nx) / params.output.space_stride);
  // Five float64 fields and one int8 per stored node, and the sample's time.
  const double interface = samples * (stored_nodes * (5.0 * 8.0 + 1.0) + 8.0);
  const double probes = steps * 4.0 * 8.0;
  const double stations = StationRecorder::record_bytes(params.stations, steps); // every step
  const double front = 3.0 * 8.0 * m.nx;
  const double overhead = 1.0e6; // metadata, energy series, chunk indices
  return interface + probes + stations + front + overhead;
}

void check_result_size(const JobSpec& job, const ValidationLimits& limits,
                       std::vector<FieldError>& errors) {
  if (job.result_estimate_bytes <= limits.max_result_bytes) return; // NaN is refused
  std::ostringstream out;
  out.precision(3);
  out << "the result file would hold about " << job.result_estimate_bytes / 1e9
      << " GB (estimate, before compression), above the limit of " << limits.max_result_bytes / 1e9
      << " GB: use a larger output.interval or output.space_stride, or a shorter duration";
  errors.push_back({"/output/interval", out.str()});
}

} // namespace slipfront::api
