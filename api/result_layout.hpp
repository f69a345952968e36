// The names of the HDF5 result file's groups and datasets (docs/hdf5-layout.md), defined
// once: the writer (api/result_file.cpp), the XDMF sidecar (api/result_xdmf.cpp) and the
// reader (api/result_reader.cpp) all spell them from here. Changing one changes the layout,
// which is part of the API.
#pragma once

#include <array>
#include <string>

namespace slipfront::api::layout {

// Groups under the root.
inline constexpr const char* interface_group = "interface";
inline constexpr const char* front_group = "front";
inline constexpr const char* probes_group = "probes";
inline constexpr const char* energy_group = "energy";
inline constexpr const char* stations_group = "stations"; // only when the job has stations

// Datasets of /interface: the coordinates, then the 2-D [n_samples, n_nodes] fields.
inline constexpr const char* x1 = "x1";
inline constexpr const char* time = "time";

struct InterfaceField {
  const char* name;
  const char* units;
  const char* xdmf_number_type; // XDMF NumberType of its values
  int precision;                // bytes per value
};

// The float64 fields, in the order of InterfaceSample's members.
inline constexpr std::array<InterfaceField, 5> float_fields = {{
    {"slip_velocity", "m/s", "Float", 8},
    {"slip", "m", "Float", 8},
    {"shear_traction", "Pa", "Float", 8},
    {"contact_pressure", "Pa", "Float", 8},
    {"strength", "Pa", "Float", 8},
}};
// The int8 contact state (0 = stick, 1 = slip, 2 = open).
inline constexpr InterfaceField state_field = {"state", "1", "Char", 1};
// Every 2-D field of /interface: the float64 ones, then the state.
inline constexpr std::array<InterfaceField, float_fields.size() + 1> all_fields = {
    {float_fields[0], float_fields[1], float_fields[2], float_fields[3], float_fields[4],
     state_field}};

// Datasets of /front.
inline constexpr const char* front_arrival_time = "arrival_time";
inline constexpr const char* front_rupture_speed = "rupture_speed";

// Datasets and attributes of /probes.
inline constexpr const char* probe_slip_velocity_arrival = "slip_velocity_arrival";
inline constexpr const char* probe_slip_velocity_spectrum = "slip_velocity_spectrum";
inline constexpr const char* probe_strength_spectrum = "strength_spectrum";
inline constexpr const char* probe_arrival_x1 = "arrival_x1";   // attribute
inline constexpr const char* probe_spectrum_x1 = "spectrum_x1"; // attribute

// Datasets and attributes of /stations (besides x1 [n] and time [m]): the 2-D [m, n] series in
// the order of StationRecords' members, then the per-station data.
struct StationField {
  const char* name;
  const char* units;
};
inline constexpr std::array<StationField, 4> station_fields = {{
    {"slip_rate", "m/s"},
    {"slip", "m"},
    {"shear_traction", "Pa"},
    {"normal_traction", "Pa"},
}};
inline constexpr const char* station_node_x1 = "node_x1";                     // [n, 2]
inline constexpr const char* station_node_weight = "node_weight";             // [n, 2]
inline constexpr const char* station_rupture_time = "rupture_time";           // [n]
inline constexpr const char* station_rupture_threshold = "rupture_threshold"; // attribute

// Datasets of /energy.
inline constexpr const char* energy_kinetic = "kinetic";
inline constexpr const char* energy_strain = "strain";
inline constexpr const char* energy_external_work = "external_work";
inline constexpr const char* energy_dissipated = "dissipated";

// Root attributes (variable-length UTF-8 strings).
inline constexpr const char* spec_attribute = "spec"; // the job's canonical JSON text
inline constexpr const char* spec_sha256_attribute = "spec_sha256";
inline constexpr const char* metrics_attribute = "metrics";
inline constexpr const char* code_version_attribute = "code_version";
inline constexpr const char* method_attribute = "method";
inline constexpr const char* method_description_attribute = "method_description";
inline constexpr const char* created_attribute = "created";
// Where each number with a unit came from, and the job's warnings (JSON arrays; files written
// before they existed lack them, so they are not required).
inline constexpr const char* provenance_attribute = "provenance";
inline constexpr const char* job_warnings_attribute = "job_warnings";
inline constexpr std::array<const char*, 7> root_attributes = {
    spec_attribute,   spec_sha256_attribute,        metrics_attribute, code_version_attribute,
    method_attribute, method_description_attribute, created_attribute};

// "/group/name": the absolute path of a dataset.
inline std::string path(const char* group, const char* name) {
  std::string p = "/";
  p += group;
  p += '/';
  p += name;
  return p;
}

} // namespace slipfront::api::layout
