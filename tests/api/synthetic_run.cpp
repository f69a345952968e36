#include "synthetic_run.hpp"

#include "api/job_spec.hpp"
#include "api/result_file.hpp"
#include "api/run_job.hpp"

#include <cmath>
#include <limits>

namespace slipfront::testing {

InterfaceLayout synthetic_layout(int nodes) {
  InterfaceLayout layout;
  for (int i = 0; i < nodes; ++i)
    layout.x1.push_back(-10.0 + 0.25 * i);
  layout.sample_interval = 0.1;
  layout.expected_samples = 100;
  return layout;
}

InterfaceSample synthetic_sample(const InterfaceLayout& layout, int k) {
  InterfaceSample sample;
  sample.time = 0.1 * k;
  for (std::size_t i = 0; i < layout.x1.size(); ++i) {
    const double v = k + static_cast<double>(i) / 1000.0;
    sample.slip_velocity.push_back(v);
    sample.slip.push_back(2.0 * v);
    sample.shear_traction.push_back(3.0 * v);
    sample.contact_pressure.push_back(4.0 * v);
    sample.strength.push_back(5.0 * v);
    sample.state.push_back(static_cast<std::int8_t>((k + i) % 3));
  }
  return sample;
}

RunResult synthetic_result(const InterfaceLayout& layout) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  RunResult result;
  result.front.x1 = layout.x1;
  for (std::size_t i = 0; i < layout.x1.size(); ++i) {
    const bool undefined = i == 0 || i + 1 == layout.x1.size();
    result.front.arrival_time.push_back(undefined ? nan : 0.5 * static_cast<double>(i));
    result.front.rupture_speed.push_back(undefined ? nan : 1.5);
  }
  for (int k = 0; k < 10; ++k) {
    result.probes.time.push_back(0.01 * k);
    result.probes.slip_velocity_arrival.push_back(1e-3 * k);
    result.probes.slip_velocity_spectrum.push_back(2e-3 * k);
    result.probes.strength_spectrum.push_back(0.01125 - 1e-4 * k);
    result.energy.time.push_back(0.01 * k);
    result.energy.kinetic.push_back(1.0 * k);
    result.energy.strain.push_back(2.0 * k);
    result.energy.external_work.push_back(4.0 * k);
    result.energy.dissipated.push_back(1.0 * k);
  }
  result.probes.arrival_node_x1 = 11.0;
  result.probes.spectrum_node_x1 = 6.0;
  result.metrics.outcome = Outcome::arrested;
  result.metrics.arrest_position = 12.5;
  result.metrics.arrival_time_at_probe = nan;
  result.metrics.steps = 1234;
  result.mesh = {.nx = static_cast<int>(layout.x1.size()),
                 .ny = 3,
                 .dx = 0.25,
                 .height = 0.5,
                 .stable_dt = 0.1,
                 .dt = 0.05,
                 .threads = 1};
  return result;
}

nlohmann::json synthetic_spec() {
  return api::parse_job({{"name", "synthetic"}, {"friction", {{"L", 1e-5}}}}).spec->canonical;
}

void write_synthetic_file(const std::string& path, int nodes, int samples) {
  const InterfaceLayout layout = synthetic_layout(nodes);
  api::ResultFileWriter writer(path);
  writer.begin(layout);
  for (int k = 0; k < samples; ++k)
    writer.write(synthetic_sample(layout, k));
  const RunResult result = synthetic_result(layout);
  writer.finish(result, synthetic_spec(), api::metrics_json(result));
}

} // namespace slipfront::testing
