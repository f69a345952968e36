// The search language of GET /api/v1/jobs: parsing and the field whitelist (its SQL:
// run_query_sql_test.cpp).
#include "server/core/run_query.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace slipfront::server;

namespace {

std::string reason_of(const std::string& where) {
  try {
    parse_where(where);
  } catch (const QueryError& e) {
    EXPECT_EQ(e.parameter(), "where");
    return e.what();
  }
  return "";
}

} // namespace

TEST(RunQuery, ParsesConditionsJoinedBySemicolonOrAnd) {
  auto c = parse_where("friction.L<1e-4; metrics.arrest_position >= 12 and outcome=arrested");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].field.name, "friction.L");
  EXPECT_EQ(c[0].op, CompareOp::lt);
  EXPECT_DOUBLE_EQ(std::get<double>(c[0].value), 1e-4);
  EXPECT_EQ(c[1].field.name, "metrics.arrest_position");
  EXPECT_EQ(c[1].op, CompareOp::ge);
  EXPECT_EQ(c[2].field.name, "outcome");
  EXPECT_EQ(std::get<std::string>(c[2].value), "arrested");
}

TEST(RunQuery, QuotedValuesKeepSeparatorsAndSpaces) {
  auto c = parse_where("name='a; b and c' ; tag=\"x y\"");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(std::get<std::string>(c[0].value), "a; b and c");
  EXPECT_EQ(std::get<std::string>(c[1].value), "x y");
}

TEST(RunQuery, EverySpecLeafAndMetricIsSearchable) {
  auto fields = searchable_fields();
  for (const char* name :
       {"friction.L", "geometry.nodes_per_meter", "time.stop_on_arrest", "metrics.arrest_position",
        "metrics.rupture_speed.max", "metrics.outcome", "created_at", "convergence_status"})
    EXPECT_NE(std::find(fields.begin(), fields.end(), name), fields.end()) << name;
  EXPECT_NO_THROW(parse_where("spec.friction.L=1e-5"));
  EXPECT_NO_THROW(parse_where("time.stop_on_arrest=true"));
}

TEST(RunQuery, RefusesWithAReason) {
  EXPECT_NE(reason_of("friction.L<abc").find("not a finite number"), std::string::npos);
  EXPECT_NE(reason_of("friction.L<1e999").find("not a finite number"), std::string::npos);
  EXPECT_NE(reason_of("friction.X<1").find("unknown field"), std::string::npos);
  EXPECT_NE(reason_of("metrics.nope=1").find("unknown metric"), std::string::npos);
  EXPECT_NE(reason_of("friction.L ~ 1").find("comparison"), std::string::npos);
  EXPECT_NE(reason_of("friction.L<1 or 1=1").find("';' or 'and'"), std::string::npos);
  EXPECT_NE(reason_of("name='open").find("unterminated"), std::string::npos);
  EXPECT_NE(reason_of("outcome=a;").find("after a separator"), std::string::npos);
  EXPECT_NE(reason_of("  ").find("empty"), std::string::npos);
  EXPECT_NE(reason_of("tag>a").find("tag takes"), std::string::npos);
  // the run table names the column `tags`: the same filter under that name
  EXPECT_NE(reason_of("tags>a").find("tags takes = or != only"), std::string::npos);
  EXPECT_NE(reason_of("1=1").find("unknown field"), std::string::npos);
}

TEST(RunQuery, SortKeys) {
  auto keys = parse_sort("-metrics.arrest_position, friction.L");
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_TRUE(keys[0].descending);
  EXPECT_FALSE(keys[1].descending);
  EXPECT_EQ(keys[0].field.source, FieldSource::metrics);
  EXPECT_EQ(keys[0].field.key, "arrest_position");
  EXPECT_THROW(parse_sort("friction.L,"), QueryError);
  EXPECT_THROW(parse_sort("tag"), QueryError);
  EXPECT_THROW(parse_sort("j.seq; DROP TABLE jobs"), QueryError);
}
