// libFuzzer target: the Range header of a download (server/http/byte_range.hpp) against a file
// size taken from the input's first 8 bytes. A partial answer must lie inside the file and
// be non-empty; an unsatisfiable one only happens for a range starting at or after its end.
#include "server/http/byte_range.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using slipfront::server::RangeRequest;
  std::uint64_t file_size = 0;
  const std::size_t head = size < 8 ? size : 8;
  std::memcpy(&file_size, data, head);
  if (file_size % 4 == 0) file_size %= 1000; // small files often, huge ones sometimes
  const std::string_view header(reinterpret_cast<const char*>(data) + head, size - head);
  const auto r = slipfront::server::parse_range(header, file_size);
  if (r.kind == RangeRequest::Kind::partial) {
    const bool inside = r.range.length > 0 && r.range.first < file_size &&
                        r.range.length <= file_size - r.range.first;
    if (!inside) {
      std::fprintf(stderr, "range [%llu, +%llu) of a %llu-byte file\n",
                   static_cast<unsigned long long>(r.range.first),
                   static_cast<unsigned long long>(r.range.length),
                   static_cast<unsigned long long>(file_size));
      std::abort();
    }
  }
  return 0;
}
