#include "server/db/run_query_sql.hpp"

#include "server/db/job_rows.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace slipfront::server {

namespace {

// The job columns of the search language (server/core/run_query.cpp names them). `method` of
// records made before the field existed is absent: FE.
const std::map<std::string, std::string> job_column_sql = {
    {"id", "j.id"},
    {"name", "j.name"},
    {"status", "j.status"},
    {"method", "COALESCE(json_extract(j.spec, '$.method'), 'fe')"},
    {"outcome", "m.outcome"},
    {"tag", ""},  // EXISTS over json_each(j.tags): condition_sql
    {"tags", ""}, // the same (the run table's column name)
    {"submitted_by", "j.submitted_by"},
    {"created_at", "j.created_at"},
    {"started_at", "j.started_at"},
    {"finished_at", "j.finished_at"},
    {"study_id", "j.study_id"},
    {"scene_hash", "j.scene_hash"},
    {"spec_sha256", "j.spec_sha256"},
    {"code_version", "j.code_version"},
    {"convergence_status",
     "(SELECT sr.convergence_status FROM study_runs sr WHERE sr.job_id = j.id "
     "ORDER BY sr.rowid DESC LIMIT 1)"},
    {"wall_time_s", "j.wall_time_s"},
    {"memory_estimate_bytes", "j.memory_estimate_bytes"},
    {"attempts", "j.attempts"},
    {"priority", "j.priority"},
    {"L", "j.L"},
    {"n_d", "j.n_d"},
};

// Metrics that are columns of the metrics table (indexed reads, no JSON parsing).
const std::map<std::string, std::string> metric_columns = {
    {"arrest_position", "m.arrest_position"},
    {"propagation_distance", "m.propagation_distance"},
    {"arrival_time_at_probe", "m.arrival_time_at_probe"},
    {"rupture_speed.max", "m.max_rupture_speed"},
    {"rupture_speed.mean", "m.mean_rupture_speed"},
    {"max_slip_velocity", "m.max_slip_velocity"},
    {"outcome", "m.outcome"},
    {"energy_error", "m.energy_error"},
    {"steps", "m.steps"},
    {"dt", "m.dt"},
};

// Spec fields that are columns of the jobs table (indexed).
const std::map<std::string, std::string> spec_columns = {
    {"friction.L", "j.L"},
    {"geometry.nodes_per_meter", "j.n_d"},
};

// The column that holds the field, or nullptr when it is read from the stored JSON.
const std::string* column_of(const RunField& f) {
  const std::map<std::string, std::string>& columns = f.source == FieldSource::job ? job_column_sql
                                                      : f.source == FieldSource::spec
                                                          ? spec_columns
                                                          : metric_columns;
  auto it = columns.find(f.key);
  if (it != columns.end()) return &it->second;
  if (f.source == FieldSource::job)
    throw std::logic_error("the search field " + f.name + " has no column in the jobs database");
  return nullptr;
}

std::string field_sql(const RunField& f, SqlParams& params) {
  if (const std::string* column = column_of(f)) return *column;
  const char* json_column = f.source == FieldSource::spec ? "j.spec" : "m.metrics_json";
  return std::string("json_extract(") + json_column + ", " + params.add("$." + f.key) + ")";
}

const char* op_text(CompareOp op) {
  switch (op) {
  case CompareOp::eq:
    return "=";
  case CompareOp::ne:
    return "!=";
  case CompareOp::lt:
    return "<";
  case CompareOp::le:
    return "<=";
  case CompareOp::gt:
    return ">";
  case CompareOp::ge:
    return ">=";
  }
  return "=";
}

} // namespace

std::string SqlParams::add(std::variant<double, std::string> value) {
  values.push_back(std::move(value));
  // (append, not "?" + string: GCC 12's -Wrestrict misfires on that with -O2, PR 105651)
  std::string placeholder = "?";
  placeholder += std::to_string(values.size());
  return placeholder;
}

std::string condition_sql(const Condition& c, SqlParams& params) {
  if (c.field.type == FieldType::tag) {
    std::string exists =
        "EXISTS (SELECT 1 FROM json_each(j.tags) WHERE json_each.value = " + params.add(c.value) +
        ")";
    return c.op == CompareOp::ne ? "NOT " + exists : exists;
  }
  const std::string field = field_sql(c.field, params); // its JSON path binds first
  // A bare number compares as a number where the field is JSON; columns keep text (SQLite's
  // affinity).
  const bool json = column_of(c.field) == nullptr;
  const auto value =
      c.bare_number && json ? std::variant<double, std::string>(*c.bare_number) : c.value;
  return field + " " + op_text(c.op) + " " + params.add(value);
}

std::string sort_sql(const SortKey& key, SqlParams& params) {
  return field_sql(key.field, params) + (key.descending ? " DESC" : " ASC") + " NULLS LAST";
}

ListQuery list_query(const JobFilter& f) {
  std::string where = "WHERE 1 = 1";
  ListQuery q;
  SqlParams& params = q.params;
  if (!f.statuses.empty()) {
    where += " AND j.status IN (";
    for (std::size_t i = 0; i < f.statuses.size(); ++i)
      where += (i ? ", " : "") + params.add(to_string(f.statuses[i]));
    where += ")";
  }
  if (!f.tag.empty())
    where += " AND EXISTS (SELECT 1 FROM json_each(j.tags) WHERE json_each.value = " +
             params.add(f.tag) + ")";
  auto equal = [&](const char* column, const std::string& value) {
    if (!value.empty()) where += std::string(" AND ") + column + " = " + params.add(value);
  };
  if (f.archived == ArchivedRuns::exclude) where += " AND j.archived_at IS NULL";
  if (f.archived == ArchivedRuns::only) where += " AND j.archived_at IS NOT NULL";
  equal("j.name", f.name);
  equal("m.outcome", f.outcome);
  equal("j.submitted_by", f.submitted_by);
  equal("j.spec_sha256", f.spec_sha256);
  equal("j.scene_hash", f.scene_hash);
  equal("j.study_id", f.study_id);
  auto range = [&](const char* column, const char* op, const std::optional<double>& v) {
    if (v) where += std::string(" AND ") + column + " " + op + " " + params.add(*v);
  };
  range("j.L", ">=", f.L_min);
  range("j.L", "<=", f.L_max);
  range("j.n_d", ">=", f.n_d_min);
  range("j.n_d", "<=", f.n_d_max);
  for (const auto& c : f.conditions)
    where += " AND " + condition_sql(c, params);
  std::string order = " ORDER BY ";
  if (f.sort.empty()) {
    if (f.before_seq) where += " AND j.seq < " + params.add(static_cast<double>(*f.before_seq));
  } else {
    for (const auto& key : f.sort)
      order += sort_sql(key, params) + ", ";
  }
  order += "j.seq DESC";
  std::string tail = " LIMIT " + std::to_string(std::max(1, f.limit) + 1);
  if (!f.sort.empty() && f.offset > 0) tail += " OFFSET " + std::to_string(f.offset);
  q.sql = select_jobs() + where + order + tail;
  return q;
}

void bind_all(Statement& s, const SqlParams& params) {
  for (std::size_t i = 0; i < params.values.size(); ++i)
    std::visit([&](const auto& v) { s.bind(static_cast<int>(i + 1), v); }, params.values[i]);
}

} // namespace slipfront::server
