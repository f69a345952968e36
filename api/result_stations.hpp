// The /stations group of the result file (docs/hdf5-layout.md "/stations"; names in
// api/result_layout.hpp), read back for the CSV export (api/station_csv.hpp), the CLI and the
// server. Its writer, which needs the HDF5 headers: api/result_stations_writer.hpp.
#pragma once

#include "solver/run/records.hpp"

#include <optional>
#include <string>

namespace slipfront::api {

// The stations of the result file at `path`: empty records when the file has no /stations
// group (a job without stations); nullopt, with the reason in `why`, when the file cannot be
// read as a result file.
std::optional<StationRecords> read_stations(const std::string& path, std::string& why);

} // namespace slipfront::api
