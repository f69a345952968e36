// Wall-clock timestamps as the API and the database show them.
#pragma once

#include <string>

namespace slipfront::server {

// Current UTC time as ISO 8601 with milliseconds, e.g. "2024-05-01T12:00:00.123Z".
std::string now_iso8601();

// Whether `text` is a time as now_iso8601() writes it: UTC, ISO 8601, "YYYY-MM-DDTHH:MM:SS"
// with 1 to 9 digits of a second's fraction or none, then "Z", a date that exists.
bool is_utc_iso8601(const std::string& text);

// Seconds between two timestamps produced by now_iso8601() (NaN if either is unparsable).
double seconds_between(const std::string& from, const std::string& to);

// This machine's host name ("unknown" if it cannot be read).
std::string host_name();

} // namespace slipfront::server
