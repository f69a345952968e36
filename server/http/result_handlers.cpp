// GET /jobs/{id}/result.h5 (ETag, Range, If-None-Match), /jobs/{id}/result.xdmf (its XDMF
// sidecar), /jobs/{id}/metrics, /jobs/{id}/front, /jobs/{id}/fields/{name} (a window of an
// /interface field as JSON). The stations: station_handlers.cpp.
#include "api/result_reader.hpp"
#include "api/result_xdmf.hpp"
#include "server/http/byte_range.hpp"
#include "server/http/handlers.hpp"
#include "server/http/range_file.hpp"
#include "server/http/responses.hpp"
#include "server/http/result_lookup.hpp"

#include <boost/beast/http/basic_file_body.hpp>

#include <charconv>
#include <cmath>

namespace slipfront::server {

namespace {

using RangeFileBody = http::basic_file_body<RangeFile>;

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
    return result_unreadable(req, job, "XDMF", without_path(e.what(), path, job));
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
  return json_response(rc.request, http::status::ok, std::move(body));
}

std::optional<double> finite_number(const std::string& s) {
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
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
  if (!slice) return result_unreadable(req, job, "field " + name, without_path(why, path, job));
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
  return json_response(req, http::status::ok, std::move(body));
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
}

} // namespace slipfront::server
