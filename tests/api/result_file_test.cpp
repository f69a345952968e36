// The HDF5 result file, written with synthetic data and read back with the HDF5 C API.
#include "api/result_check.hpp"
#include "api/result_file.hpp"
#include "api/run_job.hpp"
#include "synthetic_run.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/mount.h>
#include <sys/statvfs.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using slipfront::testing::synthetic_layout;
using slipfront::testing::synthetic_result;
using slipfront::testing::synthetic_sample;
using slipfront::testing::synthetic_spec;
using slipfront::testing::write_synthetic_file;

namespace {

// A fresh directory per test, removed afterwards.
class ResultFile : public ::testing::Test {
protected:
  void SetUp() override {
    directory_ = fs::path(::testing::TempDir()) /
                 ("result_file_" +
                  std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  std::string path(const std::string& name) const { return (directory_ / name).string(); }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

private:
  fs::path directory_;
};

struct Array {
  std::vector<hsize_t> shape;
  std::vector<double> values;
};

Array read_doubles(hid_t file, const std::string& name) {
  Array array;
  const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  EXPECT_GE(dataset, 0) << name;
  if (dataset < 0) return array;
  const hid_t space = H5Dget_space(dataset);
  array.shape.resize(H5Sget_simple_extent_ndims(space));
  H5Sget_simple_extent_dims(space, array.shape.data(), nullptr);
  array.values.resize(H5Sget_simple_extent_npoints(space));
  if (!array.values.empty()) {
    H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, array.values.data());
  }
  H5Sclose(space);
  H5Dclose(dataset);
  return array;
}

std::string read_string_attribute(hid_t object, const std::string& object_name,
                                  const std::string& name) {
  const hid_t attribute =
      H5Aopen_by_name(object, object_name.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(attribute, 0) << object_name << " @" << name;
  if (attribute < 0) return {};
  const hid_t type = H5Aget_type(attribute);
  EXPECT_TRUE(H5Tis_variable_str(type) > 0);
  char* text = nullptr;
  H5Aread(attribute, type, &text);
  std::string value = text != nullptr ? text : "";
  H5free_memory(text);
  H5Tclose(type);
  H5Aclose(attribute);
  return value;
}

double read_double_attribute(hid_t object, const std::string& object_name,
                             const std::string& name) {
  double value = std::nan("");
  const hid_t attribute =
      H5Aopen_by_name(object, object_name.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(attribute, 0) << object_name << " @" << name;
  if (attribute < 0) return value;
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attribute);
  return value;
}

} // namespace

TEST_F(ResultFile, InterfaceFieldsRoundTripTimeMajor) {
  constexpr int nodes = 37;
  constexpr int samples = 150; // two full chunks of 64 rows and a partial one
  write_synthetic_file(path("r.h5"), nodes, samples);

  const hid_t file = H5Fopen(path("r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const Array x1 = read_doubles(file, "/interface/x1");
  EXPECT_EQ(x1.shape, (std::vector<hsize_t>{nodes}));
  EXPECT_EQ(x1.values[1], -9.75);
  const Array time = read_doubles(file, "/interface/time");
  ASSERT_EQ(time.shape, (std::vector<hsize_t>{samples}));
  EXPECT_DOUBLE_EQ(time.values[149], 14.9);

  const std::vector<std::pair<std::string, double>> fields = {{"slip_velocity", 1.0},
                                                              {"slip", 2.0},
                                                              {"shear_traction", 3.0},
                                                              {"contact_pressure", 4.0},
                                                              {"strength", 5.0}};
  for (const auto& [name, factor] : fields) {
    const Array field = read_doubles(file, "/interface/" + name);
    ASSERT_EQ(field.shape, (std::vector<hsize_t>{samples, nodes})) << name;
    for (int k : {0, 63, 64, 149}) {
      for (int i : {0, 36}) {
        EXPECT_DOUBLE_EQ(field.values[k * nodes + i], factor * (k + i / 1000.0)) << name;
      }
    }
  }

  const hid_t state = H5Dopen2(file, "/interface/state", H5P_DEFAULT);
  const hid_t state_type = H5Dget_type(state);
  EXPECT_EQ(H5Tget_size(state_type), 1u);
  EXPECT_EQ(H5Tget_sign(state_type), H5T_SGN_2);
  std::vector<std::int8_t> states(samples * nodes);
  H5Dread(state, H5T_NATIVE_INT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, states.data());
  EXPECT_EQ(states[5 * nodes + 2], (5 + 2) % 3);
  H5Tclose(state_type);
  H5Dclose(state);
  EXPECT_EQ(read_string_attribute(file, "/interface/state", "meaning"),
            "0 = stick, 1 = slip, 2 = open");
  H5Fclose(file);
}

TEST_F(ResultFile, InterfaceDatasetsAreChunkedCompressedAndExtendible) {
  write_synthetic_file(path("r.h5"), 37, 10);
  const hid_t file = H5Fopen(path("r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t dataset = H5Dopen2(file, "/interface/slip_velocity", H5P_DEFAULT);
  const hid_t properties = H5Dget_create_plist(dataset);
  EXPECT_EQ(H5Pget_layout(properties), H5D_CHUNKED);
  hsize_t chunk[2] = {0, 0};
  H5Pget_chunk(properties, 2, chunk);
  EXPECT_EQ(chunk[0], 64u);
  EXPECT_EQ(chunk[1], 37u);
  EXPECT_EQ(H5Pget_nfilters(properties), 2); // shuffle, deflate
  EXPECT_GT(H5Pall_filters_avail(properties), 0);
  const hid_t space = H5Dget_space(dataset);
  hsize_t maximum[2] = {0, 0};
  H5Sget_simple_extent_dims(space, nullptr, maximum);
  EXPECT_EQ(maximum[0], H5S_UNLIMITED);
  EXPECT_EQ(maximum[1], 37u);
  H5Sclose(space);
  H5Pclose(properties);
  H5Dclose(dataset);
  H5Fclose(file);
}

TEST_F(ResultFile, WideInterfacesUseSmallerChunks) {
  // 40000 nodes * 8 bytes = 320 kB a row: a chunk of 64 rows would be 20 MB.
  write_synthetic_file(path("r.h5"), 40000, 5);
  const hid_t file = H5Fopen(path("r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t dataset = H5Dopen2(file, "/interface/strength", H5P_DEFAULT);
  const hid_t properties = H5Dget_create_plist(dataset);
  hsize_t chunk[2] = {0, 0};
  H5Pget_chunk(properties, 2, chunk);
  EXPECT_EQ(chunk[0], 3u);
  EXPECT_LE(chunk[0] * chunk[1] * sizeof(double), 1u << 20);
  H5Pclose(properties);
  H5Dclose(dataset);
  H5Fclose(file);
}

TEST_F(ResultFile, FrontProbesAndEnergy) {
  write_synthetic_file(path("r.h5"), 8, 3);
  const hid_t file = H5Fopen(path("r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const Array arrival = read_doubles(file, "/front/arrival_time");
  ASSERT_EQ(arrival.shape, (std::vector<hsize_t>{8}));
  EXPECT_TRUE(std::isnan(arrival.values[0]));
  EXPECT_DOUBLE_EQ(arrival.values[3], 1.5);
  EXPECT_EQ(read_doubles(file, "/front/x1").shape, (std::vector<hsize_t>{8}));
  EXPECT_TRUE(std::isnan(read_doubles(file, "/front/rupture_speed").values[7]));

  for (const char* name :
       {"/probes/time", "/probes/slip_velocity_arrival", "/probes/slip_velocity_spectrum",
        "/probes/strength_spectrum", "/energy/time", "/energy/kinetic", "/energy/strain",
        "/energy/external_work", "/energy/dissipated"}) {
    EXPECT_EQ(read_doubles(file, name).shape, (std::vector<hsize_t>{10})) << name;
  }
  EXPECT_DOUBLE_EQ(read_doubles(file, "/energy/external_work").values[2], 8.0);
  EXPECT_EQ(read_double_attribute(file, "/probes", "arrival_x1"), 11.0);
  EXPECT_EQ(read_double_attribute(file, "/probes", "spectrum_x1"), 6.0);
  H5Fclose(file);
}

TEST_F(ResultFile, EveryDatasetHasUnits) {
  write_synthetic_file(path("r.h5"), 8, 3);
  const hid_t file = H5Fopen(path("r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const std::vector<std::pair<std::string, std::string>> units = {
      {"/interface/x1", "m"},
      {"/interface/time", "s"},
      {"/interface/slip_velocity", "m/s"},
      {"/interface/slip", "m"},
      {"/interface/shear_traction", "Pa"},
      {"/interface/contact_pressure", "Pa"},
      {"/interface/strength", "Pa"},
      {"/interface/state", "1"},
      {"/front/x1", "m"},
      {"/front/arrival_time", "s"},
      {"/front/rupture_speed", "m/s"},
      {"/probes/time", "s"},
      {"/probes/slip_velocity_arrival", "m/s"},
      {"/probes/strength_spectrum", "Pa"},
      {"/energy/kinetic", "J/m"},
      {"/energy/dissipated", "J/m"}};
  for (const auto& [dataset, unit] : units) {
    EXPECT_EQ(read_string_attribute(file, dataset, "units"), unit) << dataset;
  }
  H5Fclose(file);
}

TEST_F(ResultFile, RootAttributesHoldSpecMetricsAndVersion) {
  write_synthetic_file(path("r.h5"), 8, 3);
  const hid_t file = H5Fopen(path("r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const nlohmann::json spec = nlohmann::json::parse(read_string_attribute(file, "/", "spec"));
  EXPECT_EQ(spec, synthetic_spec());
  EXPECT_EQ(read_string_attribute(file, "/", "spec_sha256"),
            slipfront::api::spec_hash(synthetic_spec()));
  const nlohmann::json metrics = nlohmann::json::parse(read_string_attribute(file, "/", "metrics"));
  EXPECT_EQ(metrics["outcome"], "arrested");
  EXPECT_EQ(metrics["arrest_position"], 12.5);
  EXPECT_TRUE(metrics["arrival_time_at_probe"].is_null());
  EXPECT_EQ(read_string_attribute(file, "/", "code_version"), slipfront::code_version());
  EXPECT_EQ(read_string_attribute(file, "/", "method"), metrics["method"]);
  const std::string created = read_string_attribute(file, "/", "created");
  EXPECT_EQ(created.size(), 20u) << created; // 2024-01-31T12:34:56Z
  EXPECT_EQ(created.back(), 'Z');
  H5Fclose(file);
}

TEST_F(ResultFile, NoFinalFileBeforeFinish) {
  const auto layout = synthetic_layout(5);
  slipfront::api::ResultFileWriter writer(path("r.h5"));
  writer.begin(layout);
  for (int k = 0; k < 100; ++k)
    writer.write(synthetic_sample(layout, k));
  EXPECT_FALSE(fs::exists(path("r.h5")));
  ASSERT_EQ(files().size(), 1u);
  EXPECT_TRUE(files()[0].starts_with("r.h5.tmp.")) << files()[0];

  writer.finish(synthetic_result(layout), synthetic_spec(), nlohmann::json::object());
  EXPECT_EQ(files(), std::vector<std::string>{"r.h5"});
}

TEST_F(ResultFile, AbandonLeavesNothing) {
  const auto layout = synthetic_layout(5);
  slipfront::api::ResultFileWriter writer(path("r.h5"));
  writer.begin(layout);
  writer.write(synthetic_sample(layout, 0));
  writer.abandon();
  EXPECT_TRUE(files().empty());
}

TEST_F(ResultFile, DestroyingAnUnfinishedWriterLeavesNothing) {
  {
    const auto layout = synthetic_layout(5);
    slipfront::api::ResultFileWriter writer(path("r.h5"));
    writer.begin(layout);
    writer.write(synthetic_sample(layout, 0));
  }
  EXPECT_TRUE(files().empty());
}

TEST_F(ResultFile, FinishWithoutSamplesWritesEmptyInterface) {
  slipfront::api::ResultFileWriter writer(path("r.h5"));
  writer.finish(synthetic_result(synthetic_layout(4)), synthetic_spec(), nlohmann::json::object());
  const hid_t file = H5Fopen(path("r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_doubles(file, "/interface/time").shape, (std::vector<hsize_t>{0}));
  EXPECT_EQ(read_doubles(file, "/interface/slip").shape, (std::vector<hsize_t>{0, 0}));
  H5Fclose(file);
}

TEST_F(ResultFile, SampleOfTheWrongSizeIsRefused) {
  slipfront::api::ResultFileWriter writer(path("r.h5"));
  writer.begin(synthetic_layout(5));
  EXPECT_THROW(writer.write(synthetic_sample(synthetic_layout(4), 0)), std::invalid_argument);
}

// The error names the file and HDF5's reason once (it was printed twice).
TEST_F(ResultFile, UnwritableDirectoryThrows) {
  slipfront::api::ResultFileWriter writer(path("missing/dir/r.h5"));
  std::string message;
  try {
    writer.begin(synthetic_layout(5));
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("HDF5: creating file"), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  EXPECT_EQ(message.find("HDF5:"), message.rfind("HDF5:")) << message;
}

// A disk that fills while the file is written: a tmpfs of 256 KiB as the
// directory, mounted by the test (root only; skipped otherwise). The write fails with the
// disk named, the partial file is gone, its blocks are free again, and no HDF5 object is
// left open (before, the failed flush kept the file's objects registered in the library:
// "infinite loop closing library" at exit, and sometimes a crash).
TEST_F(ResultFile, FullDiskReleasesTheFileAndSaysSo) {
  const std::string mount_point = path("tmpfs");
  fs::create_directories(mount_point);
  if (::mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=256k") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs (needs root): " << std::strerror(errno);
  struct Unmount {
    std::string at;
    ~Unmount() { ::umount2(at.c_str(), MNT_DETACH); }
  } unmount{mount_point};
  auto free_bytes = [&] {
    struct statvfs s {};
    ::statvfs(mount_point.c_str(), &s);
    return static_cast<double>(s.f_bavail) * s.f_frsize;
  };
  const double free_before = free_bytes();

  const auto layout = synthetic_layout(4000); // a 32-row chunk of one field is 1 MiB
  std::string message;
  {
    slipfront::api::ResultFileWriter writer(mount_point + "/r.h5");
    try {
      writer.begin(layout);
      for (int k = 0; k < 1000; ++k)
        writer.write(synthetic_sample(layout, k));
      writer.finish(synthetic_result(layout), synthetic_spec(), nlohmann::json::object());
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
    ASSERT_FALSE(message.empty()) << "1000 samples of 4000 nodes fitted in 256 KiB";
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0)
        << "HDF5 objects left open after the failure, before the writer is destroyed";
  }
  EXPECT_NE(message.find("the disk holding " + mount_point + " is full"), std::string::npos)
      << message;
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  EXPECT_NE(message.find("partial file was removed"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_empty(mount_point));
  EXPECT_GE(free_bytes(), free_before) << "the partial file's blocks are free again";
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

// The layout check imports rely on (api/result_check.hpp): what the writer writes passes and
// gives back the spec; any other file is refused with the fault named.
TEST_F(ResultFile, TheLayoutCheckPassesTheWritersFilesOnly) {
  using slipfront::api::check_result_layout;
  write_synthetic_file(path("r.h5"), 8, 3);
  std::string why;
  const auto spec = check_result_layout(path("r.h5"), false, why);
  ASSERT_TRUE(spec.has_value()) << why;
  EXPECT_EQ(nlohmann::json::parse(*spec), synthetic_spec());
  // A job with stations needs /stations, which this file has not.
  EXPECT_FALSE(check_result_layout(path("r.h5"), true, why));
  EXPECT_NE(why.find("no group /stations"), std::string::npos) << why;

  {
    std::FILE* f = std::fopen(path("text.h5").c_str(), "w");
    std::fputs("not HDF5", f);
    std::fclose(f);
  }
  EXPECT_FALSE(check_result_layout(path("text.h5"), false, why));
  EXPECT_EQ(why, "not an HDF5 file");
  EXPECT_FALSE(check_result_layout(path("missing.h5"), false, why));

  // An HDF5 file with a field of the wrong shape.
  fs::copy_file(path("r.h5"), path("short.h5"));
  const hid_t file = H5Fopen(path("short.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hsize_t dims[2] = {1, 1};
  const hid_t set = H5Dopen2(file, "/interface/slip", H5P_DEFAULT);
  ASSERT_GE(H5Dset_extent(set, dims), 0);
  H5Dclose(set);
  H5Fclose(file);
  EXPECT_FALSE(check_result_layout(path("short.h5"), false, why));
  EXPECT_NE(why.find("/interface/slip is not [n_samples, n_nodes]"), std::string::npos) << why;
}
