// Free text from clients: job and study names and tags. It is stored, listed, logged and
// shown, never interpreted (no shell, batch script or command line ever holds it), and it may
// not hold control characters: a newline or a carriage return would start a new line in a
// log, a CSV cell or a generated file, an escape sequence would drive a terminal.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace slipfront::api {

// The JSON Schema "pattern" of such text (ECMA-262): none of the characters below.
extern const char* const free_text_pattern;

// The reason of the error for text holding a control character, naming the first one:
// "must not contain control characters (U+000A at byte 1)"; nothing if there is none.
// Control characters: U+0000-U+001F, U+007F-U+009F (C0, DEL, C1), and the line and
// paragraph separators U+2028 and U+2029.
std::optional<std::string> free_text_error(std::string_view utf8);

} // namespace slipfront::api
