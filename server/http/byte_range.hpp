// The Range header of a download (RFC 9110 §14): one range of bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace slipfront::server {

struct ByteRange {
  std::uint64_t first = 0;
  std::uint64_t length = 0;
};

struct RangeRequest {
  enum class Kind { whole, partial, unsatisfiable } kind = Kind::whole;
  ByteRange range;
};

// "bytes=a-b", "bytes=a-" or "bytes=-n" against a file of `size` bytes. Anything else
// (other units, several ranges, syntax errors) is served whole, as RFC 9110 allows.
RangeRequest parse_range(std::string_view header, std::uint64_t size);

} // namespace slipfront::server
