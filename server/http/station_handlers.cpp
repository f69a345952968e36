// GET /jobs/{id}/stations (the on-fault stations as JSON, every k-th step within a budget: the
// web view's station figures) and /jobs/{id}/stations.csv (every step, long format), both from
// /stations of a finished job's result file (docs/hdf5-layout.md "/stations").
#include "api/result_stations.hpp"
#include "api/station_csv.hpp"
#include "server/http/api_prefix.hpp"
#include "server/http/handlers.hpp"
#include "server/http/job_filter_query.hpp" // parse_long
#include "server/http/responses.hpp"
#include "server/http/result_lookup.hpp"

#include <sstream>

namespace slipfront::server {

namespace {

// The stations of the path's job, or the response to send instead: those of find_result, 410
// for a file that cannot be read as a result, 404 for a job whose spec lists no stations.
std::variant<StationRecords, Response> find_stations(ServerContext& ctx, RequestContext& rc,
                                                     std::string& job_id) {
  auto found = find_result(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const Job& job = std::get<ResultOnDisk>(found).job;
  const std::string& path = std::get<ResultOnDisk>(found).path;
  const auto& req = rc.request;
  job_id = job.id;
  std::string why;
  auto stations = api::read_stations(path, why);
  if (!stations) return result_unreadable(req, job, "stations", without_path(why, path, job));
  if (stations->empty())
    return problem_response(req, http::status::not_found,
                            "job " + job.id +
                                " has no stations (its spec lists none: \"stations\": "
                                "{\"x1\": [...]})");
  return std::move(*stations);
}

// GET /jobs/{id}/stations.csv: every recorded step at the job's stations (api/station_csv.hpp).
Response stations_csv(ServerContext& ctx, RequestContext& rc) {
  std::string id;
  auto found = find_stations(ctx, rc, id);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  std::ostringstream out;
  api::write_stations_csv(out, std::get<StationRecords>(found));
  auto res =
      text_response(rc.request, http::status::ok, std::move(out).str(), "text/csv; charset=utf-8");
  res.set(http::field::content_disposition, "attachment; filename=\"" + id + "-stations.csv\"");
  return res;
}

constexpr long default_station_samples = 10000;
constexpr long max_station_samples = 1000000;

// Rows 0, stride, 2 stride, ... of a row-major [steps, n] series, as [[...n values]...].
nlohmann::json strided_rows(const std::vector<double>& series, std::size_t n, std::size_t steps,
                            std::size_t stride) {
  auto rows = nlohmann::json::array();
  for (std::size_t r = 0; r < steps; r += stride) {
    auto row = nlohmann::json::array();
    for (std::size_t c = 0; c < n; ++c)
      row.push_back(number_or_null(series[r * n + c]));
    rows.push_back(std::move(row));
  }
  return rows;
}

// GET /jobs/{id}/stations?max_samples=N: the stations' positions, rupture times and threshold,
// and their four series at every k-th step from the first, k = ceil(steps / max_samples) (the
// file's values, not averaged; the CSV has every step).
Response stations_json(ServerContext& ctx, RequestContext& rc) {
  const auto& req = rc.request;
  long max_samples = default_station_samples;
  std::vector<api::FieldError> errors;
  for (const auto& [key, value] : rc.query) {
    if (key != "max_samples") {
      errors.push_back({"/query/" + key, "unknown query parameter (known: max_samples)"});
      continue;
    }
    const auto n = parse_long(value);
    if (!n || *n < 1 || *n > max_station_samples)
      errors.push_back({"/query/max_samples", "must be an integer in [1, " +
                                                  std::to_string(max_station_samples) + "], got '" +
                                                  value.substr(0, 40) + "'"});
    else
      max_samples = *n;
  }
  if (!errors.empty())
    return problem_response(req, http::status::bad_request, "invalid query parameters", errors);
  std::string id;
  auto found = find_stations(ctx, rc, id);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  const StationRecords& s = std::get<StationRecords>(found);
  const std::size_t n = s.x1.size();
  const std::size_t steps = s.time.size();
  const auto budget = static_cast<std::size_t>(max_samples);
  const std::size_t stride = steps > budget ? (steps + budget - 1) / budget : 1;
  auto time = nlohmann::json::array();
  for (std::size_t r = 0; r < steps; r += stride)
    time.push_back(s.time[r]);
  auto rupture_time = nlohmann::json::array();
  for (double t : s.rupture_time)
    rupture_time.push_back(number_or_null(t));
  nlohmann::json body;
  body["id"] = id;
  body["units"] = {{"x1", "m"},
                   {"time", "s"},
                   {"rupture_time", "s"},
                   {"slip_rate", "m/s"},
                   {"slip", "m"},
                   {"shear_traction", "Pa"},
                   {"normal_traction", "Pa"},
                   {"rupture_threshold", "m/s"}};
  body["x1"] = s.x1;
  body["rupture_threshold"] = s.rupture_threshold;
  body["rupture_time"] = std::move(rupture_time);
  body["steps"] = steps;
  body["stride"] = stride;
  body["time"] = std::move(time);
  body["slip_rate"] = strided_rows(s.slip_rate, n, steps, stride);
  body["slip"] = strided_rows(s.slip, n, steps, stride);
  body["shear_traction"] = strided_rows(s.shear_traction, n, steps, stride);
  body["normal_traction"] = strided_rows(s.normal_traction, n, steps, stride);
  return json_response(req, http::status::ok, std::move(body));
}

} // namespace

void add_station_routes(Router& router, ServerContext& ctx) {
  // On the blocking pool: the file is opened and may be hashed (ResultFiles).
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/stations",
      [&ctx](RequestContext& rc) { return stations_json(ctx, rc); }, Runs::read_pool);
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/stations.csv",
      [&ctx](RequestContext& rc) { return stations_csv(ctx, rc); }, Runs::read_pool);
}

} // namespace slipfront::server
