// The versioned base path of every API route and link (docs/server.md).
#pragma once

#include <string>

namespace slipfront::server {

inline const std::string api_prefix = "/api/v1";

} // namespace slipfront::server
