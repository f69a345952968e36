// The SQL of the search language (server/db/run_query_sql.hpp): values and JSON paths are
// bound parameters, the common fields are read from their indexed columns, and every field
// of the whitelist has its SQL.
#include "server/db/run_query_sql.hpp"

#include <gtest/gtest.h>

using namespace slipfront::server;

TEST(RunQuerySql, SqlBindsValuesAndPaths) {
  SqlParams params;
  auto c = parse_where("output.interval<0.1; name=\"x' OR 1=1 --\"");
  std::string first = condition_sql(c[0], params);
  std::string second = condition_sql(c[1], params);
  EXPECT_EQ(first, "json_extract(j.spec, ?1) < ?2");
  EXPECT_EQ(second, "j.name = ?3");
  ASSERT_EQ(params.values.size(), 3u);
  EXPECT_EQ(std::get<std::string>(params.values[0]), "$.output.interval");
  EXPECT_EQ(std::get<std::string>(params.values[2]), "x' OR 1=1 --");
}

TEST(RunQuerySql, IndexedColumnsForTheCommonFields) {
  SqlParams params;
  EXPECT_EQ(condition_sql(parse_where("friction.L<1")[0], params), "j.L < ?1");
  EXPECT_EQ(condition_sql(parse_where("metrics.arrest_position>1")[0], params),
            "m.arrest_position > ?2");
}

TEST(RunQuerySql, SortKeysReadTheColumn) {
  SqlParams params;
  EXPECT_EQ(sort_sql(parse_sort("-metrics.arrest_position")[0], params),
            "m.arrest_position DESC NULLS LAST");
  EXPECT_EQ(sort_sql(parse_sort("friction.law")[0], params),
            "json_extract(j.spec, ?1) ASC NULLS LAST");
}

// A bare number compares as a number in a text field kept as JSON (a spec or metrics leaf may
// hold either in some runs); a text column keeps it as text, and so does a quoted number.
TEST(RunQuerySql, BareNumbersAreNumbersOnlyInJson) {
  SqlParams params;
  EXPECT_EQ(condition_sql(parse_where("friction.law=20")[0], params),
            "json_extract(j.spec, ?1) = ?2");
  EXPECT_EQ(std::get<double>(params.values[1]), 20.0);
  EXPECT_EQ(condition_sql(parse_where("friction.law='20'")[0], params),
            "json_extract(j.spec, ?3) = ?4");
  EXPECT_EQ(std::get<std::string>(params.values[3]), "20");
  EXPECT_EQ(condition_sql(parse_where("name=20")[0], params), "j.name = ?5");
  EXPECT_EQ(std::get<std::string>(params.values[4]), "20");
  EXPECT_EQ(condition_sql(parse_where("metrics.outcome=20")[0], params), "m.outcome = ?6");
  EXPECT_EQ(std::get<std::string>(params.values[5]), "20");
}

// Every field the parser accepts has its SQL here: a job column the store cannot read would
// throw std::logic_error.
TEST(RunQuerySql, EverySearchableFieldHasItsSql) {
  for (const auto& name : searchable_fields()) {
    const RunField field = resolve_field(name, "where");
    SqlParams params;
    Condition c{field, CompareOp::eq, std::string("x"), std::nullopt};
    EXPECT_NO_THROW(condition_sql(c, params)) << name;
    if (field.type != FieldType::tag) {
      EXPECT_NO_THROW(sort_sql({field, false}, params)) << name;
    }
  }
}
