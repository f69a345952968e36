// libFuzzer target: a POST /api/v1/studies body through the bounded JSON parser, the study
// request parser (server/core/study_request.hpp) and, when it is accepted, the job validator on
// the document of its first run (what StudyService checks before anything is stored).
#include "api/job_spec.hpp"
#include "api/json_parse.hpp"
#include "server/core/study_request.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto body = slipfront::api::parse_bounded_json(text);
  if (!body.ok()) return 0;
  const auto parsed = slipfront::server::parse_study_request(body.value);
  if (!parsed.request) {
    if (parsed.errors.empty()) {
      std::fprintf(stderr, "refused without an error\n");
      std::abort();
    }
    return 0;
  }
  const auto& request = *parsed.request;
  const double L = request.L.empty() ? 5e-5 : request.L.front();
  const double n_d = request.n_d.empty() ? 10.0 : request.n_d.front();
  auto document = slipfront::server::run_document(request, "0123456789abcdef0123456789abcdef",
                                                  nlohmann::json::object(), "", L, n_d);
  if (document.is_object() && !document.contains("threads")) document["threads"] = 1;
  slipfront::api::ValidationLimits limits;
  limits.max_result_bytes = 20.0e9;
  (void)slipfront::api::parse_job(document, limits);
  return 0;
}
