// The one formatting of numbers in messages (solver/number_text.hpp), for api's messages.
#pragma once

#include "solver/number_text.hpp"

namespace slipfront::api {

using slipfront::number_text;

} // namespace slipfront::api
