// Maps method + path pattern ("/api/v1/jobs/{id}") to a handler. A path that matches
// with another method is 405 (with Allow); no match is 404.
#pragma once

#include "server/http_types.hpp"

#include <functional>
#include <string>
#include <vector>

namespace slipfront::server {

using Handler = std::function<Response(RequestContext&)>;

class Router {
public:
  void add(http::verb method, const std::string& pattern, Handler handler);
  // Runs the matching handler; errors it throws become a 500 problem (logged with context).
  Response dispatch(const Request& request) const;

  struct Route {
    http::verb method;
    std::string pattern;
    std::vector<std::string> segments;
    Handler handler;
  };
  const std::vector<Route>& routes() const { return routes_; }

private:
  std::vector<Route> routes_;
};

} // namespace slipfront::server
