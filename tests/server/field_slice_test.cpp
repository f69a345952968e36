// read_field_slice (GET /jobs/{id}/fields/{name}) against a small result file written here
// with the project's HDF5 helpers: values read back exactly, windows, the nearest node,
// decimation within the budget, and the reasons of missing files and datasets.
#include "api/hdf5_objects.hpp"
#include "api/result_reader.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace slipfront::server {
namespace {

using api::read_field_slice;
using api::SliceWindow;

constexpr int rows = 30, cols = 50;
double value(int r, int c) {
  return r * 1000.0 + c + (r == 3 && c == 4 ? NAN : 0.0);
}

std::string write_file(const testing::TempDir& dir) {
  namespace h5 = api::hdf5;
  const std::string path = dir.file("r.h5");
  auto file = h5::create_file(path);
  auto group = h5::create_group(file.get(), "interface");
  std::vector<double> x1(cols), time(rows), data;
  for (int c = 0; c < cols; ++c)
    x1[c] = -1.0 + 0.1 * c;
  for (int r = 0; r < rows; ++r)
    time[r] = 0.5 * r;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      data.push_back(value(r, c));
  h5::write_vector(group.get(), "x1", x1, "m");
  h5::write_vector(group.get(), "time", time, "s");
  h5::RowAppender v(group.get(), "slip_velocity", H5T_NATIVE_DOUBLE, cols, 8, "m/s");
  v.append(data.data(), rows);
  v.close();
  return path;
}

TEST(FieldSlice, WholeFieldIsTheFile) {
  testing::TempDir dir("slipfront-slice-");
  const auto path = write_file(dir);
  std::string why;
  auto s = read_field_slice(path, "slip_velocity", {}, why);
  ASSERT_TRUE(s) << why;
  ASSERT_EQ(s->time.size(), static_cast<std::size_t>(rows));
  ASSERT_EQ(s->x1.size(), static_cast<std::size_t>(cols));
  EXPECT_EQ(s->units, "m/s");
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double got = s->values[r * cols + c];
      if (r == 3 && c == 4)
        EXPECT_TRUE(std::isnan(got));
      else
        EXPECT_EQ(got, value(r, c));
    }
}

TEST(FieldSlice, WindowAndNearestNode) {
  testing::TempDir dir("slipfront-slice-");
  const auto path = write_file(dir);
  std::string why;
  SliceWindow w;
  w.x1_min = 0.0;  // node 10 (x1 = 0.0, up to rounding of -1 + 0.1 c)
  w.x1_max = 0.45; // up to node 14
  w.t_min = 2.0;   // row 4
  w.t_max = 3.0;   // row 6
  auto s = read_field_slice(path, "slip_velocity", w, why);
  ASSERT_TRUE(s) << why;
  ASSERT_EQ(s->time.size(), 3u);
  EXPECT_EQ(s->row_first, 4u);
  ASSERT_GE(s->x1.size(), 4u);
  for (std::size_t r = 0; r < s->time.size(); ++r)
    for (std::size_t c = 0; c < s->x1.size(); ++c)
      EXPECT_EQ(s->values[r * s->x1.size() + c],
                value(static_cast<int>(s->row_first + r), static_cast<int>(s->column_first + c)));
  SliceWindow one;
  one.x1_min = one.x1_max = 0.73; // nearest node: 17 (x1 = 0.7)
  s = read_field_slice(path, "slip_velocity", one, why);
  ASSERT_TRUE(s) << why;
  ASSERT_EQ(s->x1.size(), 1u);
  EXPECT_EQ(s->column_first, 17u);
  EXPECT_EQ(s->values[5], value(5, 17));
}

TEST(FieldSlice, DecimationKeepsEveryKthValueWithinTheBudget) {
  testing::TempDir dir("slipfront-slice-");
  const auto path = write_file(dir);
  std::string why;
  for (long budget : {1L, 7L, 100L, 400L, 1499L}) {
    SliceWindow w;
    w.max_points = budget;
    auto s = read_field_slice(path, "slip_velocity", w, why);
    ASSERT_TRUE(s) << why;
    const auto n = s->time.size() * s->x1.size();
    EXPECT_LE(static_cast<long>(n), budget);
    EXPECT_GE(n, 1u);
    for (std::size_t r = 0; r < s->time.size(); ++r)
      for (std::size_t c = 0; c < s->x1.size(); ++c) {
        const int fr = static_cast<int>(r * s->row_stride),
                  fc = static_cast<int>(c * s->column_stride);
        if (fr == 3 && fc == 4) continue;
        EXPECT_EQ(s->values[r * s->x1.size() + c], value(fr, fc));
      }
  }
}

TEST(FieldSlice, MissingFileOrDatasetSaysWhy) {
  testing::TempDir dir("slipfront-slice-");
  std::string why;
  EXPECT_FALSE(read_field_slice(dir.file("none.h5"), "slip", {}, why));
  EXPECT_EQ(why, "No such file or directory");
  const auto path = write_file(dir);
  EXPECT_FALSE(read_field_slice(path, "strength", {}, why));
  EXPECT_NE(why.find("/interface/strength"), std::string::npos) << why;
}

} // namespace
} // namespace slipfront::server
