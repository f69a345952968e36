// JobService: storing the runs of an archive all together or not at all, and the start-up
// recovery of result files (docs/server.md "Export and import", docs/reliability.md "What
// bounds the disk"). The order of the steps is what makes a crash harmless:
//
//   1. the intent: the result paths the import will create, committed first;
//   2. each result file written under a temporary name, synced, then linked into place;
//   3. one transaction: every row, and the intent forgotten.
//
// A crash before 3 commits leaves an intent naming files no row refers to: the next start
// removes them (and every temporary file). A delete records its intent in the transaction
// that deletes the row, then removes the file, then forgets the intent.
#include "api/job_spec.hpp"
#include "api/json_parse.hpp"
#include "api/result_check.hpp"
#include "server/core/clock.hpp"
#include "server/core/disk_space.hpp"
#include "server/core/file_descriptor.hpp"
#include "server/core/job_id.hpp"
#include "server/core/log.hpp"
#include "server/core/storage_error.hpp"
#include "server/db/study_store.hpp"
#include "server/services/job_service.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <system_error>

namespace slipfront::server {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void storage_failure(const std::string& what, int error) {
  // Disk full, quota, I/O error, read-only: a retry may pass (503), never a 500.
  throw StorageError(what + ": " + std::strerror(error), true);
}

// Writes `bytes` to a new file at `path` (never over an existing one) and syncs it.
void write_new_file(const std::string& path, std::string_view bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) storage_failure("cannot create " + path, errno);
  FileDescriptor owned(fd);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) storage_failure("cannot write " + path, errno);
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) storage_failure("cannot sync " + path, errno);
}

void sync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) storage_failure("cannot open " + dir, errno);
  FileDescriptor owned(fd);
  if (::fsync(fd) != 0) storage_failure("cannot sync " + dir, errno);
}

void remove_quietly(const std::string& path) {
  std::error_code ec;
  fs::remove(path, ec);
}

// Thrown to undo an import whose result file is refused.
struct ImportRefused {};

std::string temporary_name(const std::string& path) {
  return path + ".import.tmp"; // ".tmp": start-up removes it whatever happened
}

// Why the result file at `path` is not the result of `job`, or nullopt when it is: the layout
// of docs/hdf5-layout.md (api/result_check.hpp), and its `spec` attribute the job's physics
// and output settings, as this server reads them.
std::optional<std::string> not_the_result_of(const Job& job, const std::string& path) {
  const nlohmann::json& stations = job.spec.value("stations", nlohmann::json());
  const bool has_stations =
      stations.is_object() && stations.value("x1", nlohmann::json::array()).size() > 0;
  std::string why;
  const auto spec_text = api::check_result_layout(path, has_stations, why);
  if (!spec_text) return why;
  const auto parsed = api::parse_bounded_json(*spec_text);
  if (!parsed.ok()) return std::string("its spec attribute is not JSON");
  api::ValidationLimits limits;
  limits.max_memory_bytes = std::numeric_limits<double>::infinity(); // not run here
  const auto spec = api::parse_job(parsed.value, limits);
  if (!spec.ok() || !spec.spec) return std::string("its spec attribute is not a valid job");
  if (spec.spec->sha256 != job.spec_sha256)
    return std::string("its spec attribute is another run's (spec_sha256 ") + spec.spec->sha256 +
           ", the run's " + job.spec_sha256 + ")";
  if (spec.spec->canonical.value("output", nlohmann::json()) !=
      job.spec.value("output", nlohmann::json()))
    return std::string("its spec attribute has other output settings than the run's");
  return std::nullopt;
}

// Where a run was first computed: the server's host and the run's id there, followed through
// the earlier imports a run's `imported_from` records; a run computed here is (`host`, `id`).
struct RunOrigin {
  std::string host, id;
  bool operator==(const RunOrigin&) const = default;
};

RunOrigin origin_of(const nlohmann::json& imported_from, const std::string& host,
                    const std::string& id) {
  if (!imported_from.is_object()) return {host, id};
  const nlohmann::json* first = &imported_from;
  // An archive's earlier imports are at most 16 kB of JSON: the walk is bounded by it.
  while (first->contains("imported_from") && (*first)["imported_from"].is_object())
    first = &(*first)["imported_from"];
  const nlohmann::json& server = first->value("server", nlohmann::json());
  const nlohmann::json& from = first->value("id", nlohmann::json());
  return {server.is_object() && server.value("host", nlohmann::json()).is_string()
              ? server["host"].get<std::string>()
              : std::string(),
          from.is_string() ? from.get<std::string>() : std::string()};
}

} // namespace

std::optional<ImportResult::Skipped> JobService::already_here(const RunToImport& run) {
  const Job& incoming = run.job;
  const RunOrigin origin = origin_of(incoming.imported_from, "", incoming.id);
  if (origin.id.empty()) return std::nullopt;
  const std::string here = host_name();
  const std::string result =
      incoming.status == JobStatus::succeeded ? incoming.result.sha256 : std::string();
  // Both ways need the same spec: its hash is indexed, and recomputed here for both runs.
  std::optional<ImportResult::Skipped> same_result;
  for (const auto& job : store_.import_candidates(incoming.spec_sha256, origin.id, result)) {
    if (origin_of(job.imported_from, here, job.id) == origin)
      return ImportResult::Skipped{incoming.id, job.id, "same_origin",
                                   "the run " + origin.id + " of " +
                                       (origin.host.empty() ? "its server" : origin.host) +
                                       " is already here as job " + job.id};
    if (!same_result && !result.empty() && job.status == JobStatus::succeeded &&
        job.result_sha256 == result)
      same_result = ImportResult::Skipped{incoming.id, job.id, "same_result",
                                          "job " + job.id +
                                              " has the same spec and the same result file "
                                              "(SHA-256 " +
                                              result + ")"};
  }
  return same_result;
}

std::string JobService::free_import_id(const std::string& wanted,
                                       const std::set<std::string>& chosen) {
  auto taken = [&](const std::string& id) {
    return chosen.contains(id) || store_.get(id).has_value() ||
           fs::exists(result_files_.absolute_path({result_relative_path(id), 0, ""}));
  };
  if (is_valid_job_id(wanted) && !taken(wanted)) return wanted;
  std::string id = new_job_id();
  while (taken(id))
    id = new_job_id();
  return id;
}

ImportResult JobService::import_runs(std::vector<RunToImport> runs, const std::string& user,
                                     bool again, std::optional<StudyToImport> study) {
  // One import at a time: the ids chosen here stay free until its rows are in.
  std::lock_guard import_lock(import_mutex_);
  ImportResult out;
  // A run already here is not stored again: the answer says which one it is.
  std::vector<RunToImport> fresh;
  std::map<std::string, std::string> here; // the archive's run ids -> the ids here
  for (auto& run : runs) {
    if (auto skipped = again ? std::nullopt : already_here(run)) {
      here[skipped->original_id] = skipped->id;
      out.skipped.push_back(std::move(*skipped));
    } else {
      fresh.push_back(std::move(run));
    }
  }
  runs = std::move(fresh);
  // A study's archive: its study, unless one of its id is here (then not stored again).
  if (study) {
    out.study = ImportResult::ImportedStudy{study->study.id, study->study.id, false};
    const bool taken =
        store_.db().with_db([&](Database& db) { return study_exists(db, study->study.id); });
    if (taken && !again) {
      out.study->skipped = true;
      study.reset();
    } else if (taken) {
      std::string id = new_job_id();
      while (store_.db().with_db([&](Database& db) { return study_exists(db, id); }))
        id = new_job_id();
      out.study->id = study->study.id = id;
    }
  }
  if (runs.empty() && !study) return out;
  std::uint64_t result_bytes = 0;
  for (const auto& run : runs)
    result_bytes += run.result.size();
  if (!leaves_free(options_.data_dir.empty() ? "." : options_.data_dir, result_bytes,
                   options_.min_free_bytes)) {
    out.kind = ImportResult::Kind::no_space;
    out.reason = "the data dir's disk has too little free space for the " +
                 std::to_string(result_bytes) + " bytes of result files (--min-free-bytes)";
    return out;
  }
  std::set<std::string> chosen;
  std::vector<std::string> paths;
  for (auto& run : runs) {
    out.ids.push_back({"", run.job.id});
    run.job.id = free_import_id(run.job.id, chosen);
    chosen.insert(run.job.id);
    out.ids.back().first = run.job.id;
    here[out.ids.back().second] = run.job.id;
    run.job.submitted_by = user;
    run.job.result_imported_by = user;             // a cache source for this user only
    if (study) run.job.study_id = study->study.id; // its runs go with it
    run.job.result.path =
        run.job.status == JobStatus::succeeded ? result_relative_path(run.job.id) : std::string();
    run.record.result = run.job.result;
    if (!run.job.result.path.empty()) paths.push_back(run.job.result.path);
  }

  const std::int64_t intent = store_.record_file_intent("import", paths);
  std::vector<std::string> written; // absolute paths of this import's files, to undo
  try {
    for (const auto& run : runs) {
      if (run.job.result.path.empty()) continue;
      const std::string path = result_files_.absolute_path(run.job.result);
      const std::string temporary = temporary_name(path);
      written.push_back(temporary);
      write_new_file(temporary, run.result);
      if (auto why = not_the_result_of(run.job, temporary)) {
        out.kind = ImportResult::Kind::refused;
        out.where = run.member;
        out.reason = *why;
        throw ImportRefused{}; // undone below
      }
      if (::link(temporary.c_str(), path.c_str()) != 0)
        storage_failure("cannot store " + path, errno);
      written.push_back(path);
      remove_quietly(temporary);
    }
    if (!paths.empty())
      sync_directory(
          fs::path(result_files_.absolute_path({paths[0], 0, ""})).parent_path().string());
    std::vector<JobStore::FinishedRun> rows;
    for (auto& run : runs)
      rows.push_back({std::move(run.job), std::move(run.record)});
    // The study lists its runs by their ids here; its stored analysis names them too.
    std::function<void(Database&)> also;
    if (study) {
      study->study.submitted_by = user;
      std::string result = study->study.result.dump();
      for (const auto& [original, id] : here)
        if (original != id)
          for (auto at = result.find(original); at != std::string::npos;
               at = result.find(original, at + id.size()))
            result.replace(at, original.size(), id);
      study->study.result = nlohmann::json::parse(result);
      for (auto& row : study->runs)
        row.job_id = here.at(row.job_id);
      also = [&study](Database& db) { insert_imported_study(db, study->study, study->runs); };
    }
    bool stored = false;
    {
      std::lock_guard lock(submit_mutex_);
      stored = store_.insert_finished(rows, intent, also);
    }
    if (!stored) throw std::runtime_error("an imported run's id was taken meanwhile");
  } catch (...) {
    for (const auto& path : written)
      remove_quietly(path);
    try {
      store_.forget_file_intent(intent);
    } catch (const std::exception& e) { // the next start removes the files it names
      log_error("import undone, its intent stays until the next start: " + std::string(e.what()));
    }
    if (out.kind == ImportResult::Kind::refused) return out;
    throw;
  }
  out.kind = ImportResult::Kind::imported;
  return out;
}

StrayResults JobService::recover_result_files() {
  StrayResults out;
  const ResultReferences refs = store_.result_references();
  // Changes a crash interrupted: their files no row refers to go.
  for (const FileIntent& intent : store_.file_intents()) {
    for (const std::string& path : intent.paths)
      if (!refs.paths.contains(path)) {
        std::error_code ec;
        if (fs::remove(result_files_.absolute_path({path, 0, ""}), ec)) ++out.undone;
      }
    store_.forget_file_intent(intent.id);
    ++out.intents;
  }
  // Any other file without a row (left by an older version, or copied in by hand).
  for (const StrayResult& stray : find_stray_results(options_.data_dir, refs)) {
    std::error_code ec;
    fs::remove(result_files_.absolute_path({stray.path, 0, ""}), ec);
    if (!ec) out.removed.push_back(stray);
  }
  return out;
}

} // namespace slipfront::server
