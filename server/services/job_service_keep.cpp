// JobService: what an owner does with a run after submission (docs/server.md "Keep, annotate,
// share"): tags and note, archive and restore, delete.
#include "server/core/clock.hpp"
#include "server/core/log.hpp"
#include "server/services/job_service.hpp"

#include <filesystem>
#include <system_error>

namespace slipfront::server {

namespace {
using Kind = KeepResult::Kind;
} // namespace

KeepResult JobService::annotate(const std::string& id, const std::string& user,
                                const api::TagChange& tags,
                                const std::optional<std::string>& note) {
  auto job = store_.get(id);
  if (!job) return {};
  if (options_.auth_enabled && job->submitted_by != user)
    return {Kind::forbidden, job, {}, false, {}};
  const auto after = store_.annotate(id, tags, note);
  if (!after) return {};
  if (after->error) return {Kind::invalid, job, {}, false, after->error};
  return {Kind::done, get(id), {}, false, {}};
}

KeepResult JobService::set_archived(const std::string& id, const std::string& user, bool archived) {
  auto job = store_.get(id);
  if (!job) return {};
  if (options_.auth_enabled && job->submitted_by != user)
    return {Kind::forbidden, job, {}, false, {}};
  // Archiving an archived run keeps its first archive time.
  if (archived != job->archived_at.empty()) return {Kind::done, get(id), {}, false, {}};
  if (!store_.set_archived(id, archived ? now_iso8601() : std::string())) return {};
  return {Kind::done, get(id), {}, false, {}};
}

KeepResult JobService::remove(const std::string& id, const std::string& user) {
  // Under the submission lock: no submission can pick this run's file as a cache hit between
  // the row's deletion and the file's.
  std::lock_guard lock(submit_mutex_);
  auto job = store_.get(id);
  if (!job) return {};
  if (options_.auth_enabled && job->submitted_by != user)
    return {Kind::forbidden, job, {}, false, {}};
  const JobStore::Removal removal = store_.remove(id);
  using Removed = JobStore::Removal::Kind;
  switch (removal.kind) {
  case Removed::not_found:
    return {};
  case Removed::not_final:
    return {Kind::not_final, job, {}, false, {}};
  case Removed::in_study:
    return {Kind::in_study, job, removal.study_id, false, {}};
  case Removed::removed:
    break;
  }
  bool result_deleted = false;
  if (!removal.orphaned_result.empty()) {
    std::error_code ec;
    const std::string path = result_files_.absolute_path({removal.orphaned_result, 0, ""});
    result_deleted = std::filesystem::remove(path, ec);
    if (ec)
      log_error("job " + id +
                " deleted, but its result file stays until the next start: " + ec.message());
    else
      try {
        store_.forget_file_intent(removal.intent);
      } catch (const std::exception& e) { // harmless: the next start finds the file gone
        log_error("job " + id + " deleted; its intent stays until the next start: " + e.what());
      }
  }
  log_info("job " + id + " deleted by " + user +
           (result_deleted ? " with its result file"
                           : (job->result.path.empty() ? "" : "; its result file is shared")));
  return {Kind::done, job, {}, result_deleted, {}};
}

} // namespace slipfront::server
