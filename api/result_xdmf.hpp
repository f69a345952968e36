// The XDMF sidecar of a result file (docs/hdf5-layout.md, "Opening results in ParaView and
// xarray"): an XDMF 3 document that describes the interface fields as one 2-D rectilinear
// grid over (time, x1) — the x1–t plane — whose arrays are the HDF5 datasets themselves.
// ParaView and VisIt open it with their XDMF readers.
#pragma once

#include <string>

namespace slipfront::api {

// The XDMF text for the result file at `h5_path`; the data items refer to the HDF5 file
// as `h5_reference` (the file name as seen from the XDMF file, e.g. "out.h5"). Reads the
// dataset shapes from the file; throws std::runtime_error naming what is missing.
std::string result_xdmf(const std::string& h5_path, const std::string& h5_reference);

// Writes result_xdmf(h5_path, file name of h5_path) to `xdmf_path` (via a temporary file).
void write_result_xdmf(const std::string& h5_path, const std::string& xdmf_path);

} // namespace slipfront::api
