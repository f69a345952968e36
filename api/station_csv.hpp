// The stations of a run as CSV, in the long format that benchmark exchanges use (one row per
// station and time step; docs/hdf5-layout.md "Stations as CSV"): what `slipfront stations
// --csv`, GET /api/v1/jobs/{id}/stations.csv and the Python client serve.
#pragma once

#include "solver/run/records.hpp"

#include <ostream>

namespace slipfront::api {

// Comment lines ("# ...": the units, the threshold and each station's rupture time), the header
// station_x1,time,slip,slip_rate,shear_traction,normal_traction, then the rows station by
// station, each in time order. Numbers in their shortest exact decimal form; "\n" line ends.
void write_stations_csv(std::ostream& out, const StationRecords& stations);

} // namespace slipfront::api
