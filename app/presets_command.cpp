// `slipfront presets [NAME] [--json]`: the presets a job may start from (api/presets.hpp,
// docs/presets.md). Without NAME a table of names and titles (or the whole list as JSON);
// with NAME the preset's job, ready to run or to edit:
//   slipfront presets scec_tpv3_2d > tpv3.json && slipfront run tpv3.json
// A job file may also name it: {"preset": "scec_tpv3_2d", "method": "spectral_bi"}.
#include "app/commands.hpp"

#include "api/presets.hpp"

#include <iomanip>
#include <iostream>

namespace slipfront::app {

void print_presets_usage(std::ostream& out) {
  out << R"(usage: slipfront presets [NAME] [--json]

Without NAME: the presets, one per line (name and title), or with --json the whole list
({"presets": [{name, origin, title, description, reference, spec}]}, as GET /api/v1/presets).
With NAME: that preset's job as JSON on stdout (by FE unless the preset says), to run or
edit; with --json the whole entry, its job by each method under "specs".
A job file may name a preset and change some fields:
  {"preset": "scec_tpv3_2d", "method": "spectral_bi"}
(the preset's job with the file's other members merged over it; docs/presets.md).

exit codes: 0 success, 2 unknown preset or argument.
)";
}

int presets_command(const std::vector<std::string>& args) {
  if (wants_help(args)) {
    print_presets_usage(std::cout);
    return exit_code::success;
  }
  bool json = false;
  std::string name;
  for (const std::string& arg : args) {
    if (arg == "--json") {
      json = true;
    } else if (!arg.empty() && arg[0] != '-' && name.empty()) {
      name = arg;
    } else {
      std::cerr << "slipfront presets: unexpected argument \"" << arg << "\"\n\n";
      print_presets_usage(std::cerr);
      return exit_code::bad_input;
    }
  }
  if (!name.empty()) {
    const api::Preset* preset = api::find_preset(name);
    if (preset == nullptr) {
      std::cerr << "slipfront presets: no preset is called \"" << name
                << "\" (`slipfront presets` lists them)\n";
      return exit_code::bad_input;
    }
    const nlohmann::json entry = api::preset_json(*preset);
    std::cout << (json ? entry : entry["spec"]).dump(2) << '\n';
    return exit_code::success;
  }
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const api::Preset& preset : api::presets())
      list.push_back(api::preset_json(preset));
    std::cout << nlohmann::json{{"presets", list}}.dump(2) << '\n';
    return exit_code::success;
  }
  for (const api::Preset& preset : api::presets())
    std::cout << std::left << std::setw(28) << preset.name << ' ' << preset.title << '\n';
  return exit_code::success;
}

} // namespace slipfront::app
