#include "server/core/priority.hpp"

#include <cstdint>

namespace slipfront::server {

std::string priority_rule() {
  return "must be an integer in [" + std::to_string(lowest_priority) + ", " +
         std::to_string(highest_priority) + "]";
}

std::optional<int> priority_of(long value) {
  if (value < lowest_priority || value > highest_priority) return std::nullopt;
  return static_cast<int>(value);
}

std::optional<int> priority_of(const nlohmann::json& value) {
  if (!value.is_number_integer()) return std::nullopt;
  // An unsigned integer above the range is refused before a signed read could wrap it.
  if (value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t{highest_priority})
    return std::nullopt;
  return priority_of(static_cast<long>(value.get<std::int64_t>()));
}

} // namespace slipfront::server
