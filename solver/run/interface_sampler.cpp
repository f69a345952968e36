#include "solver/run/interface_sampler.hpp"

#include "solver/step_count.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront {

InterfaceSample make_sample(const InterfaceFields& f, double t, int stride) {
  InterfaceSample s;
  s.time = t;
  for (std::size_t i = 0; i < f.x1.size(); i += stride) {
    s.slip_velocity.push_back(f.velocity[i]);
    s.slip.push_back(f.slip[i]);
    s.shear_traction.push_back(f.shear_traction[i]);
    s.contact_pressure.push_back(f.pressure[i]);
    s.strength.push_back(f.strength[i]);
    s.state.push_back(f.state[i]);
  }
  return s;
}

InterfaceSampler::InterfaceSampler(SampleSink* sink, const OutputSampling& output, double dt,
                                   long total_steps, const std::vector<double>& x1)
    : sink_(sink), every_(steps_per_interval(output.interval, dt)),
      stride_(std::max(1, output.space_stride)) {
  if (!sink_) return;
  InterfaceLayout layout;
  for (std::size_t i = 0; i < x1.size(); i += stride_)
    layout.x1.push_back(x1[i]);
  layout.expected_samples = total_steps / every_ + 1;
  layout.sample_interval = every_ * dt;
  sink_->begin(layout);
}

void InterfaceSampler::record(const InterfaceFields& f, long step, double t_n) {
  if (sink_ && due(step)) sink_->write(make_sample(f, t_n, stride_));
}

} // namespace slipfront
