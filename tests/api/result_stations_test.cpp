// The /stations group of the result file (written by ResultFileWriter, read back by
// api::read_stations) and the stations' CSV export (api/station_csv.hpp).
#include "api/result_file.hpp"
#include "api/result_stations.hpp"
#include "api/station_csv.hpp"
#include "synthetic_run.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace fs = std::filesystem;
using slipfront::StationRecords;
using slipfront::api::read_stations;
using slipfront::api::write_stations_csv;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

// Two stations (one between nodes, one on a node that never ruptured), three steps.
StationRecords two_stations() {
  StationRecords r;
  r.x1 = {4.5, -2.0};
  r.node_x1 = {4.25, 4.75, -2.0, -2.0};
  r.node_weight = {0.5, 0.5, 1.0, 0.0};
  r.rupture_threshold = 1e-3;
  r.time = {0.0, 0.125, 0.25};
  r.slip_rate = {0.0, 0.0, 2e-3, 0.0, 0.1, 1e-4};
  r.slip = {0.0, 0.0, 1.25e-4, 0.0, 1.3e-2, 1.25e-5};
  r.shear_traction = {7e7, 7e7, 6.5e7, 7e7, 6.3e7, 6.9e7};
  r.normal_traction = {-1.2e8, -1.2e8, -1.2e8, -1.2e8, -1.1e8, -1.2e8};
  r.rupture_time = {0.0625, nan};
  return r;
}

class ResultStations : public ::testing::Test {
protected:
  void SetUp() override {
    directory_ = fs::path(::testing::TempDir()) /
                 ("result_stations_" +
                  std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  std::string path(const std::string& name) const { return (directory_ / name).string(); }

  // A complete result file of the synthetic run with `stations`.
  std::string write_with(const StationRecords& stations) {
    using namespace slipfront::testing;
    const std::string file = path("with_stations.h5");
    const auto layout = synthetic_layout(8);
    slipfront::api::ResultFileWriter writer(file);
    writer.begin(layout);
    writer.write(synthetic_sample(layout, 0));
    slipfront::RunResult result = synthetic_result(layout);
    result.stations = stations;
    writer.finish(result, synthetic_spec(), nlohmann::json::object());
    return file;
  }

private:
  fs::path directory_;
};

void expect_same_bits(const std::vector<double>& got, const std::vector<double>& want,
                      const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i) {
    if (std::isnan(want[i]))
      EXPECT_TRUE(std::isnan(got[i])) << what << "[" << i << "]";
    else
      EXPECT_EQ(got[i], want[i]) << what << "[" << i << "]";
  }
}

} // namespace

TEST_F(ResultStations, RoundTripExactly) {
  const StationRecords written = two_stations();
  std::string why;
  const auto read = read_stations(write_with(written), why);
  ASSERT_TRUE(read.has_value()) << why;
  EXPECT_EQ(read->rupture_threshold, written.rupture_threshold);
  expect_same_bits(read->x1, written.x1, "x1");
  expect_same_bits(read->node_x1, written.node_x1, "node_x1");
  expect_same_bits(read->node_weight, written.node_weight, "node_weight");
  expect_same_bits(read->time, written.time, "time");
  expect_same_bits(read->slip_rate, written.slip_rate, "slip_rate");
  expect_same_bits(read->slip, written.slip, "slip");
  expect_same_bits(read->shear_traction, written.shear_traction, "shear_traction");
  expect_same_bits(read->normal_traction, written.normal_traction, "normal_traction");
  expect_same_bits(read->rupture_time, written.rupture_time, "rupture_time");
}

TEST_F(ResultStations, AFileWithoutStationsHasNoGroupAndReadsEmpty) {
  const std::string file = path("plain.h5");
  slipfront::testing::write_synthetic_file(file, 8, 3);
  const hid_t h = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(h, 0);
  EXPECT_EQ(H5Lexists(h, "stations", H5P_DEFAULT), 0);
  H5Fclose(h);
  std::string why;
  const auto read = read_stations(file, why);
  ASSERT_TRUE(read.has_value()) << why;
  EXPECT_TRUE(read->empty());
}

TEST_F(ResultStations, UnreadableFilesSayWhy) {
  std::string why;
  EXPECT_FALSE(read_stations(path("missing.h5"), why).has_value());
  EXPECT_EQ(why, "No such file or directory"); // the system's words
  EXPECT_FALSE(read_stations(path(""), why).has_value());
  EXPECT_EQ(why, "Is a directory");
  std::ofstream(path("text.h5")) << "not HDF5";
  EXPECT_FALSE(read_stations(path("text.h5"), why).has_value());
  EXPECT_EQ(why, "the result file cannot be opened as HDF5");
}

// Numbers in their shortest exact form (fixed or scientific, whichever is shorter).
TEST(StationCsv, LongFormatWithUnitsAndRuptureTimesInTheHeader) {
  std::ostringstream out;
  write_stations_csv(out, two_stations());
  EXPECT_EQ(out.str(),
            "# slipfront stations: one row per station and time step, every step of the run\n"
            "# units: station_x1 [m], time [s], slip [m], slip_rate [m/s], shear_traction [Pa], "
            "normal_traction [Pa] (negative in compression)\n"
            "# rupture_time [s]: the first time |slip_rate| > rupture_threshold = 0.001 m/s, "
            "linear in time between steps (nan: never)\n"
            "# station_x1 = 4.5: rupture_time = 0.0625\n"
            "# station_x1 = -2: rupture_time = nan\n"
            "station_x1,time,slip,slip_rate,shear_traction,normal_traction\n"
            "4.5,0,0,0,7e+07,-1.2e+08\n"
            "4.5,0.125,0.000125,0.002,6.5e+07,-1.2e+08\n"
            "4.5,0.25,0.013,0.1,6.3e+07,-1.1e+08\n"
            "-2,0,0,0,7e+07,-1.2e+08\n"
            "-2,0.125,0,0,7e+07,-1.2e+08\n"
            "-2,0.25,1.25e-05,1e-04,6.9e+07,-1.2e+08\n");
}

TEST(StationCsv, NumbersReadBackExactly) {
  StationRecords r = two_stations();
  r.slip[5] = 0.1 + 0.2; // 0.30000000000000004: needs all 17 digits
  std::ostringstream out;
  write_stations_csv(out, r);
  const std::string text = out.str();
  EXPECT_NE(text.find("-2,0.25,0.30000000000000004,"), std::string::npos) << text;
}
