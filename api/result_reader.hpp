// Reading a result file (layout: docs/hdf5-layout.md, names: api/result_layout.hpp), next to
// its writer (api/result_file.hpp): the slip-velocity record at the spectrum probe and
// windows of the /interface fields, decimated to a point budget (what the server's
// GET /jobs/{id}/fields/{name} and the study probe comparisons serve).
//
// Nothing here throws for a missing or malformed file: the functions return nullopt and put
// the reason in `why`, which the server passes on in its problem responses.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// --- The probe record --------------------------------------------------------------------

struct ProbeRecord {
  std::vector<double> time;
  std::vector<double> slip_velocity;
  double x1 = 0.0; // the node's x1 (attribute spectrum_x1 of /probes)
};

// /probes/time and /probes/slip_velocity_spectrum (default probe x1 = 6 m).
std::optional<ProbeRecord> read_probe_record(const std::string& path, std::string& why);

// --- Windows of the interface fields -----------------------------------------------------

// The fields that may be sliced: the 2-D datasets of /interface.
const std::vector<std::string>& slice_field_names();
std::string slice_field_units(const std::string& name); // "" for an unknown name

struct SliceWindow {
  std::optional<double> x1_min, x1_max, t_min, t_max; // unset: the whole axis
  long max_points = 200000;                           // budget for n_time * n_x1
};

struct FieldSlice {
  std::vector<double> x1;     // the x1 of each column kept, m
  std::vector<double> time;   // the time of each row kept, s
  std::vector<double> values; // row-major [time.size(), x1.size()], NaN kept as NaN
  std::size_t source_rows = 0, source_columns = 0; // the dataset's full shape
  std::size_t row_first = 0, row_stride = 1;       // rows kept: first + k * stride
  std::size_t column_first = 0, column_stride = 1; // columns kept: first + k * stride
  std::string units;
};

// Reads `name` from `path` within `window`. The nodes (samples) kept are those with x1 (t) in
// [min, max]; a window holding none keeps the one nearest its middle (so x1_min = x1_max
// picks the nearest node). The same stride along both axes where the budget allows
// (a single-column or single-row window spends the whole budget on the other axis).
std::optional<FieldSlice> read_field_slice(const std::string& path, const std::string& name,
                                           const SliceWindow& window, std::string& why);

} // namespace slipfront::api
