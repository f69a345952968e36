// Which jobs a listing wants (GET /api/v1/jobs: filters, the search conditions and sort keys
// of server/core/run_query.hpp, the page) and the page it gets back. The SQL that answers it
// is the store's (server/db/run_query_sql.hpp).
#pragma once

#include "server/core/job.hpp"
#include "server/core/run_query.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

// Archived runs (docs/server.md, "Keep, annotate, share"): listed or not.
enum class ArchivedRuns { include, exclude, only };

struct JobFilter {
  std::vector<JobStatus> statuses; // any of these (empty = all)
  std::string tag;                 // jobs carrying this tag
  std::string name;                // exact name
  std::string outcome;             // metrics outcome (finished jobs only)
  std::string submitted_by;
  std::string spec_sha256;
  std::string scene_hash;
  std::string study_id;
  ArchivedRuns archived = ArchivedRuns::include;        // GET /jobs: exclude unless ?archived=...
  std::optional<double> L_min, L_max, n_d_min, n_d_max; // inclusive ranges
  std::optional<std::int64_t> before_seq;               // cursor: jobs older than this
  std::vector<Condition> conditions;                    // `where` (server/core/run_query.hpp)
  std::vector<SortKey> sort; // `sort`; empty = newest first (then pages by before_seq)
  std::int64_t offset = 0;   // with `sort`: rows to skip (the cursor of sorted listings)
  int limit = 50;
};

struct JobPage {
  std::vector<Job> jobs;                   // newest first, or in `sort` order
  std::optional<std::int64_t> next_cursor; // before_seq of the next page (newest first)
  std::optional<std::int64_t> next_offset; // offset of the next page (sorted listings)
  std::map<std::string, std::string> convergence_status; // job id -> status, if in a study
  // Rows of the page that could not be read (stored JSON that does not parse): left out, and
  // reported as "ID: reason" (docs/server.md, GET /jobs).
  std::vector<std::string> skipped;
};

} // namespace slipfront::server
