// Helpers shared by the verification tests of the solver (docs/verification.md).
#pragma once

#include "solver/params.hpp"
#include "solver/run/sample_sink.hpp"

#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

namespace slipfront::verification {

// Prints one "[measure] case: ..." line: the numbers docs/verification.md quotes.
inline void measure(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline void measure(const char* format, ...) {
  char text[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  std::printf("[measure] %s\n", text);
  std::fflush(stdout);
}

// A small block with the paper's material: width x height, n_d nodes per metre, no
// nucleation, one thread, energy sampled every step.
inline SimulationParams small_block(double width, double height, double nodes_per_meter) {
  SimulationParams p;
  p.geometry.width = width;
  p.geometry.height = height;
  p.geometry.x_min = 0.0;
  p.geometry.nodes_per_meter = nodes_per_meter;
  p.nucleation.enabled = false;
  p.threads = 1;
  p.output.interval = 0.0; // every step
  p.time.stop_on_arrest = false;
  return p;
}

// Keeps every interface sample the run streams.
class RecordingSink : public SampleSink {
public:
  InterfaceLayout layout;
  std::vector<InterfaceSample> samples;
  void begin(const InterfaceLayout& l) override { layout = l; }
  void write(const InterfaceSample& s) override { samples.push_back(s); }
};

} // namespace slipfront::verification
