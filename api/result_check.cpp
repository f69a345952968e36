#include "api/result_check.hpp"

#include "api/hdf5_objects.hpp"
#include "api/result_layout.hpp"

#include <stdexcept>
#include <string_view>
#include <vector>

namespace slipfront::api {

namespace {

using hdf5::Handle;

// The first layout fault found: thrown inside the check, caught at its end.
struct LayoutFault : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Kind { float64, int8 };

Handle open_group(hid_t file, const char* name) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0 || H5Oexists_by_name(file, name, H5P_DEFAULT) <= 0)
    throw LayoutFault(std::string("no group /") + name);
  Handle group(H5Gopen2(file, name, H5P_DEFAULT));
  if (!group.valid()) throw LayoutFault(std::string("/") + name + " is not a group");
  return group;
}

// The dimensions of /group/name, a dataset of `rank` dimensions holding `kind` values.
std::vector<hsize_t> shape(hid_t group, const char* group_name, const char* name, int rank,
                           Kind kind = Kind::float64) {
  const std::string path = layout::path(group_name, name);
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0 || H5Oexists_by_name(group, name, H5P_DEFAULT) <= 0)
    throw LayoutFault("no dataset " + path);
  Handle set(H5Dopen2(group, name, H5P_DEFAULT));
  if (!set.valid()) throw LayoutFault(path + " is not a dataset");
  Handle type(H5Dget_type(set.get()));
  const bool float64 = H5Tget_class(type.get()) == H5T_FLOAT && H5Tget_size(type.get()) == 8;
  const bool int8 = H5Tget_class(type.get()) == H5T_INTEGER && H5Tget_size(type.get()) == 1;
  if (kind == Kind::float64 ? !float64 : !int8)
    throw LayoutFault(path + " is not of " + (kind == Kind::float64 ? "float64" : "int8"));
  Handle space(H5Dget_space(set.get()));
  if (!space.valid() || H5Sget_simple_extent_ndims(space.get()) != rank)
    throw LayoutFault(path + " is not a " + std::to_string(rank) + "-D dataset");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank), 0);
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

void expect(bool holds, const std::string& fault) {
  if (!holds) throw LayoutFault(fault);
}

// A root attribute holding a string, read whole (at most `max_bytes`).
std::string string_attribute(hid_t file, const char* name, std::size_t max_bytes) {
  if (H5Aexists(file, name) <= 0) throw LayoutFault(std::string("no root attribute ") + name);
  Handle attribute(H5Aopen(file, name, H5P_DEFAULT));
  Handle type(attribute.valid() ? H5Aget_type(attribute.get()) : H5I_INVALID_HID);
  Handle space(attribute.valid() ? H5Aget_space(attribute.get()) : H5I_INVALID_HID);
  if (!type.valid() || !space.valid() || H5Tget_class(type.get()) != H5T_STRING ||
      H5Tis_variable_str(type.get()) <= 0 || H5Sget_simple_extent_npoints(space.get()) != 1)
    throw LayoutFault(std::string("root attribute ") + name + " is not a string");
  Handle memory(H5Tcopy(H5T_C_S1));
  H5Tset_size(memory.get(), H5T_VARIABLE);
  H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
  char* text = nullptr;
  if (H5Aread(attribute.get(), memory.get(), &text) < 0 || text == nullptr)
    throw LayoutFault(std::string("root attribute ") + name + " cannot be read");
  std::string value(text);
  H5free_memory(text);
  if (value.size() > max_bytes)
    throw LayoutFault(std::string("root attribute ") + name + " is longer than " +
                      std::to_string(max_bytes) + " bytes");
  return value;
}

std::string check_layout(hid_t file, bool stations) {
  using namespace layout;
  {
    Handle g = open_group(file, interface_group);
    const hsize_t nodes = shape(g.get(), interface_group, x1, 1)[0];
    const hsize_t samples = shape(g.get(), interface_group, time, 1)[0];
    for (const auto& field : all_fields) {
      const auto dims = shape(g.get(), interface_group, field.name, 2,
                              field.precision == 1 ? Kind::int8 : Kind::float64);
      expect(dims[0] == samples && dims[1] == nodes,
             path(interface_group, field.name) + " is not [n_samples, n_nodes] of " +
                 path(interface_group, time) + " and " + path(interface_group, x1));
    }
  }
  // The 1-D records of a group: each as long as its axis.
  auto records = [&](const char* group, const char* axis, std::vector<const char*> names) {
    Handle g = open_group(file, group);
    const hsize_t n = shape(g.get(), group, axis, 1)[0];
    for (const char* name : names)
      expect(shape(g.get(), group, name, 1)[0] == n,
             path(group, name) + " is not as long as " + path(group, axis));
  };
  records(front_group, x1, {front_arrival_time, front_rupture_speed});
  records(probes_group, time,
          {probe_slip_velocity_arrival, probe_slip_velocity_spectrum, probe_strength_spectrum});
  records(energy_group, time,
          {energy_kinetic, energy_strain, energy_external_work, energy_dissipated});
  if (stations) {
    Handle g = open_group(file, stations_group);
    const hsize_t n = shape(g.get(), stations_group, x1, 1)[0];
    const hsize_t steps = shape(g.get(), stations_group, time, 1)[0];
    for (const auto& field : station_fields) {
      const auto dims = shape(g.get(), stations_group, field.name, 2);
      expect(dims[0] == steps && dims[1] == n,
             path(stations_group, field.name) + " is not [n_steps, n_stations]");
    }
    expect(shape(g.get(), stations_group, station_rupture_time, 1)[0] == n,
           path(stations_group, station_rupture_time) + " is not [n_stations]");
    for (const char* name : {station_node_x1, station_node_weight}) {
      const auto dims = shape(g.get(), stations_group, name, 2);
      expect(dims[0] == n && dims[1] == 2, path(stations_group, name) + " is not [n_stations, 2]");
    }
  }
  constexpr std::size_t max_attribute_bytes = 16 << 20;
  std::string spec;
  for (const char* name : root_attributes) {
    std::string value = string_attribute(file, name, max_attribute_bytes);
    if (std::string_view(name) == spec_attribute) spec = std::move(value);
  }
  return spec;
}

} // namespace

std::optional<std::string> check_result_layout(const std::string& path, bool stations,
                                               std::string& why) {
  if (!hdf5::readable_file(path, why)) return std::nullopt;
  hdf5::QuietErrors quiet; // the faults are reported through `why`
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    why = "not an HDF5 file";
    return std::nullopt;
  }
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) {
    why = "cannot be opened as HDF5";
    return std::nullopt;
  }
  try {
    return check_layout(file.get(), stations);
  } catch (const LayoutFault& fault) {
    why = std::string("not a result file of docs/hdf5-layout.md: ") + fault.what();
    return std::nullopt;
  }
}

} // namespace slipfront::api
