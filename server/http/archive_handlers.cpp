// GET /exports (a set of finished runs as one tar file) and POST /imports (such a file
// stored here): docs/server.md "Export and import", the format in server/http/run_archive.hpp.
#include "api/json_fields.hpp"
#include "api/json_parse.hpp"
#include "api/number_text.hpp"
#include "server/core/disk_space.hpp"
#include "server/core/file_descriptor.hpp"
#include "server/core/job_id.hpp"
#include "server/core/storage_error.hpp"
#include "server/http/handlers.hpp"
#include "server/http/job_filter_query.hpp"
#include "server/http/range_file.hpp"
#include "server/http/responses.hpp"
#include "server/http/run_archive.hpp"

#include <boost/beast/http/basic_file_body.hpp>

#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <variant>

namespace slipfront::server {

namespace {

using RangeFileBody = http::basic_file_body<RangeFile>;

using Chosen = std::variant<std::vector<Job>, Response>;

// The jobs of `ids` (each once, in the order given) or the refusal naming `pointer`: 400 for
// none or more than max_archive_runs, 404 for an id that names no job (`pointer` + its index
// for a JSON list, the pointer alone for the query).
Chosen jobs_of(ServerContext& ctx, const Request& req, const std::vector<std::string>& given,
               const std::string& pointer, bool indexed, http::status too_many) {
  std::vector<std::string> ids;
  for (const auto& id : given)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  if (ids.empty() || ids.size() > max_archive_runs)
    return problem_response(
        req, too_many, "invalid list of runs",
        {{pointer, "must list 1 to " + std::to_string(max_archive_runs) + " job ids"}});
  std::vector<Job> jobs;
  for (const auto& id : ids) {
    auto job = is_valid_job_id(id) ? ctx.service.get(id) : std::nullopt;
    if (!job) {
      const auto at = std::find(given.begin(), given.end(), id) - given.begin();
      const std::string shown = api::cut_text(id, 64);
      return problem_response(
          req, http::status::not_found, "no job with id " + shown,
          {{indexed ? pointer + "/" + std::to_string(at) : pointer, "no job with id " + shown}});
    }
    jobs.push_back(std::move(*job));
  }
  return jobs;
}

// The runs of POST /exports: {"ids": [...]} (1 to max_archive_runs job ids, more than a
// query string holds).
Chosen runs_of_body(ServerContext& ctx, RequestContext& rc) {
  const auto& req = rc.request;
  auto body = api::parse_bounded_json(req.body());
  if (body.status == api::JsonParse::Status::syntax)
    return problem_response(req, http::status::bad_request, "the body is not valid JSON",
                            {body.error});
  if (!body.ok())
    return problem_response(req, http::status::unprocessable_entity, "invalid body", {body.error});
  const auto& doc = body.value;
  if (!doc.is_object() || doc.size() != 1 || !doc.contains("ids") || !doc["ids"].is_array())
    return problem_response(req, http::status::unprocessable_entity, "invalid body",
                            {{"/ids", "give {\"ids\": [job ids]} and nothing else"}});
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < doc["ids"].size(); ++i) {
    if (!doc["ids"][i].is_string())
      return problem_response(req, http::status::unprocessable_entity, "invalid body",
                              {{"/ids/" + std::to_string(i), "must be a job id (a string)"}});
    ids.push_back(doc["ids"][i].get<std::string>());
  }
  return jobs_of(ctx, req, ids, "/ids", true, http::status::unprocessable_entity);
}

// The runs an export asks for: ?ids=a,b,... or the filters of GET /jobs (a search, a study,
// a tag). Either the jobs or the refusal.
Chosen runs_to_export(ServerContext& ctx, RequestContext& rc) {
  const auto& req = rc.request;
  std::vector<Job> jobs;
  if (auto it = rc.query.find("ids"); it != rc.query.end()) {
    if (rc.query.size() != 1)
      return problem_response(req, http::status::bad_request, "invalid query parameters",
                              {{"/query/ids", "give ids alone, or the filters of GET /jobs"}});
    auto chosen =
        jobs_of(ctx, req, split_commas(it->second), "/query/ids", false, http::status::bad_request);
    if (auto* refusal = std::get_if<Response>(&chosen)) return std::move(*refusal);
    jobs = std::move(std::get<std::vector<Job>>(chosen));
  } else {
    auto query = parse_job_filter(rc.query);
    if (rc.query.count("limit") || rc.query.count("cursor") || rc.query.count("fields") ||
        rc.query.count("format"))
      query.errors.push_back({"/query", "an export takes ids or filters (no limit, cursor, "
                                        "fields or format)"});
    if (!query.errors.empty())
      return problem_response(req, http::status::bad_request, "invalid query parameters",
                              query.errors);
    if (rc.query.empty())
      return problem_response(req, http::status::bad_request, "invalid query parameters",
                              {{"/query", "name the runs: ids=..., study_id=..., tag=..., "
                                          "where=... (the filters of GET /jobs)"}});
    JobFilter& f = query.filter;
    if (f.statuses.empty())
      f.statuses = {JobStatus::succeeded, JobStatus::failed, JobStatus::cancelled};
    f.limit = static_cast<int>(max_archive_runs);
    JobPage page = ctx.service.list(f);
    if (page.next_cursor || page.next_offset)
      return problem_response(req, http::status::unprocessable_entity,
                              "more than " + std::to_string(max_archive_runs) +
                                  " runs match: narrow the search");
    jobs = std::move(page.jobs);
    if (jobs.empty())
      return problem_response(req, http::status::not_found, "no finished run matches");
  }
  for (const Job& job : jobs)
    if (!is_final(job.status))
      return problem_response(req, http::status::conflict,
                              "job " + job.id + " is " + to_string(job.status) +
                                  ": only finished runs are exported");
  return jobs;
}

// The disk an archive of `size` bytes would take: nullopt when it may be written, else the
// refusal (422 past the whole bound, 503 while other archives hold it or the disk is short).
std::optional<Response> refuse_archive_space(ServerContext& ctx, const Request& req,
                                             std::uint64_t size,
                                             std::optional<ByteReservation>& reserved) {
  const std::uint64_t limit = ctx.export_bytes->limit();
  if (size > limit)
    return problem_response(req, http::status::unprocessable_entity,
                            "the archive would take " + std::to_string(size) +
                                " bytes, more than this server writes for exports "
                                "(--max-export-bytes " +
                                std::to_string(limit) + "): export fewer runs at a time");
  reserved = ByteReservation::take(ctx.export_bytes, size);
  if (!reserved)
    return unavailable_response(req,
                                "archives not yet read by their clients take " +
                                    std::to_string(ctx.export_bytes->held()) + " of the " +
                                    std::to_string(limit) +
                                    " bytes this server writes for exports "
                                    "(--max-export-bytes); retry later",
                                ctx.retry_after_s);
  if (!leaves_free(ctx.data_dir, size, ctx.min_free_bytes))
    return unavailable_response(req,
                                "the data dir's disk has too little free space for an archive of " +
                                    std::to_string(size) + " bytes (--min-free-bytes " +
                                    api::number_text(ctx.min_free_bytes) + "); retry later",
                                ctx.retry_after_s);
  return std::nullopt;
}

Response archive_response(ServerContext& ctx, const Request& req, const std::vector<Job>& jobs,
                          const nlohmann::json* study, const std::string& file_name);

// GET /exports (ids or filters in the query) and POST /exports ({"ids": [...]}).
Response export_archive(ServerContext& ctx, RequestContext& rc, bool ids_in_body) {
  // Exports may take much disk and bandwidth: on a shared server they need a token, as writes do.
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& req = rc.request;
  if (ids_in_body && !rc.query.empty())
    return problem_response(req, http::status::bad_request, "invalid query parameters",
                            {{"/query", "POST /exports takes its ids in the body only"}});
  auto chosen = ids_in_body ? runs_of_body(ctx, rc) : runs_to_export(ctx, rc);
  if (auto* refusal = std::get_if<Response>(&chosen)) return std::move(*refusal);
  return archive_response(ctx, req, std::get<std::vector<Job>>(chosen), nullptr,
                          "slipfront-runs-" +
                              std::to_string(std::get<std::vector<Job>>(chosen).size()));
}

// GET /studies/{id}/export: a study that is over with its runs, as one archive (study.json
// beside the runs' members).
Response export_study(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& req = rc.request;
  const auto& id = rc.path_params.at("id");
  if (!rc.query.empty())
    return problem_response(
        req, http::status::bad_request, "invalid query parameters",
        {{"/query/" + api::cut_text(rc.query.begin()->first, 64), "unknown query parameter"}});
  auto view = is_valid_job_id(id) ? ctx.studies.view(id) : std::nullopt;
  if (!view) return problem_response(req, http::status::not_found, "no study with id " + id);
  if (view->study.status == api::StudyStatus::running)
    return problem_response(req, http::status::conflict,
                            "study " + id +
                                " is running: export it once it is over (or cancel it first)");
  if (view->runs.size() > max_archive_runs)
    return problem_response(req, http::status::unprocessable_entity,
                            "study " + id + " has more than " + std::to_string(max_archive_runs) +
                                " runs, more than an archive holds");
  std::vector<Job> jobs;
  for (const auto& run : view->runs) {
    auto job = ctx.service.get(run.job_id);
    if (!job) throw std::runtime_error("run " + run.job_id + " of study " + id + " vanished");
    if (!is_final(job->status))
      return problem_response(req, http::status::conflict,
                              "run " + job->id + " of study " + id + " is " +
                                  to_string(job->status) + ": export the study once it stops");
    jobs.push_back(std::move(*job));
  }
  const nlohmann::json study = study_archive_json(view->study, view->runs);
  return archive_response(ctx, req, jobs, &study, "slipfront-study-" + id);
}

// The archive of `jobs` (and `study`, if given) streamed from an unnamed file of the data dir.
Response archive_response(ServerContext& ctx, const Request& req, const std::vector<Job>& jobs,
                          const nlohmann::json* study, const std::string& file_name) {
  ArchivePlan plan;
  try {
    plan = plan_run_archive(ctx.service, jobs, study);
  } catch (const ArchiveRefusal& e) {
    return problem_response(req, http::status::conflict, e.what());
  }
  // Its exact size is known: reserved before a byte is written, released when the file the
  // answer streams from is closed (sent, or its client cut after --send-timeout-s).
  std::optional<ByteReservation> reserved;
  if (auto refusal = refuse_archive_space(ctx, req, plan.size, reserved))
    return std::move(*refusal);
  // Written to a file of the data dir that has no name once opened: the answer streams from
  // it and the space is freed when it is sent (or the server stops).
  std::string name = (ctx.data_dir.empty() ? std::string(".") : ctx.data_dir) + "/export-XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0)
    throw StorageError(std::string("cannot create the archive: ") + std::strerror(errno), true);
  ::unlink(name.c_str());
  FileDescriptor file(fd);
  try {
    write_run_archive(fd, ctx.service, jobs, plan);
  } catch (const ArchiveRefusal& e) {
    return problem_response(req, http::status::conflict, e.what());
  }
  if (::lseek(fd, 0, SEEK_SET) != 0)
    throw StorageError(std::string("cannot read the archive: ") + std::strerror(errno), true);
  beast::error_code ec;
  RangeFile body;
  body.adopt(file.release(), ec);
  if (ec)
    return problem_response(req, http::status::internal_server_error,
                            "cannot read the archive: " + ec.message());
  body.hold(std::move(*reserved));
  http::response<RangeFileBody> res{http::status::ok, req.version()};
  res.set(http::field::server, "slipfront");
  res.set(http::field::content_type, "application/x-tar");
  res.set(http::field::content_disposition, "attachment; filename=\"" + file_name + ".tar\"");
  res.set(http::field::cache_control, "no-store");
  res.body().reset(std::move(body), ec);
  if (ec)
    return problem_response(req, http::status::internal_server_error,
                            "cannot read the archive: " + ec.message());
  res.prepare_payload();
  res.keep_alive(req.keep_alive());
  return res;
}

Response import_archive(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& req = rc.request;
  // ?again=true stores the runs already here too, under new ids (a copy of one's own).
  bool again = false;
  for (const auto& [name, value] : rc.query) {
    if (name == "again" && (value == "true" || value == "false"))
      again = value == "true";
    else
      return problem_response(
          req, http::status::bad_request, "invalid query parameters",
          {{"/query/" + api::cut_text(name, 64),
            name == "again" ? "must be true or false"
                            : "unknown parameter (POST /imports takes again)"}});
  }
  try {
    const ImportResult imported = import_run_archive(req.body(), ctx.service, rc.user, again);
    if (imported.kind == ImportResult::Kind::no_space)
      return unavailable_response(req, imported.reason + "; nothing was stored, retry later",
                                  ctx.retry_after_s);
    if (imported.kind == ImportResult::Kind::refused)
      throw ArchiveRefusal(imported.where, imported.reason);
    nlohmann::json runs = nlohmann::json::array();
    for (const auto& [id, original_id] : imported.ids)
      runs.push_back(
          {{"id", id}, {"original_id", original_id}, {"url", api_prefix + "/jobs/" + id}});
    // At most one warning per run (the metric names it left out), the first 20 listed.
    nlohmann::json warnings = nlohmann::json::array();
    for (std::size_t i = 0; i < imported.warnings.size() && i < 20; ++i)
      warnings.push_back(imported.warnings[i]);
    if (imported.warnings.size() > 20)
      warnings.push_back("and " + std::to_string(imported.warnings.size() - 20) + " more");
    // The runs already here, not stored again: each with the run here that it is.
    nlohmann::json skipped = nlohmann::json::array();
    for (const auto& run : imported.skipped)
      skipped.push_back({{"original_id", run.original_id},
                         {"id", run.id},
                         {"url", api_prefix + "/jobs/" + run.id},
                         {"reason", run.reason},
                         {"detail", run.detail}});
    nlohmann::json answer = {{"imported", runs},
                             {"count", imported.ids.size()},
                             {"skipped", skipped},
                             {"warnings", warnings}};
    // A study's archive: the study here, or the one of its id that was here already.
    const bool study_stored = imported.study && !imported.study->skipped;
    if (imported.study)
      answer["study"] = {{"id", imported.study->id},
                         {"original_id", imported.study->original_id},
                         {"url", api_prefix + "/studies/" + imported.study->id},
                         {"skipped", imported.study->skipped}};
    // 201 when something was stored; 200 when everything was already here (nothing created).
    return json_response(
        req, imported.ids.empty() && !study_stored ? http::status::ok : http::status::created,
        answer);
  } catch (const ArchiveRefusal& e) {
    // A member name comes from the client: a long one is cut, as other echoed values are.
    const std::string where = api::cut_text(e.where(), 300);
    return problem_response(req, http::status::unprocessable_entity,
                            "the archive is refused, nothing was stored: " +
                                (where.empty() ? "" : where + ": ") + e.what(),
                            {{where, e.what()}});
  }
}

} // namespace

void add_archive_routes(Router& router, ServerContext& ctx) {
  router.add(
      http::verb::get, api_prefix + "/exports",
      [&ctx](RequestContext& rc) { return export_archive(ctx, rc, false); }, Runs::export_pool);
  // The ids in a body: up to 1000 of them (a query string of 16 kB holds about 400).
  router.add_json_body(
      http::verb::post, api_prefix + "/exports",
      [&ctx](RequestContext& rc) { return export_archive(ctx, rc, true); }, Runs::export_pool);
  router.add(
      http::verb::get, api_prefix + "/studies/{id}/export",
      [&ctx](RequestContext& rc) { return export_study(ctx, rc); }, Runs::export_pool);
  router.add(http::verb::post, api_prefix + "/imports",
             [&ctx](RequestContext& rc) { return import_archive(ctx, rc); });
}

} // namespace slipfront::server
