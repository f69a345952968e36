// Study analysis (docs/metrics.md "Convergence status", "Critical length"), one include for all of
// it: mesh convergence (api/study/ convergence.hpp), the critical length
// (api/study/critical_length.hpp), speed/accuracy (api/study/speed_accuracy.hpp) and the
// failure-regime presets. The rules and their edge cases are documented in docs/studies.md.
#pragma once

#include "api/study/convergence.hpp"
#include "api/study/critical_length.hpp"
#include "api/study/failure_regimes.hpp"
#include "api/study/l_search.hpp"
#include "api/study/speed_accuracy.hpp"
#include "api/study/study_run.hpp"
