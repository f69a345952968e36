// The arguments and flags more than one command takes, each defined here once (its name,
// value, help and checks): JOB.json, --threads, --max-memory, --quiet. A value that does not
// parse is a CLI::ValidationError whose text is the whole reason ("--threads needs an
// integer, got \"many\"").
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace slipfront::app {

// JOB.json (run, validate): a path, or "-" for standard input.
void add_job_file(CLI::App& command, std::string& path);

// --threads N (run, validate): overrides the job's "threads" (validated like it).
void add_threads(CLI::App& command, std::optional<int>& threads);

// --max-memory SIZE (run, validate, serve): refuse a job whose memory estimate is above SIZE,
// bytes or a number with the suffix K, M, G or T (api/memory_size.hpp). "0" sets `bytes` back
// to its value now: the command's default, which `default_text` describes. `old_name` is a
// former name still accepted (serve: "max-memory-bytes").
void add_max_memory(CLI::App& command, double& bytes, const std::string& default_text,
                    const std::string& old_name = "");

// --cost-model F (validate, serve): the cost model of the estimates (api/cost_estimate.hpp), a
// file `slipfront calibrate` wrote; `default_text` says what holds without it.
void add_cost_model(CLI::App& command, std::string& path, const std::string& default_text);

// --quiet (run): no progress on stderr.
void add_quiet(CLI::App& command, bool& quiet);

// A subcommand of `parent` with the help flag, formatter and error behaviour of every
// command: unknown arguments are collected (and reported by main), a flag given twice keeps
// its last value.
CLI::App* add_command(CLI::App& parent, const std::string& name, const std::string& description,
                      const std::string& footer = "");

} // namespace slipfront::app
