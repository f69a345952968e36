#include "server/db/migrations.hpp"

#include "server/db/migrations/list.hpp"

#include <stdexcept>

namespace slipfront::server {

const std::vector<Migration>& schema_migrations() {
  static const std::vector<Migration> list = {
      {migrations::m1_jobs_and_metrics()},
      {migrations::m2_name_and_submitter_indexes()},
      {migrations::m3_studies(), migrations::m3_fill_scene_hashes},
      {migrations::m4_study_cancelled()},
      {migrations::m5_slurm_executor()},
      {migrations::m6_search_indexes()},
      {migrations::m7_study_idempotency_keys()},
      {migrations::m8_accuracy_studies()},
      {migrations::m9_run_annotations()},
      {migrations::m10_file_intents()},
      {migrations::m11_imported_results()},
      {migrations::m12_job_validation()},
      {migrations::m13_study_annotations()},
  };
  return list;
}

void fill_scene_hashes(Database& db) {
  migrations::m3_fill_scene_hashes(db);
}

void migrate(Database& db) {
  const auto& list = schema_migrations();
  const auto latest = static_cast<std::int64_t>(list.size());
  const auto version = db.user_version();
  if (version > latest)
    throw std::runtime_error("database " + db.path() + " has schema version " +
                             std::to_string(version) + ", newer than this build's " +
                             std::to_string(latest) + ": upgrade slipfront");
  for (auto v = version; v < latest; ++v) {
    const Migration& step = list[static_cast<std::size_t>(v)];
    Transaction tx(db);
    try {
      db.exec(step.sql);
    } catch (const std::exception& e) {
      throw std::runtime_error("migrating " + db.path() + " from schema version " +
                               std::to_string(v) + ": " + e.what());
    }
    if (step.then) step.then(db);
    {
      auto check = db.prepare("PRAGMA foreign_key_check");
      if (check.step())
        throw std::runtime_error("migrating " + db.path() + " to schema version " +
                                 std::to_string(v + 1) + ": a foreign key of table " +
                                 check.text(0) + " no longer holds");
    }
    db.set_user_version(v + 1);
    tx.commit();
  }
}

} // namespace slipfront::server
