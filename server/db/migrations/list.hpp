// The schema migrations, one file each (server/db/migrations.hpp lists them in order).
#pragma once

namespace slipfront::server {
class Database;
}

namespace slipfront::server::migrations {

const char* m1_jobs_and_metrics();
const char* m2_name_and_submitter_indexes();
const char* m3_studies();
void m3_fill_scene_hashes(Database& db);
const char* m4_study_cancelled();
const char* m5_slurm_executor();
const char* m6_search_indexes();
const char* m7_study_idempotency_keys();
const char* m8_accuracy_studies();
const char* m9_run_annotations();
const char* m10_file_intents();
const char* m11_imported_results();
const char* m12_job_validation();
const char* m13_study_annotations();

} // namespace slipfront::server::migrations
