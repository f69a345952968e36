// The web view's files (docs/web.md), read once from a directory at start-up and served at
// `/` from memory: only the files found then can be served (no path ever reaches the file
// system), each with a strict Content-Security-Policy.
#pragma once

#include "server/http/router.hpp"

#include <map>
#include <memory>
#include <string>

namespace slipfront::server {

class StaticFiles {
public:
  // Reads every regular file under `dir` (at most 64 MiB in all). An empty or missing
  // directory gives an empty set (the routes then answer 404 naming --web-dir).
  static std::shared_ptr<StaticFiles> load(const std::string& dir);
  // The web directory beside the executable: <exe dir>/share/slipfront/web (build tree),
  // then <exe dir>/../share/slipfront/web (install); "" when neither exists.
  static std::string default_dir();

  std::size_t size() const { return files_.size(); }
  const std::string& dir() const { return dir_; }
  Response serve(const Request& req, const std::string& relative_path) const;

private:
  struct File {
    std::string content, content_type, etag;
  };
  std::string dir_;
  std::map<std::string, File> files_; // relative path ("index.html", "vendor/x/y.js")
};

// GET / (index.html), /app/..., /vendor/... and /api-docs (the OpenAPI document rendered).
void add_static_routes(Router& router, std::shared_ptr<const StaticFiles> files);

// The Content-Security-Policy of every page.
extern const char* const content_security_policy;

} // namespace slipfront::server
