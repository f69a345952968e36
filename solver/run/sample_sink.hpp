// The sampled interface fields a run streams out as it goes (the HDF5 writer of api/ is the
// sink): the sampled nodes once, then one time sample after another.
#pragma once

#include <cstdint>
#include <vector>

namespace slipfront {

// The sampled interface nodes (every `space_stride`-th node).
struct InterfaceLayout {
  std::vector<double> x1;
  long expected_samples = 0; // if the run goes to `duration`
  double sample_interval = 0.0;
};

// One time sample of the interface fields at the sampled nodes (the names of the result
// file's /interface group, docs/hdf5-layout.md).
struct InterfaceSample {
  double time = 0.0;
  std::vector<double> slip_velocity;    // V [m/s], positive towards +x1
  std::vector<double> slip;             // u1 at the interface [m]
  std::vector<double> shear_traction;   // tau1 [Pa] (initially tau1_0)
  std::vector<double> contact_pressure; // p [Pa] (initially |tau2_0|)
  std::vector<double> strength;         // tau_s [Pa]
  std::vector<std::int8_t> state;       // NodeState
};

// Receives the sampled interface fields as the run produces them.
class SampleSink {
public:
  virtual ~SampleSink() = default;
  virtual void begin(const InterfaceLayout& layout) = 0;
  virtual void write(const InterfaceSample& sample) = 0;
};

} // namespace slipfront
