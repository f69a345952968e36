#include "solver/run/metrics.hpp"

namespace slipfront {

const char* to_string(Outcome outcome) {
  switch (outcome) {
  case Outcome::arrested:
    return "arrested";
  case Outcome::running_at_end:
    return "running_at_end";
  case Outcome::no_rupture:
    return "no_rupture";
  case Outcome::diverged:
    return "diverged";
  }
  return "unknown";
}

} // namespace slipfront
