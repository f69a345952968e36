// `slipfront presets [NAME] [--json]`: the presets a job may start from (api/presets.hpp,
// docs/presets.md). Without NAME a table of names and titles (or the whole list as JSON);
// with NAME the preset's job, ready to run or to edit:
//   slipfront presets scec_tpv3_2d > tpv3.json && slipfront run tpv3.json
// A job file may also name it: {"preset": "scec_tpv3_2d", "method": "spectral_bi"}.
#include "app/commands.hpp"
#include "app/options.hpp"

#include "api/json_number.hpp"
#include "api/presets.hpp"

#include <iomanip>
#include <iostream>
#include <memory>

namespace slipfront::app {

namespace {

struct PresetsOptions {
  std::string name;
  bool json = false;
};

int list_presets(const PresetsOptions& options);

} // namespace

Command add_presets_command(CLI::App& slipfront) {
  auto options = std::make_shared<PresetsOptions>();
  CLI::App* command = add_command(
      slipfront, "presets",
      "The presets a job may start from (the field's standard scenes and the examples): one "
      "per line, name and title; with NAME that preset's job as JSON on stdout (by FE unless "
      "the preset says), to run or edit. A job file may name a preset and change some fields "
      "(the preset's job with the file's other members merged over it; docs/presets.md):\n"
      "  {\"preset\": \"scec_tpv3_2d\", \"method\": \"spectral_bi\"}",
      "exit codes: 0 success, 2 unknown preset or invalid command line.");
  command->add_option("NAME", options->name, "a preset's name (`slipfront presets` lists them)");
  command->add_flag("--json", options->json,
                    "without NAME the whole list ({\"presets\": [{name, origin, title, "
                    "description, reference, spec}]}, as GET /api/v1/presets); with NAME the "
                    "whole entry, its job by each method under \"specs\"");
  return {command, [options] { return list_presets(*options); }};
}

namespace {

int list_presets(const PresetsOptions& options) {
  const std::string& name = options.name;
  const bool json = options.json;
  if (!name.empty()) {
    const api::Preset* preset = api::find_preset(name);
    if (preset == nullptr) {
      std::cerr << "slipfront presets: no preset is called \"" << name
                << "\" (`slipfront presets` lists them)\n";
      return exit_code::bad_input;
    }
    nlohmann::json entry = api::preset_json(*preset);
    api::whole_numbers_as_integers(entry);
    std::cout << (json ? entry : entry["spec"]).dump(2) << '\n';
    return exit_code::success;
  }
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const api::Preset& preset : api::presets())
      list.push_back(api::preset_json(preset));
    api::whole_numbers_as_integers(list);
    std::cout << nlohmann::json{{"presets", list}}.dump(2) << '\n';
    return exit_code::success;
  }
  for (const api::Preset& preset : api::presets())
    std::cout << std::left << std::setw(28) << preset.name << ' ' << preset.title << '\n';
  return exit_code::success;
}

} // namespace

} // namespace slipfront::app
