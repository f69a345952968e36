// Run archives (docs/server.md "Export and import"): a set of finished runs as one tar file
// (server/core/tar_archive.hpp) that another server imports, or a paper keeps.
//
//   manifest.json          format, version, the exporting server, the runs, and every other
//                          member with its size and SHA-256
//   runs/<id>/job.json     the run as GET /jobs/{id} shows it (spec, metrics, provenance,
//                          tags, note), with its rupture front
//   runs/<id>/result.h5    its result file (succeeded runs)
#pragma once

#include "server/core/job.hpp"
#include "server/core/study.hpp"
#include "server/services/job_service.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront::server {

constexpr std::size_t max_archive_runs = 1000;
constexpr const char* archive_format = "slipfront-runs";
constexpr int archive_version = 1;

// An archive refused: `where` names the member (and the JSON pointer inside it, after '#').
class ArchiveRefusal : public std::runtime_error {
public:
  ArchiveRefusal(std::string where, const std::string& reason)
      : std::runtime_error(reason), where_(std::move(where)) {}
  const std::string& where() const { return where_; }

private:
  std::string where_;
};

// What the archive of `jobs` (finished runs) holds besides the result files, made before a
// byte is written, and its exact size in bytes: the disk it will take is reserved first.
struct ArchivePlan {
  std::string manifest;
  std::vector<std::string> job_texts; // runs/<id>/job.json of each job, in order
  std::string study_text;             // study.json of a study's archive ("" = none)
  std::uint64_t size = 0;
};
// Throws ArchiveRefusal when a run's result file is missing or damaged (where = the job id).
// With `study` (the study these jobs are the runs of, as study_archive_json writes it), the
// archive holds it as study.json, named by the manifest's "study".
ArchivePlan plan_run_archive(JobService& service, const std::vector<Job>& jobs,
                             const nlohmann::json* study = nullptr);

// A study as its archive holds it: its record (name, tags, note, kind, request, base, status,
// times, L_c, the stored analysis) and its runs with their places in it.
nlohmann::json study_archive_json(const StudyRecord& study, const std::vector<StudyRunRow>& runs);
// Writes the archive of `jobs` as planned to `fd`. Throws ArchiveRefusal as above (a file
// damaged since), StorageError when the disk refuses the bytes.
void write_run_archive(int fd, JobService& service, const std::vector<Job>& jobs,
                       const ArchivePlan& plan);

// Checks every member of `archive` against the manifest (names, sizes, SHA-256) and every
// run's job.json before it stores anything, then stores the runs for `user`, all of them or
// none (JobService::import_runs): each keeps its id if it is free here, else gets a new one,
// and records where it came from (`imported_from`). Throws ArchiveRefusal naming what does
// not hold, StorageError when the disk refuses a write.
// A run already here is skipped unless `again` (JobService::import_runs).
ImportResult import_run_archive(std::string_view archive, JobService& service,
                                const std::string& user, bool again = false);

} // namespace slipfront::server
