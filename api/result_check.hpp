// Whether a file is a result file of the layout docs/hdf5-layout.md describes, checked with the
// HDF5 API (names: api/result_layout.hpp): what the server asks of a result file it did not
// write (an imported run's) before it stores it, so that it never serves a file its readers
// cannot read.
#pragma once

#include <optional>
#include <string>

namespace slipfront::api {

// Opens `path` and checks: the groups /interface, /front, /probes and /energy (and /stations
// when `stations`), each of their datasets with its type (float64; int8 for the state) and
// rank; the 2-D /interface fields [n_samples, n_nodes] against /interface/time and
// /interface/x1; the /front datasets against /front/x1; the probe and energy records against
// their time axis; the /stations series against its time and x1; and the root attributes.
// Reads no field's values, only the shapes and the root attribute `spec`. Returns that
// attribute (the job's canonical JSON text), or nullopt with the reason in `why`.
std::optional<std::string> check_result_layout(const std::string& path, bool stations,
                                               std::string& why);

} // namespace slipfront::api
