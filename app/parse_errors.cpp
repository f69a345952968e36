#include "app/parse_errors.hpp"

#include "app/commands.hpp"
#include "app/help_format.hpp"

#include <cctype>
#include <iostream>

namespace slipfront::app {

namespace {

// "a FILE", "an N", "a SIZE": the article as the value's name is read aloud.
std::string with_article(const std::string& name) {
  const bool vowel_sound =
      !name.empty() &&
      (std::string("AEIOU").find(static_cast<char>(
           std::toupper(static_cast<unsigned char>(name[0])))) != std::string::npos ||
       (name.size() == 1 && std::string("FHLMNRSX").find(name[0]) != std::string::npos));
  return (vowel_sound ? "an " : "a ") + name;
}

} // namespace

std::string parse_error_reason(const CLI::App& command, const CLI::ParseError& error) {
  const std::string what = error.what();
  if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr) {
    for (const CLI::Option* option : command.get_options())
      if (option->get_required() && option->count() == 0)
        return "missing " + option->get_name(true);
  }
  // CLI11 writes "--csv: 1 required FILE missing" for a flag given without its value.
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    const std::string name = what.substr(0, what.find(':'));
    if (const CLI::Option* option = command.get_option_no_throw(name))
      return name + " needs " + with_article(option->get_type_name());
  }
  return what;
}

int command_line_error(const CLI::App& command, const std::string& reason) {
  const std::string path = command_path(command);
  std::cerr << path << ": " << reason << " (see " << path << " --help)\n";
  return exit_code::bad_input;
}

std::string unexpected_arguments(const CLI::App& command) {
  const std::vector<std::string> left = command.remaining();
  if (left.empty()) return "";
  return "unexpected argument \"" + left.front() + "\"";
}

} // namespace slipfront::app
