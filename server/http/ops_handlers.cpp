// GET /healthz, GET /metrics (Prometheus text), GET /api/v1/openapi.json,
// GET /api/v1/schema/job.json (the job schema, api/job_schema.hpp).
#include "server/http/handlers.hpp"

#include "api/job_schema.hpp"
#include "server/core/disk_space.hpp"
#include "server/http/responses.hpp"

#include <sstream>

namespace slipfront::server {

namespace {

// A storage error this recent still makes /healthz degraded.
constexpr double storage_error_window_s = 60.0;

// Free space of the data dir's file system, the last storage error; degraded when the free
// space is below the threshold or the storage refused a write in the last minute.
nlohmann::json storage_health(ServerContext& ctx, bool& degraded) {
  nlohmann::json out;
  if (const auto free_bytes = free_disk_bytes(ctx.data_dir)) {
    out["free_bytes"] = static_cast<double>(*free_bytes);
    if (static_cast<double>(*free_bytes) < ctx.min_free_bytes) degraded = true;
  } else {
    out["free_bytes"] = nullptr;
  }
  out["min_free_bytes"] = ctx.min_free_bytes;
  out["last_error"] = nullptr;
  out["last_error_at"] = nullptr;
  if (auto e = ctx.stats.last_storage_error()) {
    out["last_error"] = e->message;
    out["last_error_at"] = e->at;
    if (e->age_s < storage_error_window_s) degraded = true;
  }
  return out;
}

Response healthz(ServerContext& ctx, RequestContext& rc) {
  const ServiceLoad load = ctx.service.load();
  nlohmann::json body = {{"status", ctx.draining ? "draining" : "ok"},
                         {"code_version", ctx.service.options().code_version},
                         {"executor", ctx.executor},
                         {"workers", ctx.workers},
                         {"running", load.running},
                         {"queue_depth", load.queued},
                         {"queue_limit", load.queue_limit},
                         {"auth", ctx.tokens.has_value()}};
  try {
    ctx.service.check_database();
    body["database"] = "ok";
  } catch (const std::exception& e) {
    body["status"] = "error";
    body["database"] = e.what();
  }
  bool degraded = false;
  body["storage"] = storage_health(ctx, degraded);
  if (degraded && body["status"] == "ok") body["status"] = "degraded";
  bool ok = body["status"] == "ok";
  return json_response(rc.request, ok ? http::status::ok : http::status::service_unavailable, body);
}

Response prometheus(ServerContext& ctx, RequestContext& rc) {
  const ServiceLoad load = ctx.service.load();
  std::ostringstream out;
  out << "# HELP slipfront_queue_depth Jobs waiting in the run queue.\n"
      << "# TYPE slipfront_queue_depth gauge\n"
      << "slipfront_queue_depth " << load.queued << "\n"
      << "# HELP slipfront_queue_limit Queue size above which submissions get 503.\n"
      << "# TYPE slipfront_queue_limit gauge\n"
      << "slipfront_queue_limit " << load.queue_limit << "\n"
      << "# HELP slipfront_jobs_running Jobs running now.\n"
      << "# TYPE slipfront_jobs_running gauge\n"
      << "slipfront_jobs_running " << load.running << "\n"
      << "# HELP slipfront_workers Worker threads.\n"
      << "# TYPE slipfront_workers gauge\n"
      << "slipfront_workers " << ctx.workers << "\n"
      << "# HELP slipfront_jobs Jobs in the database, by status.\n"
      << "# TYPE slipfront_jobs gauge\n";
  for (const auto& [status, n] : ctx.service.count_by_status())
    out << "slipfront_jobs{status=\"" << status << "\"} " << n << "\n";
  out << ctx.stats.prometheus_text();
  return text_response(rc.request, http::status::ok, out.str(),
                       "text/plain; version=0.0.4; charset=utf-8");
}

} // namespace

void add_ops_routes(Router& router, ServerContext& ctx) {
  router.add(http::verb::get, "/healthz", [&ctx](RequestContext& rc) { return healthz(ctx, rc); });
  router.add(http::verb::get, "/metrics",
             [&ctx](RequestContext& rc) { return prometheus(ctx, rc); });
  router.add(http::verb::get, "/api/v1/openapi.json", [](RequestContext& rc) {
    static const nlohmann::json doc = openapi_document();
    return Response(json_response(rc.request, http::status::ok, doc));
  });
  router.add(http::verb::get, "/api/v1/schema/job.json", [](RequestContext& rc) {
    static const nlohmann::json schema = api::job_json_schema();
    return Response(json_response(rc.request, http::status::ok, schema));
  });
}

} // namespace slipfront::server
