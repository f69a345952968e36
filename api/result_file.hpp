// The HDF5 result file of a run (its layout: docs/hdf5-layout.md).
#pragma once

#include "solver/run/run_result.hpp"
#include "solver/run/sample_sink.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <string>

namespace slipfront::api {

// Streams interface samples into chunked, compressed, extendible datasets of a temporary
// file; finish() adds the front, probes, energy, stations, spec, metrics and code version, closes
// the file and renames it to the final path (atomic on one file system). If the writer is
// destroyed without finish(), the temporary file is removed.
class ResultFileWriter : public SampleSink {
public:
  explicit ResultFileWriter(std::string final_path);
  ~ResultFileWriter() override;
  ResultFileWriter(const ResultFileWriter&) = delete;
  ResultFileWriter& operator=(const ResultFileWriter&) = delete;

  void begin(const InterfaceLayout& layout) override;
  void write(const InterfaceSample& sample) override;

  void finish(const RunResult& result, const nlohmann::json& canonical_spec,
              const nlohmann::json& metrics);
  // Removes the temporary file without flushing what is still buffered (a cancelled or
  // diverged run; also done by the destructor and after any error of the file).
  void abandon();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace slipfront::api
