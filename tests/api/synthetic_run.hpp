// A synthetic run (no solver): an interface layout, samples with known values and a
// RunResult with front, probes and energy records, for the result-file tests.
#pragma once

#include "solver/run/run_result.hpp"
#include "solver/run/sample_sink.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace slipfront::testing {

InterfaceLayout synthetic_layout(int nodes);

// Sample k: time = 0.1 k, slip_velocity[i] = k + i / 1000, slip = 2 x that, ..., state = (k + i)
// % 3.
InterfaceSample synthetic_sample(const InterfaceLayout& layout, int k);

// Front with NaN (undefined) entries at the first and last node; 10 probe and energy records.
RunResult synthetic_result(const InterfaceLayout& layout);

nlohmann::json synthetic_spec();

// Writes a complete file with `samples` samples of `nodes` nodes through ResultFileWriter.
void write_synthetic_file(const std::string& path, int nodes, int samples);

} // namespace slipfront::testing
