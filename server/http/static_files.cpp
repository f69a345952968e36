#include "server/http/static_files.hpp"

#include "server/http/responses.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace slipfront::server {

namespace fs = std::filesystem;

const char* const content_security_policy =
    "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:; "
    "connect-src 'self'; font-src 'self'; object-src 'none'; base-uri 'none'; "
    "form-action 'self'; frame-ancestors 'none'";

namespace {

std::string content_type_of(const fs::path& p) {
  const auto ext = p.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".ico") return "image/x-icon";
  if (ext == ".map") return "application/json";
  if (ext == ".txt" || ext == ".md") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

std::string strong_etag(const std::string& body) {
  return "\"" + fnv1a_hex(body) + "\"";
}

} // namespace

std::string StaticFiles::default_dir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const fs::path base = exe.parent_path();
  for (const auto& candidate :
       {base / "share" / "slipfront" / "web", base / ".." / "share" / "slipfront" / "web"})
    if (fs::is_regular_file(candidate / "index.html", ec)) return fs::canonical(candidate, ec);
  return "";
}

std::shared_ptr<StaticFiles> StaticFiles::load(const std::string& dir) {
  auto out = std::make_shared<StaticFiles>();
  out->dir_ = dir;
  if (dir.empty()) return out;
  std::error_code ec;
  std::uint64_t total = 0;
  constexpr std::uint64_t max_total = 64ULL << 20;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const auto rel = fs::relative(it->path(), dir, ec).generic_string();
    if (ec || rel.empty() || rel.front() == '.' || rel.find("/.") != std::string::npos) continue;
    std::ifstream in(it->path(), std::ios::binary);
    std::ostringstream buf;
    buf << in.rdbuf();
    File f{buf.str(), content_type_of(it->path()), ""};
    total += f.content.size();
    if (total > max_total)
      throw std::runtime_error("web dir " + dir + " holds more than 64 MiB of files");
    f.etag = strong_etag(f.content);
    out->files_.emplace(rel, std::move(f));
  }
  return out;
}

Response StaticFiles::serve(const Request& req, const std::string& relative_path) const {
  auto it = files_.find(relative_path);
  if (it == files_.end()) {
    if (files_.empty())
      return problem_response(req, http::status::not_found,
                              "the web view's files were not found beside the executable "
                              "(web/ or ../share/slipfront/web/); start with --web-dir DIR");
    return problem_response(req, http::status::not_found, "no such file: /" + relative_path);
  }
  const File& f = it->second;
  http::response<http::string_body> res{http::status::ok, req.version()};
  res.set(http::field::server, "slipfront");
  res.set(http::field::content_type, f.content_type);
  res.set(http::field::etag, f.etag);
  res.set(http::field::cache_control, "no-cache"); // revalidate: a new build serves new files
  res.set("Content-Security-Policy", content_security_policy);
  res.set("X-Content-Type-Options", "nosniff");
  res.set("Referrer-Policy", "no-referrer");
  res.set("X-Frame-Options", "DENY");
  res.keep_alive(req.keep_alive());
  if (req.count(http::field::if_none_match) && req[http::field::if_none_match] == f.etag) {
    res.result(http::status::not_modified);
  } else {
    res.body() = f.content;
  }
  res.prepare_payload();
  return res;
}

void add_static_routes(Router& router, std::shared_ptr<const StaticFiles> files) {
  auto serve = [files](const std::string& rel) {
    return [files, rel](RequestContext& rc) { return files->serve(rc.request, rel); };
  };
  router.add(http::verb::get, "/", serve("index.html"));
  router.add(http::verb::get, "/index.html", serve("index.html"));
  router.add(http::verb::get, "/api-docs", serve("api-docs.html"));
  // One to three segments below /app and /vendor: the router matches whole segments.
  static const std::string segment[] = {"p1", "p2", "p3"};
  for (const std::string top : {"app", "vendor"}) {
    std::string pattern = "/" + top;
    for (int depth = 1; depth <= 3; ++depth) {
      pattern.append("/{").append(segment[depth - 1]).append("}");
      router.add(http::verb::get, pattern, [files, top, depth](RequestContext& rc) {
        std::string rel = top;
        for (int i = 0; i < depth; ++i) {
          rel.push_back('/');
          rel.append(rc.path_params.at(segment[i]));
        }
        return files->serve(rc.request, rel);
      });
    }
  }
}

} // namespace slipfront::server
