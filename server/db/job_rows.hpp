// The rows of the jobs and metrics tables as C++ values: their column lists, defined once
// and used by every SELECT and INSERT of server/db/job_store.cpp, and the reading of a row by
// column name.
#pragma once

#include "server/core/job.hpp"
#include "server/db/database.hpp"

#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

// "SELECT <every column of a Job> FROM jobs j LEFT JOIN metrics m ON m.job_id = j.id ":
// append the WHERE / ORDER BY clauses.
const std::string& select_jobs();

// A row of select_jobs().
Job read_job(const Statement& row);
// The same, or nullopt when the row's stored JSON does not parse: "ID: reason" is added to
// `skipped` (a malformed row never breaks a listing, docs/reliability.md).
std::optional<Job> read_job_or_skip(const Statement& row, std::vector<std::string>& skipped);

// "INSERT INTO jobs (<the columns a new job sets>) VALUES (?1, ...)"; bind_new_job binds them.
const std::string& insert_job_sql();
void bind_new_job(Statement& insert, const Job& job);

// The columns of the metrics table after job_id, in table order ("L, n_d, ... front_json").
const std::string& metrics_columns();

} // namespace slipfront::server
