// A length fit as JSON (docs/length-fit.md "The answer"): what POST /api/v1/length-fits
// answers and `slipfront fit-length --json` prints. Infinite or undefined numbers are null.
#pragma once

#include "api/length_fit/length_fit.hpp"

#include <nlohmann/json.hpp>

namespace slipfront::api {

nlohmann::json length_fit_json(const InterfaceRecord& record, const LengthFit& fit);

} // namespace slipfront::api
