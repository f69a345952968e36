// Streams the interface fields to the SampleSink: every output.space_stride-th node, every
// sample_every = round(output.interval / dt) steps (at least 1), starting with step 0.
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/params.hpp"
#include "solver/run/sample_sink.hpp"

namespace slipfront {

// The sampled nodes of one time sample (every stride-th node from node 0).
InterfaceSample make_sample(const InterfaceFields& f, double t, int stride);

class InterfaceSampler {
public:
  // Announces the layout to the sink (if any); x1: every interface node.
  InterfaceSampler(SampleSink* sink, const OutputSampling& output, double dt, long total_steps,
                   const std::vector<double>& x1);

  bool due(long step) const { return step % every_ == 0; }
  void record(const InterfaceFields& f, long step, double t_n); // writes when due
  int every() const { return every_; }

private:
  SampleSink* sink_;
  int every_, stride_;
};

} // namespace slipfront
