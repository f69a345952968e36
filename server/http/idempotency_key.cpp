#include "server/http/idempotency_key.hpp"

#include "api/free_text.hpp"

namespace slipfront::server {

std::string idempotency_key(const Request& request, std::vector<api::FieldError>& errors) {
  if (!request.count("Idempotency-Key")) return "";
  std::string key(request["Idempotency-Key"]);
  const char* pointer = "/headers/Idempotency-Key";
  if (key.empty() || key.size() > 200) {
    errors.push_back({pointer, "must be 1 to 200 characters"});
    return "";
  }
  if (auto reason = api::free_text_error(key)) {
    errors.push_back({pointer, std::move(*reason)});
    return "";
  }
  return key;
}

} // namespace slipfront::server
