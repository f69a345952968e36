// One-line log messages on stderr with a UTC timestamp (journald keeps them).
#pragma once

#include <string>

namespace slipfront::server {

void log_info(const std::string& message);
void log_error(const std::string& message);

} // namespace slipfront::server
