// `slipfront stations RESULT.h5 [--threshold V] [--csv FILE]`: the stations of a result file
// (docs/hdf5-layout.md "/stations"): their rupture times (at another threshold if asked),
// peak slip rates and final slips, or every step as CSV.
#include "app/commands.hpp"
#include "app/options.hpp"

#include "api/result_stations.hpp"
#include "api/station_csv.hpp"
#include "solver/run/station_summary.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>

namespace slipfront::app {

namespace {

// One line per station: x1, the nodes it is read from, its rupture time (at `threshold`, the
// recorded threshold if NaN), its peak slip rate and its time, its final slip.
void print_stations(std::ostream& out, const StationRecords& r, double threshold) {
  const bool own = std::isnan(threshold);
  if (own) threshold = r.rupture_threshold;
  out << "rupture threshold: " << threshold << " m/s"
      << (own ? "" : " (asked; the run's: " + std::to_string(r.rupture_threshold) + " m/s)") << "; "
      << r.time.size() << " steps recorded\n";
  char line[300];
  std::snprintf(line, sizeof line, "%16s  %-30s  %16s  %16s  %12s  %14s\n", "station_x1 [m]",
                "nodes x1 [m] (weights)", "rupture_time [s]", "peak_rate [m/s]", "peak_time [s]",
                "final_slip [m]");
  out << line;
  for (std::size_t s = 0; s < r.x1.size(); ++s) {
    char nodes[80];
    if (r.node_weight[2 * s + 1] == 0.0)
      std::snprintf(nodes, sizeof nodes, "%.9g (on the node)", r.node_x1[2 * s]);
    else
      std::snprintf(nodes, sizeof nodes, "%.9g, %.9g (%.3g, %.3g)", r.node_x1[2 * s],
                    r.node_x1[2 * s + 1], r.node_weight[2 * s], r.node_weight[2 * s + 1]);
    const StationSummary summary = summarize_station(r, s, threshold);
    const double rupture_time = own ? r.rupture_time[s] : summary.rupture_time;
    std::snprintf(line, sizeof line, "%16.9g  %-30s  %16.9g  %16.6g  %12.6g  %14.6g\n", r.x1[s],
                  nodes, rupture_time, summary.peak_slip_rate, summary.peak_time,
                  summary.final_slip);
    out << line;
  }
}

struct StationsOptions {
  std::string result_path;
  std::string csv; // "" = the rupture times; "-" = the CSV on stdout
  double threshold = std::numeric_limits<double>::quiet_NaN(); // NaN: the run's
};

int show_stations(const StationsOptions& options);

} // namespace

Command add_stations_command(CLI::App& slipfront) {
  auto options = std::make_shared<StationsOptions>();
  CLI::App* command = add_command(
      slipfront, "stations",
      "The on-fault stations of a result file (the job's \"stations\"; docs/hdf5-layout.md): "
      "each station's x1, the nodes it is read from, its rupture time, peak slip rate and its "
      "time, and final slip; or, with --csv, "
      "every recorded step as CSV in the long format (station_x1, time, slip, slip_rate, "
      "shear_traction, normal_traction; units in the header comments).",
      "exit codes: 0 success, 1 the file cannot be read or has no stations, 2 invalid command "
      "line.");
  command
      ->add_option("RESULT.h5", options->result_path,
                   "a result file of slipfront run or the server")
      ->required();
  command
      ->add_option("--threshold", options->threshold,
                   "the rupture times at this slip rate [m/s] instead of the job's "
                   "stations.rupture_threshold (from the series of every step)")
      ->check(CLI::PositiveNumber)
      ->type_name("M/S");
  command
      ->add_option("--csv", options->csv,
                   "write every recorded step as CSV to FILE (\"-\": standard output)")
      ->type_name("FILE");
  return {command, [options] { return show_stations(*options); }};
}

namespace {

int show_stations(const StationsOptions& options) {
  const std::string& csv = options.csv;
  const std::string& file = options.result_path;
  std::string why;
  const std::optional<StationRecords> stations = api::read_stations(file, why);
  if (!stations) {
    std::cerr << "slipfront stations: " << file << ": " << why << '\n';
    return exit_code::failure;
  }
  if (stations->empty()) {
    std::cerr << "slipfront stations: " << file
              << " has no stations (its job lists none: \"stations\": {\"x1\": [...]})\n";
    return exit_code::failure;
  }
  if (csv.empty()) {
    print_stations(std::cout, *stations, options.threshold);
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

} // namespace

} // namespace slipfront::app
