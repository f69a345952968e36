#include "api/free_text.hpp"

#include <cstdio>

namespace slipfront::api {

const char* const free_text_pattern = "^[^\\u0000-\\u001f\\u007f-\\u009f\\u2028\\u2029]*$";

namespace {

struct Found {
  char32_t code_point;
  std::size_t at; // byte offset
};

// The text is UTF-8 (the JSON parser refuses anything else), so a C1 character is the two
// bytes C2 80..C2 9F and U+2028/U+2029 the three bytes E2 80 A8/A9.
std::optional<Found> first_control(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = [&](std::size_t k) {
      return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
    };
    const unsigned c = byte(i);
    if (c < 0x20 || c == 0x7f) return Found{c, i};
    if (c == 0xc2 && byte(i + 1) >= 0x80 && byte(i + 1) <= 0x9f) return Found{byte(i + 1), i};
    if (c == 0xe2 && byte(i + 1) == 0x80 && (byte(i + 2) == 0xa8 || byte(i + 2) == 0xa9))
      return Found{0x2000u + byte(i + 2) - 0x80u, i};
  }
  return std::nullopt;
}

std::string code_point_text(char32_t code_point) {
  char text[16];
  std::snprintf(text, sizeof text, "U+%04X", static_cast<unsigned>(code_point));
  return text;
}

} // namespace

std::optional<std::string> free_text_error(std::string_view utf8) {
  const auto found = first_control(utf8);
  if (!found) return std::nullopt;
  return "must not contain control characters (" + code_point_text(found->code_point) +
         " at byte " + std::to_string(found->at) + ")";
}

} // namespace slipfront::api
