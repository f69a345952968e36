#include "server/probe_record.hpp"

#include <hdf5.h>

#include <filesystem>

namespace slipfront::server {

namespace {

// Closes an HDF5 identifier with the given function when it goes out of scope.
struct Id {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Id() {
    if (id >= 0) close(id);
  }
};

bool read_vector(hid_t group, const char* name, std::vector<double>& out, std::string& why) {
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0) {
    why = std::string("no dataset /probes/") + name;
    return false;
  }
  Id set{H5Dopen2(group, name, H5P_DEFAULT), H5Dclose};
  if (set.id < 0) {
    why = std::string("cannot open /probes/") + name;
    return false;
  }
  Id space{H5Dget_space(set.id), H5Sclose};
  if (space.id < 0 || H5Sget_simple_extent_ndims(space.id) != 1) {
    why = std::string("/probes/") + name + " is not 1-D";
    return false;
  }
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.id, &n, nullptr);
  out.resize(n);
  if (n > 0 && H5Dread(set.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0) {
    why = std::string("reading /probes/") + name + " failed";
    return false;
  }
  return true;
}

} // namespace

std::optional<ProbeRecord> read_probe_record(const std::string& path, std::string& why) {
  std::error_code ec;
  if (path.empty() || !std::filesystem::exists(path, ec)) {
    why = "no result file";
    return std::nullopt;
  }
  H5E_auto2_t old_func = nullptr;
  void* old_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &old_func, &old_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // errors are reported through `why`
  std::optional<ProbeRecord> out;
  {
    Id file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    if (file.id < 0) {
      why = "cannot open " + path + " as HDF5";
    } else if (H5Lexists(file.id, "probes", H5P_DEFAULT) <= 0) {
      why = "no group /probes in " + path;
    } else {
      Id group{H5Gopen2(file.id, "probes", H5P_DEFAULT), H5Gclose};
      ProbeRecord r;
      if (group.id >= 0 && read_vector(group.id, "time", r.time, why) &&
          read_vector(group.id, "slip_velocity_spectrum", r.slip_velocity, why)) {
        if (H5Aexists(group.id, "spectrum_x1") > 0) {
          Id attr{H5Aopen(group.id, "spectrum_x1", H5P_DEFAULT), H5Aclose};
          if (attr.id >= 0) H5Aread(attr.id, H5T_NATIVE_DOUBLE, &r.x1);
        }
        out = std::move(r);
      }
    }
  }
  H5Eset_auto2(H5E_DEFAULT, old_func, old_data);
  return out;
}

} // namespace slipfront::server
