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

std::size_t JobService::remove_rows_and_files(const std::function<RowsRemoved()>& remove_rows,
                                              const std::string& what) {
  std::lock_guard lock(submit_mutex_);
  const RowsRemoved removed = remove_rows();
  std::size_t gone = 0;
  bool all_gone = true;
  for (const auto& result : removed.orphaned_results) {
    std::error_code ec;
    if (std::filesystem::remove(result_files_.absolute_path({result, 0, ""}), ec)) ++gone;
    if (ec) {
      all_gone = false;
      log_error(what + ": the result file " + result +
                " stays until the next start: " + ec.message());
    }
  }
  if (removed.intent != 0 && all_gone) try {
      store_.forget_file_intent(removed.intent);
    } catch (const std::exception& e) { // harmless: the next start finds the files gone
      log_error(what + ": its intent stays until the next start: " + e.what());
    }
  return gone;
}

KeepResult JobService::remove(const std::string& id, const std::string& user) {
  auto job = store_.get(id);
  if (!job) return {};
  if (options_.auth_enabled && job->submitted_by != user)
    return {Kind::forbidden, job, {}, false, {}};
  JobStore::Removal removal;
  const std::size_t gone = remove_rows_and_files(
      [&] {
        removal = store_.remove(id);
        if (removal.kind != JobStore::Removal::Kind::removed) return RowsRemoved{};
        if (removal.orphaned_result.empty()) return RowsRemoved{};
        return RowsRemoved{{removal.orphaned_result}, removal.intent};
      },
      "job " + id + " deleted");
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
  const bool result_deleted = gone > 0;
  log_info("job " + id + " deleted by " + user +
           (result_deleted ? " with its result file"
                           : (job->result.path.empty() ? "" : "; its result file is shared")));
  return {Kind::done, job, {}, result_deleted, {}};
}

} // namespace slipfront::server
