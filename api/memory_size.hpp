// A memory size as every command line spells it (`--max-memory SIZE` of run, validate and
// serve): bytes, or a number with the suffix K, M, G or T (powers of 1000), e.g. "8G".
#pragma once

#include <optional>
#include <string>

namespace slipfront::api {

// Nothing if the text is not such a positive, finite size.
std::optional<double> parse_memory_size(const std::string& text);

} // namespace slipfront::api
