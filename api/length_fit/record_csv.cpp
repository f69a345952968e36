#include "api/length_fit/record_csv.hpp"

#include "api/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace slipfront::api {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_cells(std::string_view line) {
  std::vector<std::string_view> cells;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

// A cell for a message: at most 40 bytes, every byte outside printable ASCII as '?'.
std::string quoted(std::string_view cell) {
  std::string out = "\"";
  for (std::size_t i = 0; i < std::min<std::size_t>(cell.size(), 40); ++i)
    out += cell[i] >= 0x20 && cell[i] < 0x7f ? cell[i] : '?';
  return out + (cell.size() > 40 ? "...\"" : "\"");
}

// The columns a CSV names, by their index in its header.
struct Layout {
  RecordSource::Kind kind = RecordSource::Kind::csv;
  std::array<std::string, record_column_count> names;
  std::array<std::size_t, record_column_count> index{};
  std::optional<std::size_t> station; // the station_x1 column
  std::size_t cells = 0;
};

std::optional<std::size_t> find(const std::vector<std::string_view>& header,
                                std::string_view name) {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) return std::nullopt;
  return std::size_t(it - header.begin());
}

std::string header_error(const std::vector<std::string_view>& header, Layout& layout) {
  for (std::size_t i = 0; i < header.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (header[i] == header[j] && !header[i].empty())
        return "the header names column " + quoted(header[i]) + " twice";
  const bool stations = !find(header, "frictional_stress") && !find(header, "contact_pressure") &&
                        find(header, "shear_traction") && find(header, "normal_traction");
  layout.kind = stations ? RecordSource::Kind::stations_csv : RecordSource::Kind::csv;
  layout.names = {"time", "slip_rate", stations ? "normal_traction" : "contact_pressure",
                  stations ? "shear_traction" : "frictional_stress"};
  std::string missing;
  for (std::size_t c = 0; c < record_column_count; ++c) {
    const auto at = find(header, layout.names[c]);
    if (at)
      layout.index[c] = *at;
    else
      missing += (missing.empty() ? "\"" : ", \"") + layout.names[c] + "\"";
  }
  if (!missing.empty())
    return "the header has no column " + missing +
           " (a record names time, slip_rate, contact_pressure and frictional_stress; a "
           "stations CSV of `slipfront stations --csv` is read as it is)";
  layout.station = find(header, "station_x1");
  layout.cells = header.size();
  return "";
}

// The rows of the file, column by column, before a station is chosen.
struct Rows {
  std::vector<double> station;
  std::array<std::vector<double>, record_column_count> values;
  std::vector<long> line;
};

bool read_number(std::string_view cell, double& value) {
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  return ec == std::errc() && end == cell.data() + cell.size() && !cell.empty();
}

std::string station_list(const std::vector<double>& stations) {
  std::string text;
  for (std::size_t i = 0; i < stations.size() && i < 20; ++i)
    text += (i ? ", " : "") + number_text(stations[i], 9);
  return text + (stations.size() > 20 ? ", ..." : "");
}

bool same_station(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
}

// The rows of one station (all rows when the file has no station_x1 column).
RecordRead select_station(Rows& rows, const Layout& layout, std::optional<double> station_x1) {
  RecordRead out;
  InterfaceRecord record;
  record.source.kind = layout.kind;
  record.source.column_names = layout.names;
  std::vector<double> stations;
  for (double x : rows.station)
    if (std::none_of(stations.begin(), stations.end(), [&](double s) { return s == x; }))
      stations.push_back(x);
  std::optional<double> chosen;
  if (!layout.station) {
    if (station_x1) {
      out.errors.push_back(
          {"station_x1", -1, 0, "the record has no station_x1 column: leave the station out"});
      return out;
    }
  } else if (station_x1) {
    const auto it = std::find_if(stations.begin(), stations.end(),
                                 [&](double s) { return same_station(s, *station_x1); });
    if (it == stations.end()) {
      out.errors.push_back({"station_x1", -1, 0,
                            "no row is at station_x1 = " + number_text(*station_x1, 9) +
                                " (the record's stations: " + station_list(stations) + " m)"});
      return out;
    }
    chosen = *it;
  } else if (stations.size() > 1) {
    out.errors.push_back({"station_x1", -1, 0,
                          "the record holds " + std::to_string(stations.size()) +
                              " stations (x1 = " + station_list(stations) +
                              " m): choose one (station_x1)"});
    return out;
  } else if (!stations.empty()) {
    chosen = stations.front();
  }
  record.source.station_x1 = chosen;
  record.source.stations_in_file = stations.size();
  const bool negate_pressure = layout.kind == RecordSource::Kind::stations_csv;
  for (std::size_t r = 0; r < rows.line.size(); ++r) {
    if (chosen && rows.station[r] != *chosen) continue;
    if (record.size() == max_record_points) {
      out.errors.push_back({"", -1, rows.line[r],
                            "the point has more than " + std::to_string(max_record_points) +
                                " samples (docs/length-fit.md \"Bounds\")"});
      return out;
    }
    for (std::size_t c = 0; c < record_column_count; ++c) {
      double v = rows.values[c][r];
      // A stations CSV has the normal traction, < 0 in compression: p = 0 - it (0, not -0).
      if (negate_pressure && c == std::size_t(RecordColumn::contact_pressure)) v = 0.0 - v;
      record.column(RecordColumn(c)).push_back(v);
    }
    record.source.line.push_back(rows.line[r]);
  }
  out.record = std::move(record);
  return out;
}

} // namespace

std::optional<RecordError> size_error(std::string_view text) {
  if (text.size() <= max_record_bytes) return std::nullopt;
  return RecordError{"", -1, 0,
                     "the record is " + std::to_string(text.size()) +
                         " bytes, more than the limit of " + std::to_string(max_record_bytes) +
                         " (docs/length-fit.md \"Bounds\")"};
}

RecordRead read_record_csv(std::string_view text, std::optional<double> station_x1) {
  RecordRead out;
  if (auto too_large = size_error(text)) {
    out.errors.push_back(*too_large);
    return out;
  }
  Layout layout;
  bool have_header = false;
  Rows rows;
  long line_number = 0;
  std::size_t data_rows = 0;
  const auto fail = [&](long line, std::string column, std::string reason) {
    out.errors.push_back({std::move(column), -1, line, std::move(reason)});
    return out.errors.size() >= max_record_errors;
  };
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> cells = split_cells(line);
    if (!have_header) {
      have_header = true;
      const std::string why = header_error(cells, layout);
      if (!why.empty()) {
        fail(line_number, "", why);
        return out;
      }
      continue;
    }
    if (++data_rows > max_record_rows) {
      fail(line_number, "",
           "more than " + std::to_string(max_record_rows) +
               " data rows (docs/length-fit.md \"Bounds\")");
      return out;
    }
    if (cells.size() != layout.cells) {
      if (fail(line_number, "",
               "has " + std::to_string(cells.size()) + " cells, the header names " +
                   std::to_string(layout.cells) + " columns"))
        return out;
      continue;
    }
    bool row_ok = true;
    const auto read = [&](std::size_t at, const std::string& name, std::vector<double>& into) {
      double value = 0;
      if (!read_number(cells[at], value)) {
        row_ok = false;
        return !fail(line_number, name, "not a number: " + quoted(cells[at]));
      }
      if (!std::isfinite(value)) {
        row_ok = false;
        return !fail(line_number, name, "not a finite number: " + quoted(cells[at]));
      }
      into.push_back(value);
      return true;
    };
    if (layout.station && !read(*layout.station, "station_x1", rows.station)) return out;
    for (std::size_t c = 0; c < record_column_count; ++c)
      if (!read(layout.index[c], layout.names[c], rows.values[c])) return out;
    if (!row_ok) {
      // Keep the columns aligned: drop what this row added.
      if (layout.station) rows.station.resize(rows.line.size());
      for (auto& column : rows.values)
        column.resize(rows.line.size());
      continue;
    }
    rows.line.push_back(line_number);
  }
  if (!have_header) {
    fail(0, "",
         "the record is empty: no header line (time,slip_rate,contact_pressure,"
         "frictional_stress) and no data");
    return out;
  }
  if (!out.errors.empty()) return out;
  return select_station(rows, layout, station_x1);
}

} // namespace slipfront::api
