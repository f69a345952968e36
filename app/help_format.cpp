#include "app/help_format.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace slipfront::app {

namespace {

constexpr std::size_t help_width = 92;
constexpr std::size_t max_name_column = 26; // longer names put their help on the next line
// The top level shows a command's whole usage line up to this many options.
constexpr std::size_t options_in_command_list = 8;

bool is_flag(const CLI::Option& option) {
  return option.get_type_name().empty();
}

std::string value_name(const CLI::Option& option) {
  return is_flag(option) ? "" : " " + option.get_type_name();
}

// "--output RESULT.h5", "-h, --help", "JOB.json".
std::string option_name(const CLI::Option& option) {
  if (option.get_positional()) return option.get_name(true);
  std::string name;
  for (const std::string& s : option.get_snames())
    name += "-" + s + ", ";
  return name + "--" + option.get_lnames().front() + value_name(option);
}

std::string usage_word(const CLI::Option& option) {
  if (option.get_positional())
    return option.get_required() ? option.get_name(true) : "[" + option.get_name(true) + "]";
  return "[--" + option.get_lnames().front() + value_name(option) + "]";
}

// The words on lines of at most help_width characters; the text starts at `first_column`
// and every line after the first `indent` spaces in.
std::string wrap(const std::vector<std::string>& words, std::size_t first_column,
                 std::size_t indent) {
  std::string out;
  std::size_t column = first_column;
  bool line_empty = true;
  for (const std::string& word : words) {
    if (!line_empty && column + 1 + word.size() > help_width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
      line_empty = true;
    }
    if (!line_empty) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    line_empty = false;
  }
  return out;
}

std::vector<std::string> split_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;)
    words.push_back(word);
  return words;
}

// "  --output RESULT.h5  write the ..." with the help wrapped in its column.
std::string option_row(const CLI::Option& option, std::size_t column) {
  std::string row = "  " + option_name(option);
  if (row.size() + 2 > column)
    row += "\n" + std::string(column, ' ');
  else
    row += std::string(column - row.size(), ' ');
  return row + wrap(split_words(option.get_description()), column, column) + "\n";
}

std::string option_table(const char* title, const std::vector<const CLI::Option*>& options) {
  if (options.empty()) return "";
  std::size_t column = 0;
  for (const CLI::Option* option : options)
    column = std::max(column, option_name(*option).size() + 4);
  column = std::min(column, max_name_column);
  std::string out = std::string("\n") + title + ":\n";
  for (const CLI::Option* option : options)
    out += option_row(*option, column);
  return out;
}

// `text` wrapped, `indent` spaces in: its paragraphs (separated by blank lines) are filled,
// lines that start with two spaces (examples, lists) kept as written.
std::string filled(const std::string& text, std::size_t indent) {
  std::string out;
  std::vector<std::string> paragraph;
  const auto flush = [&] {
    if (!paragraph.empty())
      out += std::string(indent, ' ') + wrap(paragraph, indent, indent) + "\n";
    paragraph.clear();
  };
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.starts_with("  ")) {
      flush();
      out += (line.empty() ? "" : std::string(indent, ' ') + line) + "\n";
      continue;
    }
    for (std::string& word : split_words(line))
      paragraph.push_back(std::move(word));
  }
  flush();
  return out;
}

// The commands a user types (the hidden ones, in no group, are left out).
std::vector<const CLI::App*> listed_commands(const CLI::App& top) {
  return top.get_subcommands([](const CLI::App* c) { return !c->get_group().empty(); });
}

std::string command_help(const CLI::App& command) {
  std::vector<const CLI::Option*> arguments, options;
  for (const CLI::Option* option : command.get_options()) {
    if (option == command.get_help_ptr()) continue;
    (option->get_positional() ? arguments : options).push_back(option);
  }
  options.push_back(command.get_help_ptr());
  return usage_line(command, "usage: ") + "\n\n" + filled(command.get_description(), 0) +
         option_table("arguments", arguments) + option_table("options", options) +
         (command.get_footer().empty() ? "" : "\n" + filled(command.get_footer(), 0));
}

std::string top_help(const CLI::App& top) {
  std::string out = filled(top.get_description(), 0) + "\nusage:\n";
  std::string names;
  for (const CLI::App* command : listed_commands(top)) {
    out += usage_line(*command, "  ", options_in_command_list) + "\n";
    out += filled(command->get_description(), 6);
    names += (names.empty() ? "" : "|") + command->get_name();
  }
  out += "  slipfront " + names + " --help\n" +
         "      The options of one command (also: slipfront help COMMAND).\n" +
         "  slipfront --version\n" + "  slipfront help | --help\n";
  return out + (top.get_footer().empty() ? "" : "\n" + filled(top.get_footer(), 0));
}

} // namespace

std::string command_path(const CLI::App& command) {
  const CLI::App* parent = command.get_parent();
  return parent == nullptr ? command.get_name() : command_path(*parent) + " " + command.get_name();
}

std::string usage_line(const CLI::App& command, const std::string& prefix,
                       std::size_t max_options) {
  std::vector<std::string> words = {command_path(command)};
  std::size_t shown = 0;
  for (const CLI::Option* option : command.get_options())
    if (option->get_positional()) words.push_back(usage_word(*option));
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_positional() || option == command.get_help_ptr()) continue;
    if (shown++ == max_options) {
      words.push_back("[...]");
      break;
    }
    words.push_back(usage_word(*option));
  }
  const std::size_t indent = prefix.size() + words.front().size() + 1;
  return prefix + wrap(words, prefix.size(), indent);
}

std::string HelpFormat::make_help(const CLI::App* command, std::string, CLI::AppFormatMode) const {
  return command->get_parent() == nullptr ? top_help(*command) : command_help(*command);
}

} // namespace slipfront::app
