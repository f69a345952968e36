// A memory size as every command line spells it (`--max-memory SIZE` of run, validate and
// serve): bytes, or a number with the suffix K, M, G or T (powers of 1000), e.g. "8G"; and a
// byte count as messages print it ("1 kB", "62.4 MB", "8 GB").
#pragma once

#include <optional>
#include <string>

namespace slipfront::api {

// Nothing if the text is not such a positive, finite size.
std::optional<double> parse_memory_size(const std::string& text);

// Why `text` is no size: "needs a size such as 8G or 500M, got \"lots\"".
std::string memory_size_expected(const std::string& text);

// `bytes` in the unit (bytes, kB, MB, GB, TB; powers of 1000) that leaves a number from 1 to
// 999, three significant digits: 1e3 -> "1 kB", 62426754 -> "62.4 MB", 8e9 -> "8 GB".
std::string byte_size_text(double bytes);

} // namespace slipfront::api
