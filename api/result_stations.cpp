#include "api/result_stations.hpp"

#include "api/hdf5_objects.hpp"
#include "api/result_layout.hpp"
#include "api/result_stations_writer.hpp"

#include <array>

namespace slipfront::api {

namespace {

// The 2-D series of StationRecords, in the order of layout::station_fields.
constexpr std::array<std::vector<double> StationRecords::*, layout::station_fields.size()>
    station_series = {&StationRecords::slip_rate, &StationRecords::slip,
                      &StationRecords::shear_traction, &StationRecords::normal_traction};

constexpr const char* rupture_rule =
    "first time |slip_rate| > rupture_threshold, interpolated linearly in time between the two "
    "steps around the crossing (the first step's time if it already exceeds); NaN if never";
constexpr const char* interpolation_rule =
    "value = node_weight[s, 0] f(node_x1[s, 0]) + node_weight[s, 1] f(node_x1[s, 1]): linear "
    "between the two interface nodes around x1[s] (on a node: that node, weights 1 and 0)";

// /stations/time and /stations/x1 become the coordinates of the series (dimension 0: time,
// 1: station) and x1 that of the per-station datasets.
void attach_station_scales(hid_t group) {
  using layout::path;
  const char* g = layout::stations_group;
  hdf5::Handle x1 = hdf5::open_dataset(group, layout::x1);
  hdf5::Handle time = hdf5::open_dataset(group, layout::time);
  hdf5::make_scale(x1.get(), layout::x1);
  hdf5::make_scale(time.get(), layout::time);
  auto attach = [&](const char* name, hid_t scale, unsigned dim, const char* scale_name) {
    hdf5::Handle dataset = hdf5::open_dataset(group, name);
    hdf5::attach_scale(dataset.get(), scale, dim, path(g, scale_name) + " to " + path(g, name));
  };
  for (const auto& field : layout::station_fields) {
    attach(field.name, time.get(), 0, layout::time);
    attach(field.name, x1.get(), 1, layout::x1);
  }
  for (const char* name :
       {layout::station_rupture_time, layout::station_node_x1, layout::station_node_weight})
    attach(name, x1.get(), 0, layout::x1);
}

} // namespace

void write_stations(hid_t root, const StationRecords& r) {
  if (r.empty()) return;
  const hsize_t n = r.x1.size(), m = r.time.size();
  hdf5::Handle group = hdf5::create_group(root, layout::stations_group);
  const hid_t g = group.get();
  hdf5::write_attribute(g, layout::station_rupture_threshold, r.rupture_threshold);
  hdf5::write_attribute(g, "rupture_threshold_units", "m/s");
  hdf5::write_attribute(g, "layout", "time-major: [n_steps, n_stations], every time step");
  hdf5::write_attribute(g, "interpolation", interpolation_rule);
  hdf5::write_vector(g, layout::x1, r.x1, "m");
  hdf5::write_vector(g, layout::time, r.time, "s");
  for (std::size_t f = 0; f < station_series.size(); ++f)
    hdf5::write_matrix(g, layout::station_fields[f].name, r.*station_series[f], m, n,
                       layout::station_fields[f].units);
  hdf5::Handle normal = hdf5::open_dataset(g, layout::station_fields[3].name);
  hdf5::write_attribute(normal.get(), "meaning", "-p: negative in compression");
  hdf5::write_vector(g, layout::station_rupture_time, r.rupture_time, "s");
  hdf5::Handle rupture = hdf5::open_dataset(g, layout::station_rupture_time);
  hdf5::write_attribute(rupture.get(), "meaning", rupture_rule);
  hdf5::write_matrix(g, layout::station_node_x1, r.node_x1, n, 2, "m");
  hdf5::write_matrix(g, layout::station_node_weight, r.node_weight, n, 2, "1");
  attach_station_scales(g);
}

std::optional<StationRecords> read_stations(const std::string& path, std::string& why) {
  if (!hdf5::readable_file(path, why)) return std::nullopt;
  hdf5::QuietErrors quiet; // errors are reported through `why`
  hdf5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) {
    why = "the result file cannot be opened as HDF5";
    return std::nullopt;
  }
  StationRecords r;
  if (H5Lexists(file.get(), layout::stations_group, H5P_DEFAULT) <= 0) return r;
  try {
    hdf5::Handle group(hdf5::check_id(H5Gopen2(file.get(), layout::stations_group, H5P_DEFAULT),
                                      "opening group /stations"));
    const hid_t g = group.get();
    std::vector<hsize_t> dims;
    r.rupture_threshold = hdf5::read_number_attribute(g, layout::station_rupture_threshold);
    r.x1 = hdf5::read_array(g, layout::x1, 1, dims);
    r.time = hdf5::read_array(g, layout::time, 1, dims);
    const std::vector<hsize_t> series_shape = {r.time.size(), r.x1.size()};
    for (std::size_t f = 0; f < station_series.size(); ++f) {
      r.*station_series[f] = hdf5::read_array(g, layout::station_fields[f].name, 2, dims);
      if (dims != series_shape)
        throw hdf5::Error(std::string("/stations/") + layout::station_fields[f].name +
                              " does not match /stations/time and /stations/x1",
                          0);
    }
    r.rupture_time = hdf5::read_array(g, layout::station_rupture_time, 1, dims);
    r.node_x1 = hdf5::read_array(g, layout::station_node_x1, 2, dims);
    r.node_weight = hdf5::read_array(g, layout::station_node_weight, 2, dims);
    if (r.rupture_time.size() != r.x1.size() || r.node_x1.size() != 2 * r.x1.size() ||
        r.node_weight.size() != 2 * r.x1.size())
      throw hdf5::Error("the per-station datasets of /stations do not match /stations/x1", 0);
  } catch (const hdf5::Error& e) {
    why = e.what();
    return std::nullopt;
  }
  return r;
}

} // namespace slipfront::api
