#include "server/http/query_string.hpp"

#include <cctype>

namespace slipfront::server {

namespace {
int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
} // namespace

std::optional<std::string> percent_decode(std::string_view text, bool plus_is_space) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '%') {
      if (i + 2 >= text.size()) return std::nullopt;
      int hi = hex_value(text[i + 1]), lo = hex_value(text[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      out.push_back(static_cast<char>(hi * 16 + lo));
      i += 2;
    } else if (c == '+' && plus_is_space) {
      out.push_back(' ');
    } else {
      out.push_back(c);
    }
  }
  return out;
}

std::string percent_encode(std::string_view text) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == ',') {
      out.push_back(static_cast<char>(c));
    } else {
      out.push_back('%');
      out.push_back(hex[c >> 4]);
      out.push_back(hex[c & 15]);
    }
  }
  return out;
}

namespace {

bool starts_with_ignoring_case(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  return true;
}

// The absolute form `http://host:port/path?query` (RFC 9112 §3.2.2: a server accepts it, as a
// proxy would send it) as its path and query; "/" when it has no path. Other schemes: nullopt.
std::optional<std::string> origin_form(std::string_view target) {
  std::size_t scheme = 0;
  if (starts_with_ignoring_case(target, "http://"))
    scheme = 7;
  else if (starts_with_ignoring_case(target, "https://"))
    scheme = 8;
  else
    return std::nullopt;
  const auto path = target.find_first_of("/?", scheme);
  if (path == scheme) return std::nullopt; // no authority
  if (path == std::string_view::npos) return std::string("/");
  std::string out(target.substr(path));
  if (out.front() == '?') out.insert(0, 1, '/');
  return out;
}

} // namespace

std::optional<Target> parse_target(std::string_view target) {
  std::string absolute;
  if (!target.empty() && target.front() != '/') {
    auto origin = origin_form(target);
    if (!origin) return std::nullopt;
    absolute = std::move(*origin);
    target = absolute;
  }
  if (target.empty() || target.front() != '/') return std::nullopt;
  auto q = target.find('?');
  Target t;
  auto path = percent_decode(target.substr(0, q), false);
  if (!path) return std::nullopt;
  t.path = *path;
  if (q == std::string_view::npos) return t;
  std::string_view rest = target.substr(q + 1);
  while (!rest.empty()) {
    auto amp = rest.find('&');
    std::string_view pair = rest.substr(0, amp);
    rest = amp == std::string_view::npos ? std::string_view{} : rest.substr(amp + 1);
    if (pair.empty()) continue;
    auto eq = pair.find('=');
    auto key = percent_decode(pair.substr(0, eq), true);
    auto value = percent_decode(eq == std::string_view::npos ? "" : pair.substr(eq + 1), true);
    if (!key || !value) return std::nullopt;
    t.query[*key] = *value;
  }
  return t;
}

} // namespace slipfront::server
