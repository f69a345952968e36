#include "server/db/file_intents.hpp"

#include <nlohmann/json.hpp>

namespace slipfront::server {

std::int64_t insert_file_intent(Database& db, const std::string& kind,
                                const std::vector<std::string>& paths,
                                const std::string& created_at) {
  auto s = db.prepare("INSERT INTO file_intents (kind, paths, created_at) VALUES (?1, ?2, ?3)");
  s.bind(1, kind).bind(2, nlohmann::json(paths).dump()).bind(3, created_at).run();
  return db.last_insert_rowid();
}

void delete_file_intent(Database& db, std::int64_t id) {
  db.prepare("DELETE FROM file_intents WHERE id = ?1").bind(1, id).run();
}

std::vector<FileIntent> read_file_intents(Database& db) {
  std::vector<FileIntent> intents;
  auto table = db.prepare("SELECT 1 FROM sqlite_master WHERE type = 'table' AND "
                          "name = 'file_intents'");
  if (!table.step()) return intents;
  auto s = db.prepare("SELECT id, kind, paths, created_at FROM file_intents ORDER BY id");
  while (s.step()) {
    FileIntent intent;
    intent.id = s.integer(0);
    intent.kind = s.text(1);
    const auto paths = nlohmann::json::parse(s.text(2), nullptr, false);
    if (paths.is_array())
      for (const auto& p : paths)
        if (p.is_string()) intent.paths.push_back(p.get<std::string>());
    intent.created_at = s.text(3);
    intents.push_back(std::move(intent));
  }
  return intents;
}

ResultReferences read_result_references(Database& db) {
  ResultReferences refs;
  auto paths = db.prepare("SELECT DISTINCT result_path FROM jobs WHERE result_path IS NOT NULL "
                          "AND result_path != ''");
  while (paths.step())
    refs.paths.insert(paths.text(0));
  auto unfinished = db.prepare("SELECT id FROM jobs WHERE status IN ('queued', 'running')");
  while (unfinished.step())
    refs.unfinished_ids.insert(unfinished.text(0));
  return refs;
}

} // namespace slipfront::server
