// The JobStore calls behind "Keep, annotate, share" (docs/server.md): tags and note edited
// after submission, archive and restore, delete.
#include "server/core/clock.hpp"
#include "server/db/job_rows.hpp"
#include "server/db/job_store.hpp"

namespace slipfront::server {

std::optional<api::TagsAfter> JobStore::annotate(const std::string& id, const api::TagChange& tags,
                                                 const std::optional<std::string>& note) {
  auto db = db_.lock();
  Transaction tx(*db);
  auto row = db->prepare("SELECT tags FROM jobs WHERE id = ?1");
  row.bind(1, id);
  if (!row.step()) return std::nullopt;
  const auto stored =
      parse_stored_json(row.text(0), "tags of job " + id).get<std::vector<std::string>>();
  api::TagsAfter after = api::apply_tag_change(stored, tags);
  if (after.error) return after;
  auto s = db->prepare("UPDATE jobs SET tags = ?2, note = COALESCE(?3, note) WHERE id = ?1");
  s.bind(1, id).bind(2, nlohmann::json(after.tags).dump()).bind(3, note).run();
  tx.commit();
  return after;
}

bool JobStore::set_archived(const std::string& id, const std::string& archived_at) {
  auto db = db_.lock();
  auto s = db->prepare("UPDATE jobs SET archived_at = ?2 WHERE id = ?1");
  s.bind(1, id)
      .bind(2, archived_at.empty() ? std::nullopt : std::optional<std::string>(archived_at))
      .run();
  return s.changes() == 1;
}

JobStore::Removal JobStore::remove(const std::string& id) {
  using Kind = Removal::Kind;
  auto db = db_.lock();
  Transaction tx(*db);
  auto row = db->prepare("SELECT status, study_id, result_path FROM jobs WHERE id = ?1");
  row.bind(1, id);
  if (!row.step()) return {Kind::not_found, {}, {}};
  const auto status = parse_status(row.text(0));
  if (!status || !is_final(*status)) return {Kind::not_final, {}, {}};
  std::string study_id = row.text(1);
  const std::string result_path = row.text(2);
  if (study_id.empty()) {
    auto member = db->prepare("SELECT study_id FROM study_runs WHERE job_id = ?1 LIMIT 1");
    member.bind(1, id);
    if (member.step()) study_id = member.text(0);
  }
  if (!study_id.empty()) return {Kind::in_study, study_id, {}};
  db->prepare("DELETE FROM metrics WHERE job_id = ?1").bind(1, id).run();
  db->prepare("DELETE FROM jobs WHERE id = ?1").bind(1, id).run();
  Removal removal{Kind::removed, {}, {}};
  if (!result_path.empty()) {
    // A cache hit shares the file of the run it reused: the file goes with the last of them.
    auto users = db->prepare("SELECT count(*) FROM jobs WHERE result_path = ?1");
    users.bind(1, result_path);
    if (users.step() && users.integer(0) == 0) {
      removal.orphaned_result = result_path;
      removal.intent = insert_file_intent(*db, "delete", {result_path}, now_iso8601());
    }
  }
  tx.commit();
  return removal;
}

} // namespace slipfront::server
