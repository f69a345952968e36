// Splitting a request target into its path and its decoded query parameters.
#pragma once

#include "server/core/comma_list.hpp" // split_list, for the query values

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront::server {

// Percent-decoding ('+' is a space in queries). nullopt on a malformed escape.
std::optional<std::string> percent_decode(std::string_view text, bool plus_is_space);

// Percent-encoding of a query value (unreserved characters are kept).
std::string percent_encode(std::string_view text);

struct Target {
  std::string path;                         // decoded
  std::map<std::string, std::string> query; // decoded; the last value of a repeated key wins
};

// The origin form (/path?query) or the absolute form (http://host/path?query, its path and
// query); nullopt on a malformed target (bad escapes, another scheme, neither form).
std::optional<Target> parse_target(std::string_view target);

} // namespace slipfront::server
