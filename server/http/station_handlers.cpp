// GET /jobs/{id}/stations.csv: the on-fault stations of a finished job's result file
// (docs/hdf5-layout.md "/stations").
#include "api/result_stations.hpp"
#include "api/station_csv.hpp"
#include "server/core/log.hpp"
#include "server/http/api_prefix.hpp"
#include "server/http/handlers.hpp"
#include "server/http/responses.hpp"
#include "server/http/result_lookup.hpp"

#include <sstream>

namespace slipfront::server {

namespace {

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

void add_station_routes(Router& router, ServerContext& ctx) {
  // On the blocking pool: the file is opened and may be hashed (ResultFiles).
  router.add(
      http::verb::get, api_prefix + "/jobs/{id}/stations.csv",
      [&ctx](RequestContext& rc) { return stations_csv(ctx, rc); }, true);
}

} // namespace slipfront::server
