#include "api/result_reader.hpp"

#include "api/hdf5_objects.hpp"
#include "api/result_layout.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront::api {

namespace {

using hdf5::Handle;

// The group `name` of an open file; an invalid handle (and the reason) when it is missing.
Handle open_group(hid_t file, const char* name, const std::string& missing, std::string& why) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) {
    why = missing;
    return Handle();
  }
  Handle group(H5Gopen2(file, name, H5P_DEFAULT));
  if (!group.valid()) why = std::string("cannot open group /") + name;
  return group;
}

// The 1-D float64 dataset /group_name/name, whole.
bool read_1d(hid_t group, const char* group_name, const char* name, std::vector<double>& out,
             std::string& why) {
  const std::string path = layout::path(group_name, name);
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0) {
    why = "no dataset " + path;
    return false;
  }
  Handle set(H5Dopen2(group, name, H5P_DEFAULT));
  if (!set.valid()) {
    why = "cannot open " + path;
    return false;
  }
  Handle space(H5Dget_space(set.get()));
  if (!space.valid() || H5Sget_simple_extent_ndims(space.get()) != 1) {
    why = path + " is not a 1-D dataset";
    return false;
  }
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.get(), &n, nullptr);
  out.resize(n);
  if (n > 0 &&
      H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0) {
    why = "reading " + path + " failed";
    return false;
  }
  return true;
}

// [first, last] indices of the sorted `axis` within [lo, hi]; the nearest to the middle when
// none is.
std::pair<std::size_t, std::size_t>
index_range(const std::vector<double>& axis, std::optional<double> lo, std::optional<double> hi) {
  const double a = lo.value_or(-INFINITY), b = hi.value_or(INFINITY);
  auto first = std::lower_bound(axis.begin(), axis.end(), a) - axis.begin();
  auto end = std::upper_bound(axis.begin(), axis.end(), b) - axis.begin();
  if (first < end) return {static_cast<std::size_t>(first), static_cast<std::size_t>(end - 1)};
  double mid = std::isfinite(a) && std::isfinite(b) ? 0.5 * (a + b) : (std::isfinite(a) ? a : b);
  std::size_t best = 0;
  for (std::size_t i = 1; i < axis.size(); ++i)
    if (std::abs(axis[i] - mid) < std::abs(axis[best] - mid)) best = i;
  return {best, best};
}

std::size_t ceil_div(std::size_t a, std::size_t b) {
  return (a + b - 1) / b;
}

// Row and column strides that keep ceil(nr / rs) * ceil(nc / cs) within `budget`: one
// stride for both axes, unless an axis would fall below 1 point.
std::pair<std::size_t, std::size_t> strides(std::size_t nr, std::size_t nc, std::size_t budget) {
  std::size_t rs = 1, cs = 1;
  if (nr * nc <= budget) return {rs, cs};
  if (nr == 1) return {1, ceil_div(nc, budget)};
  if (nc == 1) return {ceil_div(nr, budget), 1};
  auto st = static_cast<std::size_t>(
      std::ceil(std::sqrt(static_cast<double>(nr) * nc / static_cast<double>(budget))));
  rs = cs = std::max<std::size_t>(1, st);
  while (ceil_div(nr, rs) * ceil_div(nc, cs) > budget) {
    if (ceil_div(nr, rs) >= ceil_div(nc, cs))
      ++rs;
    else
      ++cs;
  }
  return {rs, cs};
}

std::optional<FieldSlice> slice_of(hid_t file, const std::string& name, const SliceWindow& window,
                                   std::string& why) {
  const char* g = layout::interface_group;
  Handle group = open_group(file, g, "no group /interface in the result file", why);
  std::vector<double> x1, time;
  if (!group.valid() || !read_1d(group.get(), g, layout::x1, x1, why) ||
      !read_1d(group.get(), g, layout::time, time, why))
    return std::nullopt;
  const std::string path = layout::path(g, name.c_str());
  if (H5Lexists(group.get(), name.c_str(), H5P_DEFAULT) <= 0) {
    why = "no dataset " + path + " in the result file";
    return std::nullopt;
  }
  Handle set(H5Dopen2(group.get(), name.c_str(), H5P_DEFAULT));
  Handle space(set.valid() ? H5Dget_space(set.get()) : H5I_INVALID_HID);
  if (!space.valid() || H5Sget_simple_extent_ndims(space.get()) != 2) {
    why = path + " is not a 2-D dataset";
    return std::nullopt;
  }
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  if (dims[0] != time.size() || dims[1] != x1.size()) {
    why = path + " does not match " + layout::path(g, layout::time) + " and " +
          layout::path(g, layout::x1);
    return std::nullopt;
  }
  FieldSlice s;
  s.units = slice_field_units(name);
  s.source_rows = dims[0];
  s.source_columns = dims[1];
  if (dims[0] == 0 || dims[1] == 0) return s;
  auto [r0, r1] = index_range(time, window.t_min, window.t_max);
  auto [c0, c1] = index_range(x1, window.x1_min, window.x1_max);
  const std::size_t nr = r1 - r0 + 1, nc = c1 - c0 + 1;
  const auto [rs, cs] = strides(nr, nc, static_cast<std::size_t>(std::max(1L, window.max_points)));
  const hsize_t start[2] = {r0, c0};
  const hsize_t stride[2] = {rs, cs};
  const hsize_t count[2] = {ceil_div(nr, rs), ceil_div(nc, cs)};
  if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, stride, count, nullptr) < 0) {
    why = "selecting the window failed";
    return std::nullopt;
  }
  Handle memory(H5Screate_simple(2, count, nullptr));
  s.values.resize(count[0] * count[1]);
  if (H5Dread(set.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT,
              s.values.data()) < 0) {
    why = "reading " + path + " failed";
    return std::nullopt;
  }
  s.row_first = r0;
  s.row_stride = rs;
  s.column_first = c0;
  s.column_stride = cs;
  for (hsize_t k = 0; k < count[0]; ++k)
    s.time.push_back(time[r0 + k * rs]);
  for (hsize_t k = 0; k < count[1]; ++k)
    s.x1.push_back(x1[c0 + k * cs]);
  return s;
}

} // namespace

std::optional<ProbeRecord> read_probe_record(const std::string& path, std::string& why) {
  if (!hdf5::readable_file(path, why)) return std::nullopt;
  hdf5::QuietErrors quiet; // errors are reported through `why`
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) {
    why = "cannot open " + path + " as HDF5";
    return std::nullopt;
  }
  const char* g = layout::probes_group;
  Handle group = open_group(file.get(), g, "no group /probes in " + path, why);
  ProbeRecord r;
  if (!group.valid() || !read_1d(group.get(), g, layout::time, r.time, why) ||
      !read_1d(group.get(), g, layout::probe_slip_velocity_spectrum, r.slip_velocity, why))
    return std::nullopt;
  if (H5Aexists(group.get(), layout::probe_spectrum_x1) > 0) {
    Handle attr(H5Aopen(group.get(), layout::probe_spectrum_x1, H5P_DEFAULT));
    if (attr.valid()) H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &r.x1);
  }
  return r;
}

const std::vector<std::string>& slice_field_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& f : layout::all_fields)
      out.emplace_back(f.name);
    return out;
  }();
  return names;
}

std::string slice_field_units(const std::string& name) {
  for (const auto& f : layout::all_fields)
    if (name == f.name) return f.units;
  return "";
}

std::optional<FieldSlice> read_field_slice(const std::string& path, const std::string& name,
                                           const SliceWindow& window, std::string& why) {
  if (!hdf5::readable_file(path, why)) return std::nullopt;
  hdf5::QuietErrors quiet; // errors are reported through `why`
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) {
    why = "the result file cannot be opened as HDF5";
    return std::nullopt;
  }
  return slice_of(file.get(), name, window, why);
}

} // namespace slipfront::api
