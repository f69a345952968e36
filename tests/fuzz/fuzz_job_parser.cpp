// libFuzzer target: a POST /api/v1/jobs body (or a job file of `slipfront run`) through
// the bounded JSON parser and the job validator (api/job_spec.hpp).
// Finds: crashes, sanitizer reports, exceptions (the server would answer 500), and a
// canonical form that does not validate again to the same job.
#include "api/job_spec.hpp"
#include "api/json_parse.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  slipfront::api::ValidationLimits limits; // the server's defaults
  limits.max_memory_bytes = 8.0e9;
  limits.max_result_bytes = 20.0e9;
  const auto parsed = slipfront::api::parse_job_text(text, limits);
  if (!parsed.ok()) {
    for (const auto& e : parsed.errors)
      if (e.reason.empty()) {
        std::fprintf(stderr, "error without a reason at '%s'\n", e.pointer.c_str());
        std::abort();
      }
    return 0;
  }
  // The canonical form is a job too, and the same one.
  const auto again = slipfront::api::parse_job(parsed.spec->canonical, limits);
  if (!again.ok() || again.spec->sha256 != parsed.spec->sha256 ||
      again.spec->canonical != parsed.spec->canonical) {
    std::fprintf(stderr, "canonical form does not round-trip: %s\n",
                 parsed.spec->canonical.dump().c_str());
    std::abort();
  }
  return 0;
}
