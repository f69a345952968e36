#include "api/hdf5_objects.hpp"

#include <hdf5_hl.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace slipfront::api::hdf5 {

namespace {

constexpr unsigned deflate_level = 1;
constexpr hsize_t vector_chunk = 65536;

// Shuffle + deflate on a chunked layout.
Handle compressed_layout(int rank, const hsize_t* chunk) {
  Handle properties(check_id(H5Pcreate(H5P_DATASET_CREATE), "dataset properties"));
  check(H5Pset_chunk(properties.get(), rank, chunk), "chunk layout");
  check(H5Pset_shuffle(properties.get()), "shuffle filter");
  check(H5Pset_deflate(properties.get(), deflate_level), "deflate filter");
  return properties;
}

} // namespace

namespace {

struct Cause {
  std::string text;
  int system_errno = 0;
};

// The innermost entry of this thread's HDF5 error stack: where the failure began. A failed
// system call is described as "..., errno = 28, error message = 'No space left on device',
// ...": keep the message and the number.
Cause innermost_cause() {
  Cause cause;
  auto visit = [](unsigned n, const H5E_error2_t* error, void* data) -> herr_t {
    if (n != 0 || error->desc == nullptr) return 0;
    auto& c = *static_cast<Cause*>(data);
    const std::string desc = error->desc;
    c.text = desc;
    if (const auto at = desc.find("errno = "); at != std::string::npos)
      c.system_errno = std::atoi(desc.c_str() + at + 8);
    const std::string quote = "error message = '";
    if (const auto at = desc.find(quote); at != std::string::npos) {
      const auto begin = at + quote.size();
      c.text = desc.substr(begin, desc.find('\'', begin) - begin);
    }
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, visit, &cause);
  return cause;
}

[[noreturn]] void fail(const std::string& what) {
  const Cause cause = innermost_cause();
  // The cause is carried by the exception now: nothing is left on HDF5's error stack, whose
  // entries would otherwise stay allocated until the next HDF5 call (at exit: a leak).
  H5Eclear2(H5E_DEFAULT);
  throw Error("HDF5: " + what + " failed" + (cause.text.empty() ? "" : ": " + cause.text),
              cause.system_errno);
}

herr_t close_object(hid_t id) {
  switch (H5Iget_type(id)) {
  case H5I_FILE:
    return H5Fclose(id);
  case H5I_GROUP:
    return H5Gclose(id);
  case H5I_DATASET:
    return H5Dclose(id);
  case H5I_DATASPACE:
    return H5Sclose(id);
  case H5I_DATATYPE:
    return H5Tclose(id);
  case H5I_ATTR:
    return H5Aclose(id);
  case H5I_GENPROP_LST:
    return H5Pclose(id);
  default:
    return 0; // not an object of ours (or no longer valid): nothing to close
  }
}

} // namespace

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &old_func_, &old_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() {
  H5Eset_auto2(H5E_DEFAULT, old_func_, old_data_);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

hid_t check_id(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    other.id_ = H5I_INVALID_HID;
  }
  return *this;
}

void Handle::reset() {
  if (id_ < 0) return;
  close_object(id_);
  id_ = H5I_INVALID_HID;
}

void Handle::close(const std::string& what) {
  if (id_ < 0) return;
  check(close_object(id_), what);
  id_ = H5I_INVALID_HID;
}

bool readable_file(const std::string& path, std::string& why) {
  if (path.empty()) {
    why = "no result file";
    return false;
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK); // a FIFO cannot block
  if (fd < 0) {
    why = std::strerror(errno);
    return false;
  }
  struct stat status {};
  const bool regular = ::fstat(fd, &status) == 0 && S_ISREG(status.st_mode);
  ::close(fd);
  if (!regular) why = S_ISDIR(status.st_mode) ? std::strerror(EISDIR) : "not a regular file";
  return regular;
}

Handle create_file(const std::string& path) {
  return Handle(check_id(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                         "creating file " + path));
}

Handle create_group(hid_t parent, const std::string& name) {
  return Handle(check_id(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         "creating group " + name));
}

namespace {

// A float64 dataset of `rank` (1 or 2) dimensions `dims`, written whole from `values` (row-major),
// chunked by whole rows of about vector_chunk values and compressed when not empty.
void write_array(hid_t parent, const std::string& name, const double* values, int rank,
                 const hsize_t* dims, const std::string& units) {
  const hsize_t columns = rank == 2 ? dims[1] : 1;
  const hsize_t size = dims[0] * columns;
  Handle space(check_id(H5Screate_simple(rank, dims, nullptr), "dataspace of " + name));
  Handle properties; // contiguous when empty: a chunk may not be empty
  if (size > 0) {
    const hsize_t chunk[2] = {std::clamp<hsize_t>(vector_chunk / columns, 1, dims[0]), columns};
    properties = compressed_layout(rank, chunk);
  }
  Handle dataset(
      check_id(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                          properties.valid() ? properties.get() : H5P_DEFAULT, H5P_DEFAULT),
               "creating dataset " + name));
  if (size > 0) {
    check(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values),
          "writing dataset " + name);
  }
  write_attribute(dataset.get(), "units", units);
}

} // namespace

void write_vector(hid_t parent, const std::string& name, const std::vector<double>& values,
                  const std::string& units) {
  const hsize_t size = values.size();
  write_array(parent, name, values.data(), 1, &size, units);
}

void write_matrix(hid_t parent, const std::string& name, const std::vector<double>& values,
                  hsize_t rows, hsize_t columns, const std::string& units) {
  if (values.size() != rows * columns)
    throw std::invalid_argument("dataset " + name + ": " + std::to_string(values.size()) +
                                " values for " + std::to_string(rows) + " x " +
                                std::to_string(columns));
  const hsize_t dims[2] = {rows, columns};
  write_array(parent, name, values.data(), 2, dims, units);
}

Handle open_dataset(hid_t parent, const std::string& name) {
  return Handle(check_id(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
}

void make_scale(hid_t scale, const std::string& name) {
  check(H5DSset_scale(scale, name.c_str()), "making " + name + " a dimension scale");
}

void attach_scale(hid_t dataset, hid_t scale, unsigned dim, const std::string& what) {
  check(H5DSattach_scale(dataset, scale, dim), "attaching dimension scale: " + what);
}

void write_attribute(hid_t object, const std::string& name, const std::string& value) {
  Handle type(check_id(H5Tcopy(H5T_C_S1), "string type"));
  check(H5Tset_size(type.get(), H5T_VARIABLE), "string type size");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "string type character set");
  Handle space(check_id(H5Screate(H5S_SCALAR), "scalar dataspace"));
  Handle attribute(
      check_id(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
               "creating attribute " + name));
  const char* text = value.c_str();
  check(H5Awrite(attribute.get(), type.get(), &text), "writing attribute " + name);
}

void write_attribute(hid_t object, const std::string& name, double value) {
  Handle space(check_id(H5Screate(H5S_SCALAR), "scalar dataspace"));
  Handle attribute(check_id(
      H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      "creating attribute " + name));
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value), "writing attribute " + name);
}

std::vector<double> read_array(hid_t parent, const std::string& name, int rank,
                               std::vector<hsize_t>& dims) {
  Handle dataset = open_dataset(parent, name);
  Handle space(check_id(H5Dget_space(dataset.get()), "dataspace of " + name));
  if (H5Sget_simple_extent_ndims(space.get()) != rank)
    throw Error("dataset " + name + " is not " + std::to_string(rank) + "-D", 0);
  dims.assign(std::size_t(rank), 0);
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  hsize_t size = 1;
  for (hsize_t d : dims)
    size *= d;
  std::vector<double> values(size);
  if (size > 0)
    check(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "reading dataset " + name);
  return values;
}

double read_number_attribute(hid_t object, const std::string& name) {
  Handle attribute(
      check_id(H5Aopen(object, name.c_str(), H5P_DEFAULT), "opening attribute " + name));
  double value = 0.0;
  check(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value), "reading attribute " + name);
  return value;
}

RowAppender::RowAppender(hid_t parent, const std::string& name, hid_t type,
                         std::optional<hsize_t> columns, hsize_t chunk_rows,
                         const std::string& units)
    : type_(type), rank_(columns ? 2 : 1), columns_(columns.value_or(0)), name_(name) {
  const hsize_t initial[2] = {0, columns_};
  // A row of zero columns still needs a chunk of at least one column.
  const hsize_t maximum[2] = {H5S_UNLIMITED, columns_ > 0 ? columns_ : H5S_UNLIMITED};
  const hsize_t chunk[2] = {chunk_rows, std::max<hsize_t>(columns_, 1)};
  Handle space(check_id(H5Screate_simple(rank_, initial, maximum), "dataspace of " + name));
  Handle properties = compressed_layout(rank_, chunk);
  const hid_t file_type = type == H5T_NATIVE_INT8 ? H5T_STD_I8LE : H5T_IEEE_F64LE;
  dataset_ = Handle(check_id(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                                        properties.get(), H5P_DEFAULT),
                             "creating dataset " + name));
  write_attribute(dataset_.get(), "units", units);
}

void RowAppender::append(const void* data, hsize_t rows) {
  if (rows == 0) return;
  const hsize_t new_size[2] = {rows_ + rows, columns_};
  check(H5Dset_extent(dataset_.get(), new_size), "extending dataset " + name_);
  Handle file_space(check_id(H5Dget_space(dataset_.get()), "dataspace of " + name_));
  const hsize_t start[2] = {rows_, 0};
  const hsize_t count[2] = {rows, columns_};
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
        "selecting rows of " + name_);
  Handle memory_space(check_id(H5Screate_simple(rank_, count, nullptr), "memory dataspace"));
  check(H5Dwrite(dataset_.get(), type_, memory_space.get(), file_space.get(), H5P_DEFAULT, data),
        "writing rows of " + name_);
  rows_ += rows;
}

} // namespace slipfront::api::hdf5
