// `slipfront stations RESULT.h5 [--csv FILE]`: the stations of a result file
// (docs/hdf5-layout.md "/stations"): their rupture times, or every step as CSV.
#include "app/commands.hpp"

#include "api/result_stations.hpp"
#include "api/station_csv.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace slipfront::app {

namespace {

// One line per station: x1, the nodes it is read from, its rupture time.
void print_rupture_times(std::ostream& out, const StationRecords& r) {
  out << "rupture threshold: " << r.rupture_threshold << " m/s; " << r.time.size()
      << " steps recorded\n";
  char line[200];
  std::snprintf(line, sizeof line, "%16s  %-30s  %s\n", "station_x1 [m]", "nodes x1 [m] (weights)",
                "rupture_time [s]");
  out << line;
  for (std::size_t s = 0; s < r.x1.size(); ++s) {
    char nodes[80];
    if (r.node_weight[2 * s + 1] == 0.0)
      std::snprintf(nodes, sizeof nodes, "%.9g (on the node)", r.node_x1[2 * s]);
    else
      std::snprintf(nodes, sizeof nodes, "%.9g, %.9g (%.3g, %.3g)", r.node_x1[2 * s],
                    r.node_x1[2 * s + 1], r.node_weight[2 * s], r.node_weight[2 * s + 1]);
    std::snprintf(line, sizeof line, "%16.9g  %-30s  %.9g\n", r.x1[s], nodes, r.rupture_time[s]);
    out << line;
  }
}

} // namespace

int stations_command(const std::vector<std::string>& args) {
  if (wants_help(args)) {
    print_stations_usage(std::cout);
    return exit_code::success;
  }
  std::vector<std::string> files;
  std::string csv;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--csv") {
      if (i + 1 == args.size()) {
        std::cerr << "slipfront stations: --csv needs a FILE (or - for standard output)\n";
        return exit_code::bad_input;
      }
      csv = args[++i];
    } else if (args[i].starts_with("-")) {
      std::cerr << "slipfront stations: unexpected argument \"" << args[i]
                << "\" (see slipfront stations --help)\n";
      return exit_code::bad_input;
    } else {
      files.push_back(args[i]);
    }
  }
  if (files.size() != 1) {
    std::cerr << "slipfront stations: expects exactly one RESULT.h5 (see slipfront stations "
                 "--help)\n";
    return exit_code::bad_input;
  }
  std::string why;
  const std::optional<StationRecords> stations = api::read_stations(files[0], why);
  if (!stations) {
    std::cerr << "slipfront stations: " << files[0] << ": " << why << '\n';
    return exit_code::failure;
  }
  if (stations->empty()) {
    std::cerr << "slipfront stations: " << files[0]
              << " has no stations (its job lists none: \"stations\": {\"x1\": [...]})\n";
    return exit_code::failure;
  }
  if (csv.empty()) {
    print_rupture_times(std::cout, *stations);
    return exit_code::success;
  }
  if (csv == "-") {
    api::write_stations_csv(std::cout, *stations);
    return std::cout ? exit_code::success : exit_code::failure;
  }
  std::ofstream out(csv);
  if (out) api::write_stations_csv(out, *stations);
  out.close();
  if (!out) {
    std::cerr << "slipfront stations: cannot write " << csv << '\n';
    return exit_code::failure;
  }
  return exit_code::success;
}

} // namespace slipfront::app
