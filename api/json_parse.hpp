// The one way user JSON is parsed (job files, HTTP bodies): a nesting-depth bound and
// errors in our own words.
//
// Every later walk over a document (copy, merge, dump, destroy) recurses once per level, so
// a body of 60 000 nested arrays that parses fine can still exhaust the stack afterwards.
// parse_bounded_json() stops at `max_depth` levels, before a value that deep exists. It also
// names the member holding a number JSON allows but a double cannot hold (`1e999`), and
// reports syntax errors by position, never with the JSON library's exception text.
#pragma once

#include "api/job_spec.hpp"

#include <nlohmann/json.hpp>

#include <string_view>

namespace slipfront::api {

// Job specs nest 2 levels, study requests 4; 32 leaves room and keeps recursion shallow.
constexpr int max_json_depth = 32;

struct JsonParse {
  enum class Status {
    ok,
    syntax,              // not JSON (HTTP 400)
    too_deep,            // valid JSON nested deeper than the limit (HTTP 422)
    number_out_of_range, // a number beyond the range of a double (HTTP 422)
  };
  Status status = Status::ok;
  nlohmann::json value;
  FieldError error; // pointer and reason when status != ok

  bool ok() const { return status == Status::ok; }
};

JsonParse parse_bounded_json(std::string_view text, int max_depth = max_json_depth);

} // namespace slipfront::api
