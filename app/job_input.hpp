// Reading and checking a job file for the CLI commands.
#pragma once

#include "api/job_spec.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::app {

// The job text from `path`, or from standard input for "-". Throws std::runtime_error if
// the file cannot be read.
std::string read_job_text(const std::string& path);

// Writes each error as "pointer: reason", one per line ("(document)" for the whole document).
void print_errors(std::ostream& out, const std::vector<api::FieldError>& errors);

// Writes each warning as "warning: pointer: message", one per line.
void print_warnings(std::ostream& out, const std::vector<api::FieldWarning>& warnings);

// Reads and validates the job at `path` against `limits`. On any problem prints it to
// stderr (a file that cannot be read after `command`: "slipfront run: ...") and returns
// nothing; the warnings of a valid job go to stderr too. `threads`, when given, overrides the job's
// "threads" field before validation.
std::optional<api::JobSpec> load_job(const std::string& command, const std::string& path,
                                     std::optional<int> threads,
                                     const api::ValidationLimits& limits);

} // namespace slipfront::app
