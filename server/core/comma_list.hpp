// Comma-separated lists as the API writes them: a query value (sort=a,-b, fields=...) or a
// header (If-None-Match).
#pragma once

#include <string_view>
#include <vector>

namespace slipfront::server {

// The items of a comma-separated list (a query value such as sort=a,-b, or a header such as
// If-None-Match), each with the whitespace around it trimmed. Empty items are kept: "a,,b"
// is {"a", "", "b"} and "" is {""}. The views point into `text`.
std::vector<std::string_view> split_list(std::string_view text);

} // namespace slipfront::server
