#include "server/field_slice.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace slipfront::server {

namespace {

struct Id {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Id() {
    if (id >= 0) close(id);
  }
};

bool read_1d(hid_t group, const char* name, std::vector<double>& out, std::string& why) {
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0) {
    why = std::string("no dataset /interface/") + name;
    return false;
  }
  Id set{H5Dopen2(group, name, H5P_DEFAULT), H5Dclose};
  Id space{set.id >= 0 ? H5Dget_space(set.id) : -1, H5Sclose};
  if (space.id < 0 || H5Sget_simple_extent_ndims(space.id) != 1) {
    why = std::string("/interface/") + name + " is not a 1-D dataset";
    return false;
  }
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.id, &n, nullptr);
  out.resize(n);
  if (n > 0 && H5Dread(set.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0) {
    why = std::string("reading /interface/") + name + " failed";
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

} // namespace

const std::vector<std::string>& slice_field_names() {
  static const std::vector<std::string> names = {"slip_velocity",    "slip",     "shear_traction",
                                                 "contact_pressure", "strength", "state"};
  return names;
}

std::string slice_field_units(const std::string& name) {
  if (name == "slip_velocity") return "m/s";
  if (name == "slip") return "m";
  if (name == "shear_traction" || name == "contact_pressure" || name == "strength") return "Pa";
  if (name == "state") return "1";
  return "";
}

std::optional<FieldSlice> read_field_slice(const std::string& path, const std::string& name,
                                           const SliceWindow& window, std::string& why) {
  std::error_code ec;
  if (path.empty() || !std::filesystem::exists(path, ec)) {
    why = "no result file";
    return std::nullopt;
  }
  H5E_auto2_t old_func = nullptr;
  void* old_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &old_func, &old_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // errors are reported through `why`
  std::optional<FieldSlice> out;
  [&] {
    Id file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    if (file.id < 0) {
      why = "the result file cannot be opened as HDF5";
      return;
    }
    if (H5Lexists(file.id, "interface", H5P_DEFAULT) <= 0) {
      why = "no group /interface in the result file";
      return;
    }
    Id group{H5Gopen2(file.id, "interface", H5P_DEFAULT), H5Gclose};
    std::vector<double> x1, time;
    if (group.id < 0 || !read_1d(group.id, "x1", x1, why) || !read_1d(group.id, "time", time, why))
      return;
    if (H5Lexists(group.id, name.c_str(), H5P_DEFAULT) <= 0) {
      why = "no dataset /interface/" + name + " in the result file";
      return;
    }
    Id set{H5Dopen2(group.id, name.c_str(), H5P_DEFAULT), H5Dclose};
    Id space{set.id >= 0 ? H5Dget_space(set.id) : -1, H5Sclose};
    if (space.id < 0 || H5Sget_simple_extent_ndims(space.id) != 2) {
      why = "/interface/" + name + " is not a 2-D dataset";
      return;
    }
    hsize_t dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space.id, dims, nullptr);
    if (dims[0] != time.size() || dims[1] != x1.size()) {
      why = "/interface/" + name + " does not match /interface/time and /interface/x1";
      return;
    }
    FieldSlice s;
    s.units = slice_field_units(name);
    s.source_rows = dims[0];
    s.source_columns = dims[1];
    if (dims[0] == 0 || dims[1] == 0) {
      out = std::move(s);
      return;
    }
    auto [r0, r1] = index_range(time, window.t_min, window.t_max);
    auto [c0, c1] = index_range(x1, window.x1_min, window.x1_max);
    const std::size_t nr = r1 - r0 + 1, nc = c1 - c0 + 1;
    const auto budget = static_cast<std::size_t>(std::max(1L, window.max_points));
    std::size_t rs = 1, cs = 1;
    if (nr * nc > budget) {
      if (nr == 1)
        cs = ceil_div(nc, budget);
      else if (nc == 1)
        rs = ceil_div(nr, budget);
      else {
        // One stride for both axes, unless an axis would fall below 1 point.
        auto st = static_cast<std::size_t>(
            std::ceil(std::sqrt(static_cast<double>(nr) * nc / static_cast<double>(budget))));
        rs = cs = std::max<std::size_t>(1, st);
        while (ceil_div(nr, rs) * ceil_div(nc, cs) > budget) {
          if (ceil_div(nr, rs) >= ceil_div(nc, cs))
            ++rs;
          else
            ++cs;
        }
      }
    }
    const hsize_t start[2] = {r0, c0};
    const hsize_t stride[2] = {rs, cs};
    const hsize_t count[2] = {ceil_div(nr, rs), ceil_div(nc, cs)};
    if (H5Sselect_hyperslab(space.id, H5S_SELECT_SET, start, stride, count, nullptr) < 0) {
      why = "selecting the window failed";
      return;
    }
    Id memory{H5Screate_simple(2, count, nullptr), H5Sclose};
    s.values.resize(count[0] * count[1]);
    if (H5Dread(set.id, H5T_NATIVE_DOUBLE, memory.id, space.id, H5P_DEFAULT, s.values.data()) < 0) {
      why = "reading /interface/" + name + " failed";
      return;
    }
    s.row_first = r0;
    s.row_stride = rs;
    s.column_first = c0;
    s.column_stride = cs;
    for (hsize_t k = 0; k < count[0]; ++k)
      s.time.push_back(time[r0 + k * rs]);
    for (hsize_t k = 0; k < count[1]; ++k)
      s.x1.push_back(x1[c0 + k * cs]);
    out = std::move(s);
  }();
  H5Eset_auto2(H5E_DEFAULT, old_func, old_data);
  return out;
}

} // namespace slipfront::server
