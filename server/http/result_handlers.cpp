// GET /jobs/{id}/result.h5 (ETag, Range, If-None-Match), /jobs/{id}/result.xdmf (its XDMF
// sidecar), /jobs/{id}/metrics, /jobs/{id}/front, /jobs/{id}/fields/{name} (a window of an
// /interface field as JSON), /jobs/{id}/stations.csv (the stations' records as CSV).
#include "api/result_reader.hpp"
#include "api/result_stations.hpp"
#include "api/result_xdmf.hpp"
#include "api/station_csv.hpp"
#include "server/core/job_id.hpp"
#include "server/core/log.hpp"
#include "server/http/byte_range.hpp"
#include "server/http/handlers.hpp"
#include "server/http/range_file.hpp"
#include "server/http/responses.hpp"

#include <boost/beast/http/basic_file_body.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace slipfront::server {

namespace {

using RangeFileBody = http::basic_file_body<RangeFile>;

// The job of the path, or the response to send instead (404 for malformed or unknown ids:
// a malformed id never reaches the store or the file system).
std::variant<Job, Response> find_job(ServerContext& ctx, RequestContext& rc) {
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return Response(problem_response(rc.request, http::status::not_found, "no job with id " + id));
  auto job = ctx.service.get(id);
  if (!job)
    return Response(problem_response(rc.request, http::status::not_found, "no job with id " + id));
  return *job;
}

Response not_finished(const Request& req, const Job& job, const std::string& what) {
  return problem_response(req, http::status::conflict,
                          "job " + job.id + " is " + to_string(job.status) + "; no " + what +
                              " yet");
}

// The answer for a result file that cannot be served as the database describes it. Its words
// never hold the server's paths (the log has the full story).
Response result_gone(const Request& req, const Job& job, const OpenedResult& file) {
  using State = OpenedResult::State;
  std::string why;
  switch (file.state) {
  case State::missing:
    why = "is no longer on the server (deleted from its data dir)";
    break;
  case State::not_regular:
    why = "is not a regular file on the server";
    break;
  case State::damaged:
    why = "is " + file.reason;
    break;
  case State::unreadable:
    why = "cannot be read on the server (" + file.reason + ")";
    break;
  case State::intact:
    throw std::logic_error("result_gone for an intact file");
  }
  log_error("job " + job.id + ": result file " + job.result.path + " " + why + "; answered 410");
  return problem_response(req, http::status::gone,
                          "the result file of job " + job.id + " " + why +
                              "; submit the job again with fresh=true to recompute it");
}

// A finished job's result file, open and verified (ResultFiles).
struct ResultOnDisk {
  Job job;
  OpenedResult file;
  std::string path; // absolute, for HDF5: the stored path is relative to the data dir
};

// The result file of the path's job, or the response to send instead: 404 (unknown job, or
// a job that ended without a result file), 409 (not finished yet), 410 (file deleted,
// damaged or not a regular file). Verifying may hash the file: only on the blocking pool.
std::variant<ResultOnDisk, Response> find_result(ServerContext& ctx, RequestContext& rc) {
  auto found = find_job(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  Job& job = std::get<Job>(found);
  const auto& req = rc.request;
  if (!is_final(job.status)) return not_finished(req, job, "result file");
  if (job.status != JobStatus::succeeded || job.result.path.empty())
    return problem_response(req, http::status::not_found,
                            "job " + job.id + " has no result file (" + to_string(job.status) +
                                (job.error.empty() ? "" : ": " + job.error) + ")");
  auto& files = ctx.service.result_files();
  auto file = files.open(job.result);
  if (file.state != OpenedResult::State::intact) return result_gone(req, job, file);
  std::string path = files.absolute_path(job.result);
  return ResultOnDisk{std::move(job), std::move(file), std::move(path)};
}

// `text` (an error from the HDF5 reader) without the server's path of the file.
std::string without_path(std::string text, const std::string& path, const Job& job) {
  const std::string name = job.id + ".h5";
  for (auto at = text.find(path); at != std::string::npos; at = text.find(path, at + name.size()))
    text.replace(at, path.size(), name);
  return text;
}

Response download(ServerContext& ctx, RequestContext& rc) {
  auto found = find_result(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const Job& job = std::get<ResultOnDisk>(found).job;
  const auto& req = rc.request;
  const std::string etag = "\"" + job.result.sha256 + "\"";
  if (req.count(http::field::if_none_match) &&
      etag_list_matches(req[http::field::if_none_match], etag)) {
    http::response<http::empty_body> res{http::status::not_modified, req.version()};
    res.set(http::field::server, "slipfront");
    res.set(http::field::etag, etag);
    res.keep_alive(req.keep_alive());
    return res;
  }
  beast::error_code ec;
  RangeFile file;
  file.adopt(std::get<ResultOnDisk>(found).file.fd.release(), ec);
  if (ec)
    return problem_response(req, http::status::internal_server_error,
                            "result file of job " + job.id + ": " + ec.message());
  const std::uint64_t size = file.size(ec);
  RangeRequest range;
  if (req.count(http::field::range)) {
    bool if_range_ok = !req.count(http::field::if_range) || req[http::field::if_range] == etag;
    if (if_range_ok) range = parse_range(req[http::field::range], size);
  }
  if (range.kind == RangeRequest::Kind::unsatisfiable) {
    auto res = problem_response(req, http::status::range_not_satisfiable,
                                "range " + std::string(req[http::field::range]) +
                                    " is outside the file (" + std::to_string(size) + " bytes)");
    res.set(http::field::content_range, "bytes */" + std::to_string(size));
    return res;
  }
  auto status = http::status::ok;
  if (range.kind == RangeRequest::Kind::partial) {
    status = http::status::partial_content;
    file.set_range(range.range.first, range.range.length, ec);
    if (ec)
      return problem_response(req, http::status::internal_server_error,
                              "seeking in the result file of job " + job.id + ": " + ec.message());
  }
  http::response<RangeFileBody> res{status, req.version()};
  res.set(http::field::server, "slipfront");
  res.set(http::field::content_type, "application/x-hdf5");
  res.set(http::field::content_disposition, "attachment; filename=\"" + job.id + ".h5\"");
  res.set(http::field::etag, etag);
  res.set(http::field::accept_ranges, "bytes");
  res.set(http::field::cache_control, "private, max-age=31536000, immutable");
  if (status == http::status::partial_content)
    res.set(http::field::content_range,
            "bytes " + std::to_string(range.range.first) + "-" +
                std::to_string(range.range.first + range.range.length - 1) + "/" +
                std::to_string(size));
  res.body().reset(std::move(file), ec);
  if (ec)
    return problem_response(req, http::status::internal_server_error,
                            "result file of job " + job.id + ": " + ec.message());
  res.keep_alive(req.keep_alive());
  res.prepare_payload();
  return res;
}

// The XDMF sidecar of the result file, generated from it; it names the file "ID.h5" (the
// download's file name), so both belong in one directory.
Response xdmf(ServerContext& ctx, RequestContext& rc) {
  auto found = find_result(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const Job& job = std::get<ResultOnDisk>(found).job;
  const std::string& path = std::get<ResultOnDisk>(found).path;
  const auto& req = rc.request;
  std::string text;
  try {
    text = api::result_xdmf(path, job.id + ".h5");
  } catch (const std::exception& e) {
    log_error("XDMF of job " + job.id + ": " + e.what());
    return problem_response(req, http::status::internal_server_error,
                            "XDMF of job " + job.id + ": " + without_path(e.what(), path, job));
  }
  auto res = text_response(req, http::status::ok, std::move(text), "application/xml");
  res.set(http::field::content_disposition, "attachment; filename=\"" + job.id + ".xdmf\"");
  return res;
}

Response metrics(ServerContext& ctx, RequestContext& rc) {
  auto found = find_job(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const Job& job = std::get<Job>(found);
  if (!is_final(job.status)) return not_finished(rc.request, job, "metrics");
  if (job.metrics.is_null())
    return problem_response(rc.request, http::status::not_found,
                            "job " + job.id + " has no metrics (" + to_string(job.status) + ")");
  return json_response(rc.request, http::status::ok,
                       {{"id", job.id},
                        {"status", to_string(job.status)},
                        {"spec_sha256", job.spec_sha256},
                        {"code_version", job.code_version},
                        {"metrics", job.metrics}});
}

Response front(ServerContext& ctx, RequestContext& rc) {
  auto found = find_job(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const Job& job = std::get<Job>(found);
  if (!is_final(job.status)) return not_finished(rc.request, job, "front");
  auto stored = ctx.service.front(job.id);
  if (!stored || stored->is_null())
    return problem_response(rc.request, http::status::not_found,
                            "job " + job.id + " has no front (" + to_string(job.status) + ")");
  nlohmann::json body = *stored;
  if (body.is_object()) {
    body["id"] = job.id;
    body["units"] = {{"x1", "m"}, {"arrival_time", "s"}, {"rupture_speed", "m/s"}};
  }
  return json_response(rc.request, http::status::ok, body);
}

std::optional<double> finite_number(const std::string& s) {
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

constexpr long max_slice_points = 4000000;

// GET /jobs/{id}/fields/{name}?x1_min&x1_max&t_min&t_max&max_points
Response field(ServerContext& ctx, RequestContext& rc) {
  const auto& req = rc.request;
  const auto& name = rc.path_params.at("name");
  std::vector<api::FieldError> errors;
  api::SliceWindow window;
  for (const auto& [key, value] : rc.query) {
    if (key == "x1_min" || key == "x1_max" || key == "t_min" || key == "t_max") {
      auto v = finite_number(value);
      if (!v) {
        errors.push_back(
            {"/query/" + key, "must be a finite number, got '" + value.substr(0, 40) + "'"});
        continue;
      }
      (key == "x1_min"   ? window.x1_min
       : key == "x1_max" ? window.x1_max
       : key == "t_min"  ? window.t_min
                         : window.t_max) = *v;
    } else if (key == "max_points") {
      long n = 0;
      auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
      if (value.empty() || ec != std::errc() || end != value.data() + value.size() || n < 1 ||
          n > max_slice_points)
        errors.push_back({"/query/max_points",
                          "must be an integer in [1, " + std::to_string(max_slice_points) + "]"});
      else
        window.max_points = n;
    } else {
      errors.push_back({"/query/" + key, "unknown query parameter (known: x1_min, x1_max, "
                                         "t_min, t_max, max_points)"});
    }
  }
  if (window.x1_min && window.x1_max && *window.x1_min > *window.x1_max)
    errors.push_back({"/query/x1_max", "must be >= x1_min"});
  if (window.t_min && window.t_max && *window.t_min > *window.t_max)
    errors.push_back({"/query/t_max", "must be >= t_min"});
  if (!errors.empty())
    return problem_response(req, http::status::bad_request, "invalid query parameters", errors);
  if (api::slice_field_units(name).empty()) {
    std::string known;
    for (const auto& n : api::slice_field_names())
      known += (known.empty() ? "" : ", ") + n;
    return problem_response(req, http::status::not_found,
                            "no field '" + name.substr(0, 40) + "'; the fields are " + known);
  }
  auto found = find_result(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const Job& job = std::get<ResultOnDisk>(found).job;
  const std::string& path = std::get<ResultOnDisk>(found).path;
  std::string why;
  auto slice = api::read_field_slice(path, name, window, why);
  if (!slice) {
    log_error("field " + name + " of job " + job.id + ": " + why);
    return problem_response(req, http::status::internal_server_error,
                            "the result file of job " + job.id +
                                " cannot be read: " + without_path(why, path, job));
  }
  nlohmann::json body;
  body["id"] = job.id;
  body["field"] = name;
  body["units"] = {{"values", slice->units}, {"x1", "m"}, {"time", "s"}};
  body["shape"] = {slice->time.size(), slice->x1.size()};
  body["source_shape"] = {slice->source_rows, slice->source_columns};
  body["stride"] = {{"time", slice->row_stride}, {"x1", slice->column_stride}};
  body["first_index"] = {{"time", slice->row_first}, {"x1", slice->column_first}};
  body["x1"] = slice->x1;
  body["time"] = slice->time;
  auto rows = nlohmann::json::array();
  const std::size_t nc = slice->x1.size();
  double vmin = INFINITY, vmax = -INFINITY;
  for (std::size_t r = 0; r < slice->time.size(); ++r) {
    auto row = nlohmann::json::array();
    for (std::size_t c = 0; c < nc; ++c) {
      double v = slice->values[r * nc + c];
      if (std::isfinite(v)) {
        vmin = std::min(vmin, v);
        vmax = std::max(vmax, v);
      }
      row.push_back(number_or_null(v));
    }
    rows.push_back(std::move(row));
  }
  body["values"] = std::move(rows);
  body["min"] = number_or_null(vmin);
  body["max"] = number_or_null(vmax);
  return json_response(req, http::status::ok, body);
}

// GET /jobs/{id}/stations.csv: every recorded step at the job's stations (api/station_csv.hpp);
// 404 for a job whose spec lists no stations.
Response stations_csv(ServerContext& ctx, RequestContext& rc) {
  auto found = find_result(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const Job& job = std::get<ResultOnDisk>(found).job;
  const std::string& path = std::get<ResultOnDisk>(found).path;
  const auto& req = rc.request;
  std::string why;
  const auto stations = api::read_stations(path, why);
  if (!stations) {
    log_error("stations of job " + job.id + ": " + why);
    return problem_response(req, http::status::internal_server_error,
                            "the result file of job " + job.id +
                                " cannot be read: " + without_path(why, path, job));
  }
  if (stations->empty())
    return problem_response(req, http::status::not_found,
                            "job " + job.id +
                                " has no stations (its spec lists none: \"stations\": "
                                "{\"x1\": [...]})");
  std::ostringstream out;
  api::write_stations_csv(out, *stations);
  auto res = text_response(req, http::status::ok, std::move(out).str(), "text/csv; charset=utf-8");
  res.set(http::field::content_disposition, "attachment; filename=\"" + job.id + "-stations.csv\"");
  return res;
}

} // namespace

void add_result_routes(Router& router, ServerContext& ctx) {
  // On the blocking pool: the file is opened and may be hashed (ResultFiles).
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/result.h5",
      [&ctx](RequestContext& rc) { return download(ctx, rc); }, Runs::read_pool);
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/result.xdmf",
      [&ctx](RequestContext& rc) { return xdmf(ctx, rc); }, Runs::read_pool);
  router.add(http::verb::get, api_prefix + "/jobs/{id}/metrics",
             [&ctx](RequestContext& rc) { return metrics(ctx, rc); });
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/front",
      [&ctx](RequestContext& rc) { return front(ctx, rc); }, Runs::read_pool);
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/fields/{name}",
      [&ctx](RequestContext& rc) { return field(ctx, rc); }, Runs::read_pool);
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/stations.csv",
      [&ctx](RequestContext& rc) { return stations_csv(ctx, rc); }, Runs::read_pool);
}

} // namespace slipfront::server
