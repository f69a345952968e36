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

class Router {
public:
  // offload: a handler that may block (listings over many rows, HDF5 reads) runs on the
  // blocking-work pool, not on an I/O thread, so that health checks and status reads stay
  // quick (docs/server.md, "Threads"). Every route of another method than GET is offloaded
  // whatever the flag: it writes to the database.
  void add(http::verb method, const std::string& pattern, Handler handler, bool offload = false);
  // A route whose handler reads the body as JSON: a request whose Content-Type is another
  // media type than application/json is answered 415 (naming the type to send) before the
  // handler runs. A body without Content-Type is read as JSON.
  void add_json_body(http::verb method, const std::string& pattern, Handler handler);
  bool offloaded(const Request& request) const;
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
    bool offload = false;
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
