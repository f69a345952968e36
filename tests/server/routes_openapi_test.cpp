// The router's API routes and the OpenAPI document's operations are the same set: a route
// added without its documentation, or a documented path nobody serves, fails here.
#include "server/http/handlers.hpp"
#include "server/server_app.hpp"

#include <gtest/gtest.h>

#include <boost/beast/http/verb.hpp>

#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <set>
#include <string>

namespace slipfront::server {
namespace {

std::string lower(std::string text) {
  for (char& c : text)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The API proper: /api/..., /healthz and /metrics (not the web page's static files).
bool is_api_path(const std::string& path) {
  return path.rfind("/api/", 0) == 0 || path == "/healthz" || path == "/metrics";
}

TEST(RoutesAndOpenApi, AreTheSameSetOfOperations) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("slipfront-routes-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ServerConfig config;
  config.port = 0;
  config.workers = 1;
  config.io_threads = 1;
  config.data_dir = dir.string();
  std::set<std::string> routed, documented;
  {
    ServerApp app(config);
    app.start();
    for (const auto& route : app.router().routes())
      if (is_api_path(route.pattern))
        routed.insert(lower(std::string(boost::beast::http::to_string(route.method))) + " " +
                      route.pattern);
    app.shutdown();
  }
  std::filesystem::remove_all(dir);

  const nlohmann::json doc = openapi_document();
  for (const auto& [path, operations] : doc["paths"].items())
    for (const auto& [method, operation] : operations.items())
      if (method != "head" && method != "parameters" && is_api_path(path))
        documented.insert(method + " " + path);

  for (const auto& op : routed)
    EXPECT_TRUE(documented.contains(op)) << op << " is served but not in the OpenAPI document";
  for (const auto& op : documented)
    EXPECT_TRUE(routed.contains(op)) << op << " is documented but no route serves it";
  EXPECT_GE(routed.size(), 15u);
}

} // namespace
} // namespace slipfront::server
