#include "server/http/byte_range.hpp"

#include <charconv>

namespace slipfront::server {

namespace {
std::optional<std::uint64_t> number(std::string_view s) {
  if (s.empty()) return std::nullopt;
  std::uint64_t v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}
} // namespace

RangeRequest parse_range(std::string_view header, std::uint64_t size) {
  RangeRequest whole;
  constexpr std::string_view unit = "bytes=";
  if (header.substr(0, unit.size()) != unit) return whole;
  auto spec = header.substr(unit.size());
  if (spec.find(',') != std::string_view::npos) return whole;
  auto dash = spec.find('-');
  if (dash == std::string_view::npos) return whole;
  auto a = spec.substr(0, dash), b = spec.substr(dash + 1);
  RangeRequest r;
  r.kind = RangeRequest::Kind::partial;
  if (a.empty()) { // suffix: the last n bytes
    auto n = number(b);
    if (!n) return whole;
    if (*n == 0 || size == 0) return {RangeRequest::Kind::unsatisfiable, {}};
    std::uint64_t len = *n < size ? *n : size;
    r.range = {size - len, len};
    return r;
  }
  auto first = number(a);
  if (!first) return whole;
  std::uint64_t last = size == 0 ? 0 : size - 1;
  if (!b.empty()) {
    auto l = number(b);
    if (!l || *l < *first) return whole;
    if (*l < last) last = *l;
  }
  if (*first >= size) return {RangeRequest::Kind::unsatisfiable, {}};
  r.range = {*first, last - *first + 1};
  return r;
}

} // namespace slipfront::server
