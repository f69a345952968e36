#include "app/options.hpp"

#include "api/memory_size.hpp"

#include <charconv>

namespace slipfront::app {

void add_job_file(CLI::App& command, std::string& path) {
  command
      .add_option("JOB.json", path,
                  "the job (docs/api-job-spec.md); \"-\" reads it from "
                  "standard input")
      ->required();
}

void add_threads(CLI::App& command, std::optional<int>& threads) {
  command
      .add_option_function<std::string>(
          "--threads",
          [&threads](const std::string& text) {
            int value = 0;
            const auto [end, error] =
                std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc() || end != text.data() + text.size())
              throw CLI::ValidationError("--threads needs an integer, got \"" + text + "\"");
            threads = value;
          },
          "worker threads (overrides the job's \"threads\", and is checked like it; 0 = all "
          "cores; the spec hash does not change)")
      ->type_name("N");
}

void add_max_memory(CLI::App& command, double& bytes, const std::string& default_text,
                    const std::string& old_name) {
  command
      .add_option_function<std::string>(
          "--max-memory" + (old_name.empty() ? "" : ",--" + old_name),
          [&bytes, default_bytes = bytes](const std::string& text) {
            if (text == "0") {
              bytes = default_bytes;
              return;
            }
            const std::optional<double> size = api::parse_memory_size(text);
            if (!size)
              throw CLI::ValidationError("--max-memory " + api::memory_size_expected(text));
            bytes = *size;
          },
          "refuse a job whose memory estimate is above SIZE: bytes, or a number with the suffix "
          "K, M, G or T (powers of 1000); 0 or no flag: " +
              default_text +
              (old_name.empty() ? "" : " (its old name --" + old_name + " is taken too)"))
      ->type_name("SIZE");
}

void add_cost_model(CLI::App& command, std::string& path, const std::string& default_text) {
  command
      .add_option("--cost-model", path,
                  "the cost model of the wall-time estimate, as slipfront calibrate writes it "
                  "(docs/performance.md \"Cost estimate\"); without it: " +
                      default_text)
      ->type_name("F");
}

void add_quiet(CLI::App& command, bool& quiet) {
  command.add_flag("--quiet", quiet, "no progress on stderr");
}

CLI::App* add_command(CLI::App& parent, const std::string& name, const std::string& description,
                      const std::string& footer) {
  CLI::App* command = parent.add_subcommand(name, description);
  command->footer(footer);
  command->allow_extras();
  command->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  command->group("commands");
  return command;
}

} // namespace slipfront::app
