// Schema migration 4 -> 5 (server/db/migrations.hpp): the executor that ran (or runs) a job, and
// its SLURM job while it is in SLURM: the server re-attaches to it after a restart instead of
// running it again.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m5_slurm_executor() {
  return R"sql(
ALTER TABLE jobs ADD COLUMN executor TEXT;
ALTER TABLE jobs ADD COLUMN slurm_job_id TEXT;
ALTER TABLE jobs ADD COLUMN slurm_state TEXT;
CREATE INDEX jobs_slurm ON jobs (status, slurm_job_id);
)sql";
}

} // namespace slipfront::server::migrations
