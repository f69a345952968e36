// Job identifiers: 32 lower-case hex characters (128 random bits).
#pragma once

#include <string>
#include <string_view>

namespace slipfront::server {

std::string new_job_id();

// True only for exactly 32 characters in [0-9a-f]; anything else never reaches the store or
// the file system.
bool is_valid_job_id(std::string_view text);

} // namespace slipfront::server
