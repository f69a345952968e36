#include "api/result_file.hpp"

#include "api/hdf5_objects.hpp"
#include "api/job_spec.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <stdexcept>

namespace slipfront::api {

namespace {

constexpr hsize_t max_chunk_rows = 64;
constexpr hsize_t max_chunk_bytes = 1 << 20;

// The float64 interface fields, in the order of InterfaceSample, with their units.
struct FieldInfo {
  const char* name;
  const char* units;
  const std::vector<double> InterfaceSample::*values;
};
constexpr std::array<FieldInfo, 5> interface_fields = {{
    {"slip_velocity", "m/s", &InterfaceSample::slip_velocity},
    {"slip", "m", &InterfaceSample::slip},
    {"shear_traction", "Pa", &InterfaceSample::shear_traction},
    {"contact_pressure", "Pa", &InterfaceSample::contact_pressure},
    {"strength", "Pa", &InterfaceSample::strength},
}};

std::string iso_time_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

} // namespace

struct ResultFileWriter::Impl {
  std::string final_path;
  std::string temp_path;
  bool finished = false;

  hdf5::Handle file;
  hdf5::Handle interface_group;
  hdf5::RowAppender time;
  std::array<hdf5::RowAppender, interface_fields.size()> fields;
  hdf5::RowAppender state;

  // Samples wait here until a chunk's worth of rows is complete.
  std::size_t nodes = 0;
  hsize_t chunk_rows = 1;
  hsize_t buffered = 0;
  std::vector<double> time_buffer;
  std::array<std::vector<double>, interface_fields.size()> field_buffers;
  std::vector<std::int8_t> state_buffer;

  void open_file();
  void create_interface(const InterfaceLayout& layout);
  void flush();
  void write_records(const RunResult& result);
  void attach_interface_scales();
  void close();   // every flush and close checked: throws hdf5::Error
  void release(); // error paths: close what can be closed, ignoring failures
  void discard_after_error();
  [[noreturn]] void fail(const std::exception& error);
};

void ResultFileWriter::Impl::open_file() {
  if (file.valid()) return;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // failures become exceptions, not stderr noise
  file = hdf5::create_file(temp_path);
}

void ResultFileWriter::Impl::create_interface(const InterfaceLayout& layout) {
  open_file();
  if (interface_group.valid()) throw std::logic_error("ResultFileWriter::begin called twice");
  nodes = layout.x1.size();
  const hsize_t row_bytes = std::max<hsize_t>(nodes, 1) * sizeof(double);
  chunk_rows = std::clamp<hsize_t>(max_chunk_bytes / row_bytes, 1, max_chunk_rows);

  interface_group = hdf5::create_group(file.get(), "interface");
  const hid_t group = interface_group.get();
  hdf5::write_attribute(group, "sample_interval", layout.sample_interval);
  hdf5::write_attribute(group, "layout", "time-major: [n_samples, n_nodes]");
  hdf5::write_vector(group, "x1", layout.x1, "m");
  time = hdf5::RowAppender(group, "time", H5T_NATIVE_DOUBLE, std::nullopt, chunk_rows, "s");
  for (std::size_t f = 0; f < interface_fields.size(); ++f) {
    fields[f] = hdf5::RowAppender(group, interface_fields[f].name, H5T_NATIVE_DOUBLE, nodes,
                                  chunk_rows, interface_fields[f].units);
    field_buffers[f].reserve(chunk_rows * nodes);
  }
  state = hdf5::RowAppender(group, "state", H5T_NATIVE_INT8, nodes, chunk_rows, "1");
  hdf5::write_attribute(state.id(), "meaning", "0 = stick, 1 = slip, 2 = open");
  state_buffer.reserve(chunk_rows * nodes);
}

void ResultFileWriter::Impl::flush() {
  if (buffered == 0) return;
  time.append(time_buffer.data(), buffered);
  for (std::size_t f = 0; f < interface_fields.size(); ++f) {
    fields[f].append(field_buffers[f].data(), buffered);
    field_buffers[f].clear();
  }
  state.append(state_buffer.data(), buffered);
  time_buffer.clear();
  state_buffer.clear();
  buffered = 0;
}

void ResultFileWriter::Impl::write_records(const RunResult& result) {
  const hid_t root = file.get();
  {
    hdf5::Handle front = hdf5::create_group(root, "front");
    hdf5::write_vector(front.get(), "x1", result.front.x1, "m");
    hdf5::write_vector(front.get(), "arrival_time", result.front.arrival_time, "s");
    hdf5::write_vector(front.get(), "rupture_speed", result.front.rupture_speed, "m/s");
  }
  {
    const ProbeRecords& p = result.probes;
    hdf5::Handle probes = hdf5::create_group(root, "probes");
    hdf5::write_attribute(probes.get(), "arrival_x1", p.arrival_node_x1);
    hdf5::write_attribute(probes.get(), "spectrum_x1", p.spectrum_node_x1);
    hdf5::write_vector(probes.get(), "time", p.time, "s");
    hdf5::write_vector(probes.get(), "slip_velocity_arrival", p.slip_velocity_arrival, "m/s");
    hdf5::write_vector(probes.get(), "slip_velocity_spectrum", p.slip_velocity_spectrum, "m/s");
    hdf5::write_vector(probes.get(), "strength_spectrum", p.strength_spectrum, "Pa");
  }
  {
    const EnergyRecords& e = result.energy;
    hdf5::Handle energy = hdf5::create_group(root, "energy");
    hdf5::write_vector(energy.get(), "time", e.time, "s");
    hdf5::write_vector(energy.get(), "kinetic", e.kinetic, "J/m");
    hdf5::write_vector(energy.get(), "strain", e.strain, "J/m");
    hdf5::write_vector(energy.get(), "external_work", e.external_work, "J/m");
    hdf5::write_vector(energy.get(), "dissipated", e.dissipated, "J/m");
  }
}

// /interface/time and /interface/x1 become the coordinates of every interface field
// (dimension 0: time, 1: x1); /front/x1, /probes/time and /energy/time those of their groups.
void ResultFileWriter::Impl::attach_interface_scales() {
  const hid_t group = interface_group.get();
  hdf5::Handle x1 = hdf5::open_dataset(group, "x1");
  hdf5::make_scale(x1.get(), "x1");
  hdf5::make_scale(time.id(), "time");
  for (std::size_t f = 0; f < interface_fields.size(); ++f) {
    const std::string name = std::string("/interface/") + interface_fields[f].name;
    hdf5::attach_scale(fields[f].id(), time.id(), 0, "/interface/time to " + name);
    hdf5::attach_scale(fields[f].id(), x1.get(), 1, "/interface/x1 to " + name);
  }
  hdf5::attach_scale(state.id(), time.id(), 0, "/interface/time to /interface/state");
  hdf5::attach_scale(state.id(), x1.get(), 1, "/interface/x1 to /interface/state");
  const hid_t root = file.get();
  const std::pair<const char*, std::vector<const char*>> groups[] = {
      {"/front/x1", {"/front/arrival_time", "/front/rupture_speed"}},
      {"/probes/time",
       {"/probes/slip_velocity_arrival", "/probes/slip_velocity_spectrum",
        "/probes/strength_spectrum"}},
      {"/energy/time",
       {"/energy/kinetic", "/energy/strain", "/energy/external_work", "/energy/dissipated"}},
  };
  for (const auto& [scale_path, dataset_paths] : groups) {
    hdf5::Handle scale = hdf5::open_dataset(root, scale_path);
    const std::string scale_name(scale_path);
    hdf5::make_scale(scale.get(), scale_name.substr(scale_name.rfind('/') + 1));
    for (const char* path : dataset_paths) {
      hdf5::Handle dataset = hdf5::open_dataset(root, path);
      hdf5::attach_scale(dataset.get(), scale.get(), 0, scale_name + " to " + path);
    }
  }
}

void ResultFileWriter::Impl::close() {
  time.close();
  for (auto& field : fields)
    field.close();
  state.close();
  interface_group.close("closing group interface");
  if (file.valid()) hdf5::check(H5Fflush(file.get(), H5F_SCOPE_LOCAL), "flushing " + temp_path);
  file.close("closing " + temp_path);
}

void ResultFileWriter::Impl::release() {
  time.release();
  for (auto& field : fields)
    field.release();
  state.release();
  interface_group.reset();
  file.reset();
}

// After a failed write HDF5 still holds dirty chunks and metadata that it cannot flush. An
// object whose close fails to flush stays registered in the library (and keeps its file
// open), so the handles would outlive the job, and the library's own clean-up at exit
// closed them again and crashed (SIGSEGV in H5F__close_cb under H5_term_library; see
// docs/reliability.md). So the file's descriptor is first pointed at an anonymous in-memory
// file: the flushes of the closes below then succeed (into memory, only what is still
// dirty), every object is released, and the descriptor of the real file is closed. The
// partial file is unlinked: with its descriptor gone its blocks are free at once. Should
// memfd_create or dup3 fail (no memory, no descriptor), the closes are tried as they are.
void ResultFileWriter::Impl::discard_after_error() {
  if (file.valid()) {
    void* handle = nullptr;
    if (H5Fget_vfd_handle(file.get(), H5P_DEFAULT, &handle) >= 0 && handle != nullptr) {
      const int fd = *static_cast<int*>(handle);
      const int scratch = ::memfd_create("slipfront-discarded-result", MFD_CLOEXEC);
      if (scratch >= 0) {
        ::dup3(scratch, fd, O_CLOEXEC); // closes the real file's descriptor
        ::close(scratch);
      }
    }
  }
  std::remove(temp_path.c_str());
  release();
  H5Eclear2(H5E_DEFAULT);
  finished = true; // nothing is left to clean up
}

// Every error of the file ends here: the writer lets go of the file (above) and throws
// the error again, saying when it is the disk that is full.
void ResultFileWriter::Impl::fail(const std::exception& error) {
  const auto* hdf5_error = dynamic_cast<const hdf5::Error*>(&error);
  const int code = hdf5_error != nullptr ? hdf5_error->system_errno() : 0;
  discard_after_error();
  std::string message = "result file " + final_path + ": ";
  if (code == ENOSPC || code == EDQUOT) {
    const auto directory = std::filesystem::path(final_path).parent_path().string();
    message += "the disk holding " + (directory.empty() ? std::string(".") : directory) +
               " is full (" + std::strerror(code) + ")";
  } else {
    message += error.what();
  }
  message += "; the partial file was removed";
  if (code != 0) message += " [" + std::string(error.what()) + "]";
  throw std::runtime_error(message);
}

ResultFileWriter::ResultFileWriter(std::string final_path) : impl_(std::make_unique<Impl>()) {
  impl_->temp_path = final_path + ".tmp." + std::to_string(::getpid());
  impl_->final_path = std::move(final_path);
}

ResultFileWriter::~ResultFileWriter() {
  if (!impl_->finished) abandon();
}

void ResultFileWriter::begin(const InterfaceLayout& layout) {
  try {
    impl_->create_interface(layout);
  } catch (const hdf5::Error& e) {
    impl_->fail(e);
  }
}

void ResultFileWriter::write(const InterfaceSample& sample) {
  Impl& w = *impl_;
  if (!w.interface_group.valid()) throw std::logic_error("ResultFileWriter::write before begin");
  for (std::size_t f = 0; f < interface_fields.size(); ++f) {
    const std::vector<double>& values = sample.*interface_fields[f].values;
    if (values.size() != w.nodes) {
      throw std::invalid_argument(std::string("interface sample: ") + interface_fields[f].name +
                                  " has " + std::to_string(values.size()) + " values, expected " +
                                  std::to_string(w.nodes));
    }
    w.field_buffers[f].insert(w.field_buffers[f].end(), values.begin(), values.end());
  }
  if (sample.state.size() != w.nodes) {
    throw std::invalid_argument("interface sample: state has " +
                                std::to_string(sample.state.size()) + " values, expected " +
                                std::to_string(w.nodes));
  }
  w.state_buffer.insert(w.state_buffer.end(), sample.state.begin(), sample.state.end());
  w.time_buffer.push_back(sample.time);
  if (++w.buffered == w.chunk_rows) {
    try {
      w.flush();
    } catch (const hdf5::Error& e) {
      w.fail(e);
    }
  }
}

void ResultFileWriter::finish(const RunResult& result, const nlohmann::json& canonical_spec,
                              const nlohmann::json& metrics) {
  Impl& w = *impl_;
  if (w.finished) throw std::logic_error("ResultFileWriter::finish called twice");
  try {
    if (!w.interface_group.valid()) w.create_interface(InterfaceLayout{});
    w.flush();
    w.write_records(result);
    w.attach_interface_scales();

    const hid_t root = w.file.get();
    hdf5::write_attribute(root, "spec", canonical_text(canonical_spec));
    hdf5::write_attribute(root, "spec_sha256", spec_hash(canonical_spec));
    hdf5::write_attribute(root, "metrics", metrics.dump());
    hdf5::write_attribute(root, "code_version", code_version());
    for (const char* key : {"method", "method_description"}) {
      const auto value = metrics.find(key);
      hdf5::write_attribute(root, key,
                            value != metrics.end() && value->is_string() ? value->get<std::string>()
                                                                         : std::string());
    }
    hdf5::write_attribute(root, "created", iso_time_now());
    w.close();
  } catch (const hdf5::Error& e) {
    w.fail(e);
  }

  if (std::rename(w.temp_path.c_str(), w.final_path.c_str()) != 0) {
    const int code = errno;
    std::remove(w.temp_path.c_str());
    w.finished = true;
    throw std::runtime_error("cannot rename " + w.temp_path + " to " + w.final_path + ": " +
                             std::strerror(code));
  }
  w.finished = true;
}

void ResultFileWriter::abandon() {
  if (impl_->finished) return;
  impl_->discard_after_error();
}

} // namespace slipfront::api
