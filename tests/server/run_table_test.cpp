// The CSV of the run table (GET /jobs?format=csv), built one row at a time: the header is
// the union of every row's keys (job columns in first-seen order, then spec.* and metrics.*
// sorted), each cell lands under its column whatever the row's key order, missing and null
// values are empty, and text a spreadsheet would run is neutralised.
#include "server/http/run_table.hpp"

#include <gtest/gtest.h>

namespace slipfront::server {
namespace {

nlohmann::ordered_json row(std::initializer_list<std::pair<const char*, nlohmann::json>> cells) {
  nlohmann::ordered_json r = nlohmann::ordered_json::object();
  for (const auto& [key, value] : cells)
    r[key] = value;
  return r;
}

TEST(RunTableCsv, HeaderIsTheUnionAndCellsLandUnderTheirColumns) {
  RunTableCsv csv;
  csv.add(row({{"id", "a"}, {"metrics.steps", 10}, {"spec.time.duration", 2.0}, {"name", "x"}}));
  csv.add(row({{"id", "b"},
               {"status", "failed"},
               {"spec.friction.L", 1e-4},
               {"name", "y, \"q\""},
               {"error", nullptr}}));
  EXPECT_EQ(csv.text(), "id,name,status,error,spec.friction.L,spec.time.duration,metrics.steps\r\n"
                        "a,x,,,,2.0,10\r\n"
                        "b,\"y, \"\"q\"\"\",failed,,0.0001,,\r\n");
}

TEST(RunTableCsv, FormulaTextIsNeutralisedNumbersAreNot) {
  RunTableCsv csv;
  csv.add(row({{"name", "=cmd()"}, {"tags", "@x;-y"}, {"spec.v", -3}}));
  EXPECT_EQ(csv.text(), "name,tags,spec.v\r\n'=cmd(),'@x;-y,-3\r\n");
}

TEST(RunTableCsv, NoRowsIsAnEmptyHeader) {
  EXPECT_EQ(RunTableCsv().text(), "\r\n");
}

} // namespace
} // namespace slipfront::server
