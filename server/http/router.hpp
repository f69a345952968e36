// Maps method + path pattern ("/api/v1/jobs/{id}") to a handler. A path that matches
// with another method is 405, with Allow listing every method of the path (HEAD wherever GET
// is); no match is 404. A route that reads a JSON body answers 415 to another Content-Type.
#pragma once

#include "server/http/api_prefix.hpp"
#include "server/http/http_types.hpp"

#include <functional>
#include <string>
#include <vector>

namespace slipfront::server {

using Handler = std::function<Response(RequestContext&)>;

// Where a route's handler runs (docs/server.md, "Threads"): quick handlers on the I/O
// thread that read the request; handlers that may block on separate pools, so that neither
// health checks and status reads nor submissions wait behind a long read.
enum class Runs {
  io_thread,   // quick: status, health, one-row reads, static files
  read_pool,   // GETs that may block: listings over many rows, HDF5 reads, analyses
  write_pool,  // every route of another method than GET: it writes to the database
  export_pool, // run-table exports (GET /jobs?format=csv|ndjson): a bounded number at once
  fit_pool,    // length fits (POST /length-fits): pure computation, a bounded number at once
};
// For a route whose place depends on the query (a listing or an export).
using RunsFor = std::function<Runs(const std::map<std::string, std::string>& query)>;

class Router {
public:
  // `runs` applies to GET (and HEAD) routes; a route of another method runs on the write
  // pool unless it names a bounded pool (export_pool, fit_pool).
  void add(http::verb method, const std::string& pattern, Handler handler,
           Runs runs = Runs::io_thread);
  void add(http::verb method, const std::string& pattern, Handler handler, RunsFor runs_for);
  // Where the handler of `request` runs (io_thread if no route matches: a quick 404/405).
  Runs runs(const Request& request) const;
  // A route whose handler reads the body as JSON: a request whose Content-Type is another
  // media type than application/json is answered 415 (naming the type to send) before the
  // handler runs. A body without Content-Type is read as JSON. It runs where `add` puts it.
  void add_json_body(http::verb method, const std::string& pattern, Handler handler,
                     Runs runs = Runs::io_thread);
  // Runs the matching handler; errors it throws become a 500 problem (logged with context),
  // except storage that cannot take writes now (disk full...): 503 with Retry-After.
  Response dispatch(const Request& request) const;
  // What a storage failure answers: Retry-After, and a callback told of each (for /healthz).
  void on_storage_unavailable(int retry_after_s, std::function<void(const std::string&)> record);

  struct Route {
    http::verb method;
    std::string pattern;
    std::vector<std::string> segments;
    Handler handler;
    RunsFor runs_for;
    bool json_body = false; // add_json_body
  };
  const std::vector<Route>& routes() const { return routes_; }

private:
  Response answer(const Request& request) const;

  std::vector<Route> routes_;
  int retry_after_s_ = 30;
  std::function<void(const std::string&)> record_storage_error_;
};

} // namespace slipfront::server
