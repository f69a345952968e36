#include "api/memory_size.hpp"

#include <cmath>
#include <stdexcept>

namespace slipfront::api {

std::optional<double> parse_memory_size(const std::string& text) {
  try {
    std::size_t used = 0;
    double value = std::stod(text, &used);
    const std::string suffix = text.substr(used);
    const double scale = suffix.empty()  ? 1.0
                         : suffix == "K" ? 1e3
                         : suffix == "M" ? 1e6
                         : suffix == "G" ? 1e9
                         : suffix == "T" ? 1e12
                                         : 0.0;
    value *= scale;
    if (!(value > 0.0) || !std::isfinite(value)) return std::nullopt;
    return value;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

} // namespace slipfront::api
