#include "api/memory_size.hpp"

#include "api/number_text.hpp"

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

std::string memory_size_expected(const std::string& text) {
  return "needs a size such as 8G or 500M (bytes, or K, M, G, T: powers of 1000), got \"" + text +
         "\"";
}

std::string byte_size_text(double bytes) {
  static const char* const units[] = {"bytes", "kB", "MB", "GB", "TB"};
  int unit = 0;
  // 999.95 MB prints as "1e+03 MB" with three digits: move on to the next unit from 999.5.
  while (unit < 4 && std::abs(bytes) >= 999.5) {
    bytes /= 1000.0;
    ++unit;
  }
  return number_text(bytes, 3) + " " + units[unit];
}

} // namespace slipfront::api
