// The record of one interface point that a length fit reads (docs/length-fit.md "The
// record"): time [s], slip rate [m/s], contact pressure [Pa, > 0 in compression] and
// frictional stress [Pa], sample by sample, with where each sample came from (the source's
// column names and, for a text record, its line) so that an error can name both. Its bounds.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// The four columns of a record, in this order everywhere (CSV header names, JSON members).
enum class RecordColumn { time, slip_rate, contact_pressure, frictional_stress };
inline constexpr std::size_t record_column_count = 4;
const char* column_name(RecordColumn column); // "time", "slip_rate", ...

// The size a record may have (docs/length-fit.md "Bounds"): the text or JSON of a record, the
// data rows of a CSV (all stations of a stations CSV), and the samples of the point fitted.
inline constexpr std::size_t max_record_bytes = std::size_t{64} << 20;
inline constexpr std::size_t max_record_rows = 1'000'000;
inline constexpr std::size_t max_record_points = 200'000;
// Every value of a record lies within +-1e30 (in its SI unit): sums of squares of a record's
// stresses stay far from overflow.
inline constexpr double max_record_magnitude = 1e30;
// The fewest samples a record must have, and the fewest of them where the interface slips.
inline constexpr std::size_t min_record_points = 32;
inline constexpr std::size_t min_slipping_points = 10;

// Where a record came from: the names its source gives the four columns (a stations CSV
// calls the stresses shear_traction and normal_traction), and for a CSV the line of every
// sample (1-based, comment and blank lines counted: as an editor numbers them).
struct RecordSource {
  enum class Kind { csv, stations_csv, json };
  Kind kind = Kind::json;
  std::array<std::string, record_column_count> column_names{"time", "slip_rate", "contact_pressure",
                                                            "frictional_stress"};
  std::vector<long> line;           // CSV only
  std::optional<double> station_x1; // the station read from a stations CSV
  std::size_t stations_in_file = 0; // stations CSV: how many it holds
};

struct InterfaceRecord {
  std::vector<double> time;              // [s], strictly increasing
  std::vector<double> slip_rate;         // [m/s], its sign is ignored (|V|)
  std::vector<double> contact_pressure;  // [Pa], > 0 in compression; < 0 counts as 0 (eq. 1)
  std::vector<double> frictional_stress; // [Pa], its sign is ignored
  RecordSource source;

  std::size_t size() const { return time.size(); }
  const std::vector<double>& column(RecordColumn c) const;
  std::vector<double>& column(RecordColumn c);
};

// Something wrong with a record, located as precisely as its source allows: the column as
// the source names it ("" when the error is about no one column), the sample (0-based; -1 when
// about no one sample) and, for a CSV, its line (0 when about no one line).
struct RecordError {
  std::string column;
  long index = -1;
  long line = 0;
  std::string reason;
};

// "line 21, column \"slip_rate\": <reason>" for a CSV; for JSON,
// "/slip_rate/16: <reason>" relative to the record.
std::string describe(const RecordError& error);

// The error about sample `index` of `column`, located through the record's source.
RecordError error_at(const InterfaceRecord& record, RecordColumn column, std::size_t index,
                     std::string reason);

} // namespace slipfront::api
