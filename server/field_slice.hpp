// A window of one /interface field of a result file (docs/hdf5-layout.md), decimated to a
// point budget: what GET /api/v1/jobs/{id}/fields/{name} serves (docs/server.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

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
// nullopt with the reason in `why` when the file or dataset is missing or unreadable.
std::optional<FieldSlice> read_field_slice(const std::string& path, const std::string& name,
                                           const SliceWindow& window, std::string& why);

} // namespace slipfront::server
