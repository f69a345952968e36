#include "api/run_files.hpp"

#include "api/run_job.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace slipfront::api {

nlohmann::json progress_json(const Progress& p) {
  return {{"fraction", p.fraction}, {"time", p.time},   {"duration", p.duration},
          {"steps", p.step},        {"eta_s", p.eta_s}, {"wall_s", p.wall_s}};
}

nlohmann::json run_report_json(const JobOutput& output) {
  const RunRecord& record = output.record;
  nlohmann::json report;
  report["metrics"] = record.metrics;
  report["front"] = record.front;
  if (record.result.path.empty())
    report["result_file"] = nullptr;
  else
    report["result_file"] = {{"path", record.result.path},
                             {"bytes", record.result.size},
                             {"sha256", record.result.sha256}};
  const bool diverged = output.result.metrics.outcome == Outcome::diverged;
  report["diverged"] = diverged;
  report["message"] = diverged ? output.result.metrics.message : "";
  return report;
}

RunRecord run_record_of_report(const nlohmann::json& report) {
  RunRecord record;
  record.metrics = report.value("metrics", nlohmann::json());
  record.front = report.value("front", nlohmann::json());
  if (report.value("diverged", false)) {
    record.status = JobStatus::failed;
    record.error = diverged_error(report.value("message", std::string()));
  } else if (const auto file = report.find("result_file");
             file != report.end() && file->is_object()) {
    record.result = {file->value("path", std::string()), file->value("bytes", std::uint64_t{0}),
                     file->value("sha256", std::string())};
  }
  return record;
}

namespace {
[[noreturn]] void fail(const std::string& what, const std::string& path, int error) {
  throw std::runtime_error(what + " " + path + ": " + std::strerror(error));
}
} // namespace

void write_json_atomically(const std::string& path, const nlohmann::json& doc, bool durable) {
  const std::string temporary = path + ".tmp";
  const std::string text = doc.dump() + "\n";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("cannot create", temporary, errno);
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      fail("cannot write", temporary, error);
    }
    written += static_cast<std::size_t>(n);
  }
  if ((durable && ::fsync(fd) != 0) || ::close(fd) != 0) fail("cannot flush", temporary, errno);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("cannot rename into", path, errno);
}

} // namespace slipfront::api
