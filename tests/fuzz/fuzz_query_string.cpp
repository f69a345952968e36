// libFuzzer target: a request target (path and query) through parse_target
// (server/http/query_string.hpp) and the GET /api/v1/jobs parameter parser
// (server/http/job_filter_query.hpp). Also checks that percent_encode/percent_decode round-trip
// every decoded value (the listing builds its `next` URL with them).
#include "server/http/job_filter_query.hpp"
#include "server/http/query_string.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace {

void require(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "%s\n", what);
    std::abort();
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace slipfront::server;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto target = parse_target(text);
  if (!target) return 0;
  require(!target->path.empty() && target->path.front() == '/', "path without its '/'");
  for (const auto& [key, value] : target->query) {
    require(percent_decode(percent_encode(key), true) == key, "key does not round-trip");
    require(percent_decode(percent_encode(value), true) == value, "value does not round-trip");
  }
  const auto listing = parse_job_filter(target->query);
  if (listing.errors.empty()) {
    const auto& f = listing.filter;
    require(f.limit >= 1 && f.limit <= 1000, "limit out of [1, 1000]");
    require(!f.before_seq || *f.before_seq >= 0, "negative cursor");
    for (const auto& bound : {f.L_min, f.L_max, f.n_d_min, f.n_d_max})
      require(!bound || std::isfinite(*bound), "non-finite filter accepted");
  }
  return 0;
}
