#include "server/run/slurm/slurm_job_dir.hpp"

#include "server/core/clock.hpp"
#include "server/core/job_id.hpp"

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace slipfront::server {

namespace fs = std::filesystem;

SlurmJobDir::SlurmJobDir(const std::string& shared_dir, const std::string& job_id)
    : path_(shared_dir + "/jobs/" + job_id) {}

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text)
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::int64_t slurm_memory_mb(double memory_estimate_bytes) {
  const double mib = 1024.0 * 1024.0;
  const double bytes = std::max(0.0, memory_estimate_bytes) * 1.25 + 256.0 * mib;
  return static_cast<std::int64_t>(std::ceil(bytes / mib));
}

namespace {
void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}
} // namespace

void SlurmJobDir::prepare(const Job& job, const std::string& binary,
                          double max_memory_bytes) const {
  // The script is run by a shell and read by sbatch (#SBATCH lines): it holds the operator's
  // paths (quoted), numbers and the job id, never text a client sent (its name and tags are
  // in spec.json, which only `slipfront run` reads, as JSON).
  if (!is_valid_job_id(job.id))
    throw std::runtime_error("refusing to write a batch script for job id \"" + job.id + "\"");
  std::error_code ec;
  fs::remove_all(path_, ec); // an earlier attempt's files must not be taken for this one's
  fs::create_directories(path_, ec);
  if (ec) throw std::runtime_error("cannot create " + path_ + ": " + ec.message());
  write_file(spec(), job.spec.dump(2) + "\n");
  std::ostringstream text;
  text << "#!/bin/sh\n"
       << "# slipfront job " << job.id << ", written by slipfront serve.\n"
       << "# It runs on a compute node; its files are all it shares with the server.\n"
       << "cd " << shell_quote(path_) << " || exit 1\n"
       << shell_quote(binary) << " run spec.json --output result.h5 --quiet"
       << " --progress-file progress.json --report-file report.json"
       << " --max-memory " << static_cast<long long>(std::ceil(max_memory_bytes)) << "\n"
       << "code=$?\n"
       << "echo $code > exit_code.tmp && mv exit_code.tmp exit_code\n"
       << "exit $code\n";
  write_file(script(), text.str());
  fs::permissions(script(),
                  fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                      fs::perms::others_read | fs::perms::others_exec,
                  ec);
}

std::optional<JobProgress> SlurmJobDir::read_progress() const {
  auto text = read_file(progress());
  if (!text) return std::nullopt;
  auto doc = nlohmann::json::parse(*text, nullptr, false);
  if (!doc.is_object()) return std::nullopt;
  JobProgress p;
  p.fraction = doc.value("fraction", 0.0);
  p.time = doc.value("time", 0.0);
  p.duration = doc.value("duration", 0.0);
  p.steps = doc.value("steps", std::int64_t{0});
  p.eta_s = doc.value("eta_s", 0.0);
  p.updated_at = now_iso8601();
  return p;
}

std::optional<nlohmann::json> SlurmJobDir::read_report() const {
  auto text = read_file(report());
  if (!text) return std::nullopt;
  auto doc = nlohmann::json::parse(*text, nullptr, false);
  if (!doc.is_object() || !doc.contains("metrics") || !doc.contains("result_file"))
    throw std::runtime_error("report file " + report() + " is not a run report");
  return doc;
}

std::optional<int> SlurmJobDir::read_exit_code() const {
  auto text = read_file(exit_code());
  if (!text) return std::nullopt;
  try {
    return std::stoi(*text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string SlurmJobDir::log_tail(std::size_t max_bytes) const {
  auto text = read_file(log());
  if (!text) return "";
  std::string tail = text->size() > max_bytes ? text->substr(text->size() - max_bytes) : *text;
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == ' '))
    tail.pop_back();
  for (char& c : tail)
    if (c == '\n') c = ' ';
  return tail;
}

void SlurmJobDir::remove() const {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

} // namespace slipfront::server
