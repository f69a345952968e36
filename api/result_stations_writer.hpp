// Writing the /stations group of the result file (docs/hdf5-layout.md "/stations"), for the
// result file's writer (api/result_file.cpp); apart from api/result_stations.hpp so that the
// readers' users need no HDF5 headers.
#pragma once

#include "solver/run/records.hpp"

#include <hdf5.h>

namespace slipfront::api {

// Writes /stations under `root` (nothing for a job without stations). Throws hdf5::Error.
void write_stations(hid_t root, const StationRecords& stations);

} // namespace slipfront::api
