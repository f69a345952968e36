// `slipfront fit-length RECORD [--json] [--fit-v-star] [--v-star V] [--mu MU] [--station X1]
// [--slip-threshold V]`: the experimentalist's procedure of paper Sec. 6 on one record
// (docs/length-fit.md): the fitted L_m with its 95 % interval, f_m, the contact pressure's
// power above f_m, and whether L_m is the interface's physical length or the event only bounds
// it (by its own critical length, at least L_m).
#include "app/commands.hpp"
#include "app/options.hpp"

#include "api/length_fit/length_fit_json.hpp"
#include "api/length_fit/length_fit_request.hpp"
#include "api/length_fit/record_reader.hpp"
#include "api/number_text.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>

namespace slipfront::app {

namespace {

constexpr const char* me = "slipfront fit-length: ";

// The numeric flags and the request field each sets.
struct NumberFlag {
  const char* flag;
  const char* option;
  std::optional<double> api::LengthFitOptions::*target;
};
constexpr NumberFlag number_flags[] = {
    {"--v-star", "v_star", &api::LengthFitOptions::v_star},
    {"--mu", "mu", &api::LengthFitOptions::mu},
    {"--station", "station_x1", &api::LengthFitOptions::station_x1},
    {"--slip-threshold", "slip_threshold", &api::LengthFitOptions::slip_threshold},
};

std::optional<double> parse_number(const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty()) return std::nullopt;
  return value;
}

// The file's text, or nullopt with the reason (exit 1: cannot read; 2: too large).
std::optional<std::string> read_text(const std::string& path, std::string& why, int& code) {
  std::ifstream file;
  std::istream* in = &std::cin;
  if (path != "-") {
    file.open(path, std::ios::binary);
    if (!file) {
      why = "cannot open " + path + ": " + std::strerror(errno);
      code = exit_code::failure;
      return std::nullopt;
    }
    in = &file;
  }
  std::string text(api::max_record_bytes + 1, '\0');
  in->read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in->gcount()));
  if (in->bad()) {
    why = "cannot read " + path;
    code = exit_code::failure;
    return std::nullopt;
  }
  if (text.size() > api::max_record_bytes) {
    why = path + ": the record is larger than the limit of " +
          std::to_string(api::max_record_bytes) + " bytes (docs/length-fit.md \"Bounds\")";
    code = exit_code::bad_input;
    return std::nullopt;
  }
  return text;
}

std::string interval(double lo, double hi) {
  std::string text = "["; // appended piece by piece: "literal" + a temporary trips GCC 12
  text.append(api::number_text(lo, 3)).append(", ");
  return text.append(std::isfinite(hi) ? api::number_text(hi, 3) : "inf").append("]");
}

void print_report(std::ostream& out, const api::InterfaceRecord& record, const api::LengthFit& r) {
  using api::number_text;
  const api::LawFit& f = r.fit;
  const api::RecordSource& s = record.source;
  out << "record: " << record.size() << " samples over "
      << number_text(record.time.back() - record.time.front(), 4) << " s";
  if (s.station_x1) out << " (station x1 = " << number_text(*s.station_x1, 9) << " m)";
  out << "; " << r.slipping.count << " slip (|V| >= " << number_text(r.slipping.threshold, 3)
      << " m/s), peak |V| = " << number_text(r.peak_slip_rate, 3) << " m/s\n";
  out << "fit of the simplified Prakash-Clifton law (paper eq. 1) where it slips:\n"
      << "  L_m = " << number_text(f.law.L, 4) << " m, 95 % interval "
      << interval(f.L_low, f.L_high) << " m" << (f.at_scan_limit ? " (at the scan's limit)" : "")
      << '\n'
      << "  V*  = " << number_text(f.law.v_star, 4) << " m/s"
      << (f.v_star_fitted ? ", 95 % interval " + interval(f.v_star_low, f.v_star_high) + " m/s"
                          : " (given)")
      << '\n'
      << "  mu  = " << number_text(f.law.mu, 6)
      << (f.mu_fitted ? " +- " + number_text(f.mu_standard_error, 2) : " (given)") << '\n'
      << "  rms misfit " << number_text(f.rms_misfit, 3) << " Pa, correlated over "
      << number_text(f.misfit_correlation_time, 3)
      << " samples: " << number_text(f.effective_samples, 3) << " independent of "
      << f.fitted_samples << '\n';
  out << "measured critical frequency f_m = " << number_text(r.critical_frequency, 4)
      << " Hz (L_c(f_m) = L_m: A/A0 = " << critical_attenuation_ratio
      << " at |V| = " << number_text(r.peak_slip_rate, 3) << " m/s)\n";
  out << "contact pressure spectrum: " << number_text(100 * spectral_power_fraction, 3)
      << " % of the power below " << number_text(r.spectrum.frequency_99, 4) << " Hz; "
      << number_text(100 * r.verdict.power_above_f_m, 3) << " % above f_m\n";
  out << "verdict: " << r.verdict.text << '\n' << "  (" << r.verdict.reason << ")\n";
  if (!r.verdict.rich_enough)
    out << "  the physical length is at most " << number_text(r.verdict.upper_bound, 3) << " m\n";
}

} // namespace

namespace {

struct FitLengthOptions {
  std::string record_path;
  bool json = false;
  api::LengthFitOptions fit;
};

// A number flag checked against the range the API's field of the same name takes
// (api::option_range), so that the CLI and POST /api/v1/length-fits refuse the same values.
void add_number_flag(CLI::App& command, const NumberFlag& flag, api::LengthFitOptions& options,
                     const std::string& value_name, const std::string& help) {
  command
      .add_option_function<std::string>(
          flag.flag,
          [flag, &options](const std::string& text) {
            const api::Interval& range = api::option_range(flag.option);
            const std::optional<double> value = parse_number(text);
            if (!value || !std::isfinite(*value) || !range.contains(*value))
              throw CLI::ValidationError(std::string(flag.flag) + ": needs a finite number" +
                                         (range.describe().empty() ? "" : " " + range.describe()) +
                                         ", got \"" + text + "\"");
            options.*(flag.target) = value;
          },
          help)
      ->type_name(value_name);
}

int fit_record(const FitLengthOptions& options);

} // namespace

Command add_fit_length_command(CLI::App& slipfront) {
  auto options = std::make_shared<FitLengthOptions>();
  CLI::App* command = add_command(
      slipfront, "fit-length",
      "The experimentalist's procedure of the paper (Sec. 6) on the record of one interface "
      "point: fit the simplified Prakash-Clifton law (eq. 1) to its frictional stress where it "
      "slips (the measured length L_m, 95 % interval), the measured critical frequency f_m "
      "(L_c(f_m) = L_m by A/A0 = 0.98), the contact pressure's power above f_m, and the "
      "verdict: L_m is the interface's physical length, or the event only bounds it. "
      "docs/length-fit.md.",
      "exit codes: 0 success, 1 the file cannot be read, 2 a bad record or command line (each "
      "error with its line, row and column).");
  command
      ->add_option("RECORD", options->record_path,
                   "CSV with a header naming time [s], slip_rate [m/s], contact_pressure [Pa, > 0 "
                   "in compression], frictional_stress [Pa]; the stations CSV of `slipfront "
                   "stations --csv` as it is; or JSON {\"time\": [...], \"slip_rate\": [...], "
                   "...}. \"-\" reads standard input. At most 64 MiB, 1000000 data rows and "
                   "200000 samples of the point.")
      ->required();
  command->add_flag("--json", options->json,
                    "the whole answer as JSON (what POST /api/v1/length-fits answers)");
  command->add_flag("--fit-v-star", options->fit.fit_v_star, "fit V* too (else V* is given)");
  add_number_flag(*command, number_flags[0], options->fit, "V",
                  "V* [m/s] (the start of its fit with --fit-v-star; default 1e-4, the paper's)");
  add_number_flag(*command, number_flags[1], options->fit, "MU",
                  "the friction coefficient (default: fitted)");
  add_number_flag(*command, number_flags[2], options->fit, "X1",
                  "the station of a stations CSV that holds several");
  add_number_flag(*command, number_flags[3], options->fit, "V",
                  "|V| [m/s] from which a sample slips (default 1 % of the peak |V|)");
  return {command, [options] { return fit_record(*options); }};
}

namespace {

int fit_record(const FitLengthOptions& cli) {
  const api::LengthFitOptions& options = cli.fit;
  const bool json = cli.json;
  const std::string& file = cli.record_path;
  std::string why;
  int code = exit_code::success;
  const std::optional<std::string> text = read_text(file, why, code);
  if (!text) {
    std::cerr << me << why << '\n';
    return code;
  }
  const auto report = [&](const std::vector<api::RecordError>& errors) {
    for (const api::RecordError& e : errors) {
      if (e.column == "station_x1" && e.line == 0)
        std::cerr << me << "--station: " << e.reason << '\n';
      else
        std::cerr << me << file << ": " << api::describe(e) << '\n';
    }
    return exit_code::bad_input;
  };
  const api::RecordRead read = api::read_record_text(*text, options.station_x1);
  if (!read.record) return report(read.errors);
  const api::LengthFitOutcome outcome = api::fit_length(*read.record, options);
  if (!outcome.result) return report(outcome.errors);
  if (json)
    std::cout << api::length_fit_json(*read.record, *outcome.result).dump() << '\n';
  else
    print_report(std::cout, *read.record, *outcome.result);
  return std::cout ? exit_code::success : exit_code::failure;
}

} // namespace

} // namespace slipfront::app
