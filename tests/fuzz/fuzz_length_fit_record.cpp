// libFuzzer target: a length-fit record (POST /api/v1/length-fits' "record", a file of
// `slipfront fit-length`): CSV or JSON text through read_record_text, the record checks and,
// when it passes them, the whole fit and its JSON (api/length_fit/, docs/length-fit.md).
// The first byte, when it is a digit, chooses a station (x1 = that digit).
// Finds: crashes, sanitizer reports (a double too large for an integer included), exceptions
// (the server would answer 500), an error without a reason, and an answer that contradicts
// itself: a fitted L outside its own interval, a verdict against its own numbers.
#include "api/length_fit/length_fit_json.hpp"
#include "api/length_fit/record_reader.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace {

void fail(const char* what) {
  std::fprintf(stderr, "%s\n", what);
  std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace slipfront::api;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<double> station;
  if (!text.empty() && text.front() >= '0' && text.front() <= '9') {
    station = double(text.front() - '0');
    text.remove_prefix(1);
  }
  const RecordRead read = read_record_text(text, station);
  if (!read.record) {
    if (read.errors.empty()) fail("refused without an error");
    for (const RecordError& e : read.errors)
      if (e.reason.empty()) fail("an error without a reason");
    return 0;
  }
  const LengthFitOutcome outcome = fit_length(*read.record, LengthFitOptions{});
  if (!outcome.result) {
    if (outcome.errors.empty()) fail("not fitted, without an error");
    return 0;
  }
  const LengthFit& r = *outcome.result;
  const double L = r.fit.law.L;
  if (!(L > 0) || !std::isfinite(L)) fail("a fitted L that is not a positive number");
  if (!(r.fit.L_low <= L && L <= r.fit.L_high)) fail("L outside its own interval");
  if (r.fit.fitted_stress.size() != read.record->size()) fail("a fitted series of another size");
  if (r.verdict.rich_enough != (r.verdict.power_above_f_m > r.verdict.power_threshold))
    fail("a verdict against its own numbers");
  (void)length_fit_json(*read.record, r).dump(); // must not throw (NaN and inf are null)
  return 0;
}
