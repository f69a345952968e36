// Reading a length-fit record (api/length_fit/record_*.hpp, length_fit_request.hpp): CSV with
// its header, the stations CSV of `slipfront stations --csv` as it is, JSON columns; and every
// bad record answered with the column and the line (CSV) or the JSON pointer (JSON).
#include "api/length_fit/length_fit_request.hpp"
#include "api/length_fit/record_checks.hpp"
#include "api/length_fit/record_reader.hpp"
#include "api/station_csv.hpp"
#include "length_fit_records.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace slipfront::api {
namespace {

// A record of the synthetic event as CSV, with a comment line first.
std::string synthetic_csv(const InterfaceRecord& r) {
  std::ostringstream out;
  out.precision(17);
  out << "# a synthetic record\r\ntime,slip_rate,contact_pressure,frictional_stress,note\r\n";
  for (std::size_t k = 0; k < r.size(); ++k)
    out << r.time[k] << ',' << r.slip_rate[k] << ',' << r.contact_pressure[k] << ','
        << r.frictional_stress[k] << ",any text\r\n";
  return out.str();
}

std::string only_error(const RecordRead& read) {
  EXPECT_FALSE(read.record.has_value());
  EXPECT_EQ(read.errors.size(), 1u);
  return read.errors.empty() ? "" : describe(read.errors.front());
}

std::string check_error(const std::string& csv) {
  const RecordRead read = read_record_csv(csv, std::nullopt);
  EXPECT_TRUE(read.record.has_value());
  if (!read.record) return "";
  const std::vector<RecordError> errors = check_record(*read.record, std::nullopt);
  EXPECT_FALSE(errors.empty());
  return errors.empty() ? "" : describe(errors.front());
}

// The synthetic record's CSV with line `line` (1-based) replaced.
std::string with_line(std::string csv, int line, const std::string& text) {
  std::size_t start = 0;
  for (int i = 1; i < line; ++i)
    start = csv.find('\n', start) + 1;
  const std::size_t end = csv.find('\n', start);
  return csv.replace(start, end - start, text);
}

TEST(LengthFitRecord, ReadsACsvWithCommentsCrLfAndExtraColumns) {
  const InterfaceRecord original = test::synthetic_record({});
  const RecordRead read = read_record_csv(synthetic_csv(original), std::nullopt);
  ASSERT_TRUE(read.record) << describe(read.errors.at(0));
  const InterfaceRecord& r = *read.record;
  ASSERT_EQ(r.size(), original.size());
  EXPECT_EQ(r.time, original.time);
  EXPECT_EQ(r.frictional_stress, original.frictional_stress);
  EXPECT_EQ(r.source.kind, RecordSource::Kind::csv);
  EXPECT_EQ(r.source.line.front(), 3); // after the comment and the header
  EXPECT_TRUE(check_record(r, std::nullopt).empty());
}

TEST(LengthFitRecord, ReadsOneStationOfAStationsCsv) {
  StationRecords s;
  s.x1 = {2.0, 6.0};
  s.rupture_threshold = 1e-3;
  s.rupture_time = {0.5, 1.5};
  s.node_x1 = {2.0, 2.0, 6.0, 6.0};
  s.node_weight = {1, 0, 1, 0};
  for (int k = 0; k < 40; ++k) {
    s.time.push_back(0.1 * k);
    for (int station = 0; station < 2; ++station) {
      s.slip_rate.push_back(-1e-3 * k * (station + 1)); // sign ignored
      s.slip.push_back(0.0);
      s.shear_traction.push_back(0.01 + 1e-4 * k);
      s.normal_traction.push_back(-0.015 - 1e-4 * station);
    }
  }
  std::ostringstream csv;
  write_stations_csv(csv, s);
  EXPECT_NE(only_error(read_record_csv(csv.str(), std::nullopt))
                .find("the record holds 2 stations (x1 = 2, 6 m): choose one (station_x1)"),
            std::string::npos);
  EXPECT_NE(only_error(read_record_csv(csv.str(), 7.0))
                .find("no row is at station_x1 = 7 (the record's stations: 2, 6 m)"),
            std::string::npos);
  const RecordRead read = read_record_csv(csv.str(), 6.0);
  ASSERT_TRUE(read.record);
  const InterfaceRecord& r = *read.record;
  EXPECT_EQ(r.source.kind, RecordSource::Kind::stations_csv);
  EXPECT_EQ(*r.source.station_x1, 6.0);
  EXPECT_EQ(r.source.stations_in_file, 2u);
  ASSERT_EQ(r.size(), 40u);
  EXPECT_DOUBLE_EQ(r.contact_pressure[3], 0.0151); // -normal_traction
  EXPECT_EQ(r.slip_rate[3], -6e-3);
  EXPECT_EQ(r.frictional_stress[3], 0.01 + 3e-4);
  // Station 6's rows follow the 3 + 2 comment lines, the header and station 2's 40 rows.
  EXPECT_EQ(r.source.line.front(), 3 + 2 + 1 + 40 + 1);
}

TEST(LengthFitRecord, BadCellsNameTheirLineAndColumn) {
  const std::string csv = synthetic_csv(test::synthetic_record({}));
  EXPECT_EQ(only_error(read_record_csv(with_line(csv, 5, "0.04,abc,1e6,6e5,x"), std::nullopt)),
            "line 5, column \"slip_rate\": not a number: \"abc\"");
  EXPECT_EQ(only_error(read_record_csv(with_line(csv, 6, "0.06,0,nan,6e5,x"), std::nullopt)),
            "line 6, column \"contact_pressure\": not a finite number: \"nan\"");
  EXPECT_EQ(only_error(read_record_csv(with_line(csv, 7, "0.08,0,1e6,6e5"), std::nullopt)),
            "line 7: has 4 cells, the header names 5 columns");
  EXPECT_EQ(only_error(read_record_csv(with_line(csv, 8, "0.1,0,1e6,,x"), std::nullopt)),
            "line 8, column \"frictional_stress\": not a number: \"\"");
  EXPECT_NE(
      only_error(read_record_csv(with_line(csv, 2, "time,slip_rate,pressure,stress"), std::nullopt))
          .find("line 2: the header has no column \"contact_pressure\", "
                "\"frictional_stress\""),
      std::string::npos);
  EXPECT_EQ(only_error(read_record_csv("", std::nullopt)).substr(0, 20), "the record is empty:");
  // At most ten errors, then reading stops.
  std::string many = csv;
  for (int line = 3; line < 30; ++line)
    many = with_line(many, line, "x,0,1e6,6e5,x");
  EXPECT_EQ(read_record_csv(many, std::nullopt).errors.size(), max_record_errors);
}

TEST(LengthFitRecord, PhysicalChecksNameTheColumnAndTheSample) {
  const std::string csv = synthetic_csv(test::synthetic_record({}));
  EXPECT_EQ(check_error(with_line(csv, 10, "0.1,0,1e6,6e5,x")).substr(0, 80),
            "line 10, column \"time\": time must increase from sample to sample: 0.1 s follows ");
  std::string short_csv = csv.substr(0, csv.find('\n', csv.find('\n') + 1) + 1);
  for (int k = 0; k < 31; ++k)
    short_csv += std::to_string(k) + ",1,1e6,6e5,x\n";
  EXPECT_EQ(only_error(RecordRead{
                std::nullopt,
                check_record(*read_record_csv(short_csv, std::nullopt).record, std::nullopt)}),
            "too short: 31 samples, a fit needs at least 32");
  InterfaceRecord still = test::synthetic_record({});
  for (double& v : still.slip_rate)
    v = 0;
  EXPECT_EQ(describe(check_record(still, std::nullopt).at(0)),
            "/slip_rate: no slip: the slip rate is 0 in every sample");
  InterfaceRecord open = test::synthetic_record({});
  for (double& p : open.contact_pressure)
    p = -1;
  EXPECT_NE(describe(check_record(open, std::nullopt).at(0)).find("/contact_pressure: no contact"),
            std::string::npos);
  InterfaceRecord steady = test::synthetic_record({});
  for (double& p : steady.contact_pressure)
    p = 1e6;
  EXPECT_NE(describe(check_record(steady, std::nullopt).at(0))
                .find("/contact_pressure: the pressure never changes"),
            std::string::npos);
  InterfaceRecord huge = test::synthetic_record({});
  huge.frictional_stress[7] = 1e31;
  EXPECT_EQ(describe(check_record(huge, std::nullopt).at(0)),
            "/frictional_stress/7: must be a finite number within +-1e+30, got 1e+31");
  InterfaceRecord brief = test::synthetic_record({});
  EXPECT_NE(describe(check_record(brief, 0.04999).at(0)).find("/slip_rate: too little slip: "),
            std::string::npos);
}

TEST(LengthFitRecord, RecordsAreBounded) {
  std::string rows = "time,slip_rate,contact_pressure,frictional_stress\n";
  for (std::size_t k = 0; k <= max_record_points; ++k)
    rows += std::to_string(k) + ",1,1,1\n";
  EXPECT_EQ(only_error(read_record_csv(rows, std::nullopt)),
            "line 200002: the point has more than 200000 samples (docs/length-fit.md \"Bounds\")");
  const std::string huge(max_record_bytes + 1, '#');
  EXPECT_NE(only_error(read_record_csv(huge, std::nullopt)).find("more than the limit of 67108864"),
            std::string::npos);
}

TEST(LengthFitRecord, JsonErrorsArePointers) {
  const InterfaceRecord r = test::synthetic_record({});
  nlohmann::json record = {{"time", r.time},
                           {"slip_rate", r.slip_rate},
                           {"contact_pressure", r.contact_pressure},
                           {"frictional_stress", r.frictional_stress}};
  const RecordRead good = read_record_json(record);
  ASSERT_TRUE(good.record);
  EXPECT_EQ(good.record->time, r.time);

  nlohmann::json bad = record;
  bad["slip_rate"][16] = "fast";
  bad["time"].erase(bad["time"].begin());
  bad["colour"] = "red";
  nlohmann::json body = {{"record", bad}, {"v_star", -1}, {"station_x1", 6}};
  const LengthFitRequest request = parse_length_fit_request(body);
  EXPECT_FALSE(request.record);
  std::vector<std::string> pointers;
  for (const FieldError& e : request.errors)
    pointers.push_back(e.pointer + ": " + e.reason);
  EXPECT_EQ(pointers,
            (std::vector<std::string>{
                "/v_star: must be a finite number in (0, 1e+06], got -1",
                "/record/slip_rate/16: must be a finite number, got \"fast\"",
                "/record/colour: unknown field (known here: contact_pressure, frictional_stress, "
                "slip_rate, time)"}));

  nlohmann::json uneven = record;
  uneven["time"].erase(uneven["time"].begin());
  const LengthFitRequest lengths = parse_length_fit_request({{"record", uneven}});
  ASSERT_EQ(lengths.errors.size(), 3u);
  EXPECT_EQ(lengths.errors[0].pointer, "/record/slip_rate");
  EXPECT_EQ(lengths.errors[0].reason, "has 500 values, time has 499");

  nlohmann::json backwards = record;
  backwards["time"][100] = 0.0;
  const LengthFitRequest parsed = parse_length_fit_request({{"record", backwards}});
  ASSERT_TRUE(parsed.record);
  const LengthFitAnswer answer = answer_length_fit(*parsed.record, parsed.options);
  ASSERT_EQ(answer.errors.size(), 1u);
  EXPECT_EQ(answer.errors[0].pointer, "/record/time/100");

  const LengthFitRequest missing = parse_length_fit_request({{"v_star", 1e-4}});
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_EQ(missing.errors[0].pointer, "/record");
}

TEST(LengthFitRecord, CsvErrorsOfARequestNameTheLine) {
  const std::string csv = synthetic_csv(test::synthetic_record({}));
  const LengthFitRequest request =
      parse_length_fit_request({{"record", with_line(csv, 9, "0.12,1,1e6,zz,x")}});
  ASSERT_EQ(request.errors.size(), 1u);
  EXPECT_EQ(request.errors[0].pointer, "/record");
  EXPECT_EQ(request.errors[0].reason, "line 9, column \"frictional_stress\": not a number: \"zz\"");
  const LengthFitRequest station = parse_length_fit_request({{"record", csv}, {"station_x1", 6}});
  ASSERT_EQ(station.errors.size(), 1u);
  EXPECT_EQ(station.errors[0].pointer, "/station_x1");
}

} // namespace
} // namespace slipfront::api
