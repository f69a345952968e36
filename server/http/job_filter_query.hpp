// The query parameters of GET /api/v1/jobs: the listing's filter, page and fields, with
// every bad parameter named by pointer (/query/<name>). Also the small value parsers the
// other job endpoints share (fresh, priority, fields).
#pragma once

#include "api/job_spec.hpp"
#include "server/core/job_filter.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

// "true"/"1"/"yes", "false"/"0"/"no"; nullopt otherwise.
std::optional<bool> parse_bool(const std::string& s);
// A finite number (from_chars also reads "nan" and "inf", which no filter can mean).
std::optional<double> parse_finite_double(const std::string& s);
// A whole decimal integer, nothing else around it.
std::optional<long> parse_long(const std::string& s);
// "a,,b," -> {"a", "b"}.
std::vector<std::string> split_commas(const std::string& s);

struct JobFilterQuery {
  JobFilter filter;
  std::vector<std::string> fields; // fields=a,b (empty = every field)
  std::string format = "json";     // json | csv | ndjson (the run table export)
  std::vector<api::FieldError> errors;
};

// format=csv or format=ndjson: the query asks for the run table (an export, up to 100000
// rows), not a page of jobs.
bool asks_for_export(const std::map<std::string, std::string>& query);

JobFilterQuery parse_job_filter(const std::map<std::string, std::string>& query);

} // namespace slipfront::server
