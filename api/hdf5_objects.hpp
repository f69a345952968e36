// Small RAII layer over the HDF5 C API for the result file: owned handles, 1-D and 2-D datasets,
// attributes, and 2-D datasets that grow along their first (time) axis.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace slipfront::api::hdf5 {

// A failed HDF5 call: `what` failed, with the innermost cause HDF5 recorded (for a failed
// system call, its error message) and its errno (0 when HDF5 did not name one).
class Error : public std::runtime_error {
public:
  Error(const std::string& message, int system_errno)
      : std::runtime_error(message), system_errno_(system_errno) {}
  int system_errno() const { return system_errno_; }

private:
  int system_errno_;
};

// Throw Error naming `what` when an HDF5 call failed (negative status).
void check(herr_t status, const std::string& what);
hid_t check_id(hid_t id, const std::string& what);

// While alive, HDF5 prints nothing on a failure (the caller reports it); restores the
// previous error handler when destroyed.
class QuietErrors {
public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

private:
  H5E_auto2_t old_func_ = nullptr;
  void* old_data_ = nullptr;
};

// An owned identifier (file, group, dataset, dataspace, type or property list).
class Handle {
public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(other.id_) { other.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes the object (whatever its kind), ignoring a failure: for error paths.
  void reset();
  // Closes the object and throws Error naming `what` if HDF5 could not (a file or dataset
  // close flushes: it fails when the disk does). On failure the handle is kept: HDF5 still
  // holds the object, and reset() may release it later.
  void close(const std::string& what);

private:
  hid_t id_ = H5I_INVALID_HID;
};

Handle create_file(const std::string& path); // truncates

// Whether `path` can be read as a result file; if not, `why` says why as the system does
// ("No such file or directory", "Permission denied", "Is a directory").
bool readable_file(const std::string& path, std::string& why);
Handle create_group(hid_t parent, const std::string& name);

// A 1-D float64 dataset (chunked and compressed when not empty) with a `units` attribute.
void write_vector(hid_t parent, const std::string& name, const std::vector<double>& values,
                  const std::string& units);

// A 2-D float64 dataset [rows, columns] of row-major `values`, chunked and compressed as above.
void write_matrix(hid_t parent, const std::string& name, const std::vector<double>& values,
                  hsize_t rows, hsize_t columns, const std::string& units);

Handle open_dataset(hid_t parent, const std::string& name);

// Dimension scales (HDF5 high-level library, H5DS): `scale` becomes a coordinate named
// `name`, attached to dimension `dim` of `dataset` (xarray, h5py and ParaView read them).
void make_scale(hid_t scale, const std::string& name);
void attach_scale(hid_t dataset, hid_t scale, unsigned dim, const std::string& what);

void write_attribute(hid_t object, const std::string& name, const std::string& value); // UTF-8
void write_attribute(hid_t object, const std::string& name, double value);

// The float64 dataset `name` of `parent`, whole (row-major), and its dimensions; throws Error
// when it is missing or its rank is not `rank`.
std::vector<double> read_array(hid_t parent, const std::string& name, int rank,
                               std::vector<hsize_t>& dims);
// The numeric attribute `name` of `object` as a double; throws Error when it is missing.
double read_number_attribute(hid_t object, const std::string& name);

// A dataset that grows by rows: 2-D [rows, columns], or 1-D [rows] without `columns`.
// Chunked [chunk_rows, columns], shuffle + deflate level 1. `type` is the native type of the
// data passed to append (H5T_NATIVE_DOUBLE or H5T_NATIVE_INT8), stored little-endian.
class RowAppender {
public:
  RowAppender() = default;
  RowAppender(hid_t parent, const std::string& name, hid_t type, std::optional<hsize_t> columns,
              hsize_t chunk_rows, const std::string& units);

  // Appends `rows` rows stored contiguously (row-major) at `data`.
  void append(const void* data, hsize_t rows);
  hid_t id() const { return dataset_.get(); }
  void close() { dataset_.close("closing dataset " + name_); } // throws Error on failure
  void release() { dataset_.reset(); }                         // error paths

private:
  Handle dataset_;
  hid_t type_ = H5I_INVALID_HID;
  int rank_ = 1;
  hsize_t columns_ = 0;
  hsize_t rows_ = 0;
  std::string name_;
};

} // namespace slipfront::api::hdf5
