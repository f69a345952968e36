// Reading and checking a job file for the CLI commands.
#pragma once

#include "api/job_spec.hpp"
#include "api/memory_size.hpp"

#include <iosfwd>
#include <optional>
#include <string>

namespace slipfront::app {

// The job text from `path`, or from standard input for "-". Throws std::runtime_error if
// the file cannot be read.
std::string read_job_text(const std::string& path);

// Writes each error as "pointer: reason", one per line ("(document)" for the whole document).
void print_errors(std::ostream& out, const std::vector<api::FieldError>& errors);

// Reads and validates the job at `path` against `limits`. On any problem prints it to
// stderr and returns nothing. `threads`, when given, overrides the job's "threads" field
// before validation.
std::optional<api::JobSpec> load_job(const std::string& path,
                                     std::optional<int> threads = std::nullopt,
                                     const api::ValidationLimits& limits = {});

// A memory size for --max-memory (api/memory_size.hpp).
using api::parse_memory_size;

} // namespace slipfront::app
