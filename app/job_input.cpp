#include "app/job_input.hpp"

#include "api/json_parse.hpp"

#include <cerrno>
#include <cstring>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace slipfront::app {

std::string read_job_text(const std::string& path) {
  const std::string name = path == "-" ? "standard input" : "job file " + path;
  std::ostringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
  } else {
    std::error_code ec; // a directory opens as a stream and reads as nothing
    const int error = std::filesystem::is_directory(path, ec) ? EISDIR : 0;
    std::ifstream file(path);
    if (!file || error != 0)
      throw std::runtime_error("cannot open " + name + ": " + std::strerror(error ? error : errno));
    text << file.rdbuf();
    if (file.bad()) throw std::runtime_error("cannot read " + name);
  }
  if (text.str().find_first_not_of(" \t\r\n") == std::string::npos)
    throw std::runtime_error(name + " is empty: it should hold the job as a JSON object "
                                    "({} is the paper's scene)");
  return text.str();
}

void print_errors(std::ostream& out, const std::vector<api::FieldError>& errors) {
  for (const auto& error : errors) {
    out << (error.pointer.empty() ? "(document)" : error.pointer) << ": " << error.reason << '\n';
  }
}

void print_warnings(std::ostream& out, const std::vector<api::FieldWarning>& warnings) {
  for (const auto& warning : warnings)
    out << "warning: " << warning.pointer << ": " << warning.message << '\n';
}

std::optional<api::JobSpec> load_job(const std::string& command, const std::string& path,
                                     std::optional<int> threads,
                                     const api::ValidationLimits& limits) {
  std::string text;
  try {
    text = read_job_text(path);
  } catch (const std::exception& e) {
    std::cerr << command << ": " << e.what() << '\n';
    return std::nullopt;
  }

  auto parsed_json = api::parse_bounded_json(text);
  if (!parsed_json.ok()) {
    print_errors(std::cerr, {parsed_json.error});
    return std::nullopt;
  }
  nlohmann::json& document = parsed_json.value;
  if (threads && document.is_object()) document["threads"] = *threads;

  api::ParseResult parsed = api::parse_job(document, limits);
  if (!parsed.ok()) {
    print_errors(std::cerr, parsed.errors);
    return std::nullopt;
  }
  print_warnings(std::cerr, parsed.spec->warnings);
  return std::move(parsed.spec);
}

} // namespace slipfront::app
