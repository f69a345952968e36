#include "api/result_file.hpp"

#include "api/hdf5_objects.hpp"
#include "api/job_spec.hpp"
#include "api/result_layout.hpp"
#include "api/result_stations_writer.hpp"
#include "solver/simulation.hpp"

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

// The float64 interface fields (names and units: api/result_layout.hpp), each with the
// member of InterfaceSample that holds its values.
struct FieldInfo {
  const char* name;
  const char* units;
  const std::vector<double> InterfaceSample::*values;
};
constexpr FieldInfo field_info(std::size_t i, const std::vector<double> InterfaceSample::*values) {
  return {layout::float_fields[i].name, layout::float_fields[i].units, values};
}
constexpr std::array<FieldInfo, layout::float_fields.size()> interface_fields = {{
    field_info(0, &InterfaceSample::slip_velocity),
    field_info(1, &InterfaceSample::slip),
    field_info(2, &InterfaceSample::shear_traction),
    field_info(3, &InterfaceSample::contact_pressure),
    field_info(4, &InterfaceSample::strength),
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
  void create_interface(const InterfaceLayout& grid);
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

void ResultFileWriter::Impl::create_interface(const InterfaceLayout& grid) {
  open_file();
  if (interface_group.valid()) throw std::logic_error("ResultFileWriter::begin called twice");
  nodes = grid.x1.size();
  const hsize_t row_bytes = std::max<hsize_t>(nodes, 1) * sizeof(double);
  chunk_rows = std::clamp<hsize_t>(max_chunk_bytes / row_bytes, 1, max_chunk_rows);

  interface_group = hdf5::create_group(file.get(), layout::interface_group);
  const hid_t group = interface_group.get();
  hdf5::write_attribute(group, "sample_interval", grid.sample_interval);
  hdf5::write_attribute(group, "layout", "time-major: [n_samples, n_nodes]");
  hdf5::write_vector(group, layout::x1, grid.x1, "m");
  time = hdf5::RowAppender(group, layout::time, H5T_NATIVE_DOUBLE, std::nullopt, chunk_rows, "s");
  for (std::size_t f = 0; f < interface_fields.size(); ++f) {
    fields[f] = hdf5::RowAppender(group, interface_fields[f].name, H5T_NATIVE_DOUBLE, nodes,
                                  chunk_rows, interface_fields[f].units);
    field_buffers[f].reserve(chunk_rows * nodes);
  }
  state = hdf5::RowAppender(group, layout::state_field.name, H5T_NATIVE_INT8, nodes, chunk_rows,
                            layout::state_field.units);
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
    hdf5::Handle front = hdf5::create_group(root, layout::front_group);
    hdf5::write_vector(front.get(), layout::x1, result.front.x1, "m");
    hdf5::write_vector(front.get(), layout::front_arrival_time, result.front.arrival_time, "s");
    hdf5::write_vector(front.get(), layout::front_rupture_speed, result.front.rupture_speed, "m/s");
  }
  {
    const ProbeRecords& p = result.probes;
    hdf5::Handle probes = hdf5::create_group(root, layout::probes_group);
    hdf5::write_attribute(probes.get(), layout::probe_arrival_x1, p.arrival_node_x1);
    hdf5::write_attribute(probes.get(), layout::probe_spectrum_x1, p.spectrum_node_x1);
    hdf5::write_vector(probes.get(), layout::time, p.time, "s");
    hdf5::write_vector(probes.get(), layout::probe_slip_velocity_arrival, p.slip_velocity_arrival,
                       "m/s");
    hdf5::write_vector(probes.get(), layout::probe_slip_velocity_spectrum, p.slip_velocity_spectrum,
                       "m/s");
    hdf5::write_vector(probes.get(), layout::probe_strength_spectrum, p.strength_spectrum, "Pa");
  }
  {
    const EnergyRecords& e = result.energy;
    hdf5::Handle energy = hdf5::create_group(root, layout::energy_group);
    hdf5::write_vector(energy.get(), layout::time, e.time, "s");
    hdf5::write_vector(energy.get(), layout::energy_kinetic, e.kinetic, "J/m");
    hdf5::write_vector(energy.get(), layout::energy_strain, e.strain, "J/m");
    hdf5::write_vector(energy.get(), layout::energy_external_work, e.external_work, "J/m");
    hdf5::write_vector(energy.get(), layout::energy_dissipated, e.dissipated, "J/m");
  }
  write_stations(root, result.stations); // only when the job has stations
}

// /interface/time and /interface/x1 become the coordinates of every interface field
// (dimension 0: time, 1: x1); /front/x1, /probes/time and /energy/time those of their groups.
void ResultFileWriter::Impl::attach_interface_scales() {
  using layout::path;
  const hid_t group = interface_group.get();
  hdf5::Handle x1 = hdf5::open_dataset(group, layout::x1);
  hdf5::make_scale(x1.get(), layout::x1);
  hdf5::make_scale(time.id(), layout::time);
  const std::string time_path = path(layout::interface_group, layout::time);
  const std::string x1_path = path(layout::interface_group, layout::x1);
  auto attach_both = [&](hid_t dataset, const char* name) {
    const std::string field_path = path(layout::interface_group, name);
    hdf5::attach_scale(dataset, time.id(), 0, time_path + " to " + field_path);
    hdf5::attach_scale(dataset, x1.get(), 1, x1_path + " to " + field_path);
  };
  for (std::size_t f = 0; f < interface_fields.size(); ++f)
    attach_both(fields[f].id(), interface_fields[f].name);
  attach_both(state.id(), layout::state_field.name);
  const hid_t root = file.get();
  struct Scaled {
    const char* group;
    const char* scale;
    std::vector<const char*> datasets;
  };
  const Scaled groups[] = {
      {layout::front_group, layout::x1, {layout::front_arrival_time, layout::front_rupture_speed}},
      {layout::probes_group,
       layout::time,
       {layout::probe_slip_velocity_arrival, layout::probe_slip_velocity_spectrum,
        layout::probe_strength_spectrum}},
      {layout::energy_group,
       layout::time,
       {layout::energy_kinetic, layout::energy_strain, layout::energy_external_work,
        layout::energy_dissipated}},
  };
  for (const auto& g : groups) {
    const std::string scale_path = path(g.group, g.scale);
    hdf5::Handle scale = hdf5::open_dataset(root, scale_path);
    hdf5::make_scale(scale.get(), g.scale);
    for (const char* name : g.datasets) {
      const std::string dataset_path = path(g.group, name);
      hdf5::Handle dataset = hdf5::open_dataset(root, dataset_path);
      hdf5::attach_scale(dataset.get(), scale.get(), 0, scale_path + " to " + dataset_path);
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
               " is full (" + std::strerror(code) + "); the partial file was removed [" +
               error.what() + "]";
  } else { // HDF5's message once, with the reason it carries
    message += std::string(error.what()) + "; the partial file was removed";
  }
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
    hdf5::write_attribute(root, layout::spec_attribute, canonical_text(canonical_spec));
    hdf5::write_attribute(root, layout::spec_sha256_attribute, spec_hash(canonical_spec));
    hdf5::write_attribute(root, layout::metrics_attribute, metrics.dump());
    hdf5::write_attribute(root, layout::code_version_attribute, code_version());
    for (const char* key : {layout::method_attribute, layout::method_description_attribute}) {
      const auto value = metrics.find(key);
      hdf5::write_attribute(root, key,
                            value != metrics.end() && value->is_string() ? value->get<std::string>()
                                                                         : std::string());
    }
    // Where each number with a unit came from, and the job's warnings (api/scene_defaults.hpp).
    for (const char* key : {layout::provenance_attribute, layout::job_warnings_attribute}) {
      const auto value = metrics.find(key);
      hdf5::write_attribute(root, key, value != metrics.end() ? value->dump() : std::string("[]"));
    }
    hdf5::write_attribute(root, layout::created_attribute, iso_time_now());
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
