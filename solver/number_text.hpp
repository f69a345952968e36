// A number as people write it in messages and names: printf's %g (shortest of fixed and
// scientific, trailing zeros dropped) with a chosen number of significant digits.
// "5e-05", "20", "0.125"; the one formatting of numbers in reasons, logs and run names.
#pragma once

#include <cstdio>
#include <string>

namespace slipfront {

inline std::string number_text(double value, int significant_digits = 6) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant_digits, value);
  return buffer;
}

} // namespace slipfront
