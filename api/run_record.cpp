#include "api/run_record.hpp"

namespace slipfront::api {

std::string diverged_error(const std::string& message) {
  return "diverged: " + message;
}

} // namespace slipfront::api
