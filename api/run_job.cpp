#include "api/run_job.hpp"

#include "api/result_file.hpp"

#include <filesystem>
#include <optional>

namespace slipfront::api {

namespace {

// Passes every sample to two sinks (the result file and the caller's own sink).
class TeeSink : public SampleSink {
public:
  TeeSink(SampleSink& first, SampleSink& second) : first_(first), second_(second) {}
  void begin(const InterfaceLayout& layout) override {
    first_.begin(layout);
    second_.begin(layout);
  }
  void write(const InterfaceSample& sample) override {
    first_.write(sample);
    second_.write(sample);
  }

private:
  SampleSink& first_;
  SampleSink& second_;
};

// The record of a run that ended (the result file, if any, is added by the caller): the
// metrics with the values the job took and the warnings it was given.
RunRecord record_of(const RunResult& result, const JobSpec& job) {
  const SimulationParams& params = job.params;
  RunRecord record;
  if (result.cancelled) {
    record.status = JobStatus::cancelled;
  } else if (result.metrics.outcome == Outcome::diverged) {
    record.status = JobStatus::failed;
    record.error = diverged_error(result.metrics.message);
  }
  record.metrics = metrics_json(result, params);
  record.metrics["provenance"] = provenance_json(job.provenance);
  record.metrics["job_warnings"] = warnings_json(job.warnings);
  record.front = front_json(result);
  return record;
}

} // namespace

JobOutput run_job(const JobSpec& job, const std::string& output_path, const RunHooks& hooks) {
  JobOutput output;
  if (output_path.empty()) {
    output.result = run_simulation(job.params, hooks);
    output.record = record_of(output.result, job);
    return output;
  }

  ResultFileWriter writer(output_path); // removes its temporary file unless finished
  std::optional<TeeSink> tee;
  RunHooks run_hooks = hooks;
  if (hooks.sink != nullptr) {
    tee.emplace(writer, *hooks.sink);
    run_hooks.sink = &*tee;
  } else {
    run_hooks.sink = &writer;
  }

  output.result = run_simulation(job.params, run_hooks);
  output.record = record_of(output.result, job);
  if (output.record.status != JobStatus::succeeded) {
    writer.abandon();
    return output;
  }
  writer.finish(output.result, job.canonical, output.record.metrics);
  output.record.result = {output_path, std::filesystem::file_size(output_path),
                          sha256_file(output_path)};
  return output;
}

} // namespace slipfront::api
