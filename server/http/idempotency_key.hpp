// The Idempotency-Key header of POST /jobs and POST /studies (docs/server.md): a client that
// got no answer retries with the same key and gets the first submission's job or study.
#pragma once

#include "api/job_spec.hpp" // api::FieldError
#include "server/http/http_types.hpp"

#include <string>
#include <vector>

namespace slipfront::server {

// The key ("" when the header is absent); an error at /headers/Idempotency-Key when it is
// empty, longer than 200 characters or holds control characters.
std::string idempotency_key(const Request& request, std::vector<api::FieldError>& errors);

} // namespace slipfront::server
