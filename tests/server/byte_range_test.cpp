#include "server/core/job_id.hpp"
#include "server/http/byte_range.hpp"
#include "server/http/query_string.hpp"

#include <gtest/gtest.h>

using namespace slipfront::server;
using Kind = RangeRequest::Kind;

TEST(ByteRange, Forms) {
  auto r = parse_range("bytes=0-9", 100);
  EXPECT_EQ(r.kind, Kind::partial);
  EXPECT_EQ(r.range.first, 0u);
  EXPECT_EQ(r.range.length, 10u);
  r = parse_range("bytes=90-", 100);
  EXPECT_EQ(r.range.first, 90u);
  EXPECT_EQ(r.range.length, 10u);
  r = parse_range("bytes=-5", 100);
  EXPECT_EQ(r.range.first, 95u);
  EXPECT_EQ(r.range.length, 5u);
  r = parse_range("bytes=50-1000", 100); // clipped to the end
  EXPECT_EQ(r.range.length, 50u);
}

TEST(ByteRange, UnsatisfiableAndIgnored) {
  EXPECT_EQ(parse_range("bytes=100-", 100).kind, Kind::unsatisfiable);
  EXPECT_EQ(parse_range("bytes=-0", 100).kind, Kind::unsatisfiable);
  EXPECT_EQ(parse_range("bytes=0-1,5-6", 100).kind, Kind::whole);
  EXPECT_EQ(parse_range("items=0-1", 100).kind, Kind::whole);
  EXPECT_EQ(parse_range("bytes=5-2", 100).kind, Kind::whole);
  EXPECT_EQ(parse_range("bytes=x-", 100).kind, Kind::whole);
}

TEST(JobId, OnlyHex32) {
  auto id = new_job_id();
  EXPECT_TRUE(is_valid_job_id(id));
  EXPECT_NE(id, new_job_id());
  EXPECT_FALSE(is_valid_job_id("../../etc/passwd"));
  EXPECT_FALSE(is_valid_job_id(std::string(32, 'g')));
  EXPECT_FALSE(is_valid_job_id(std::string(31, 'a')));
  EXPECT_FALSE(is_valid_job_id(std::string(31, 'a').append("/")));
}

TEST(QueryString, Decodes) {
  auto t = parse_target("/api/v1/jobs?tag=a%20b&name=x+y&status=queued,running");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->path, "/api/v1/jobs");
  EXPECT_EQ(t->query["tag"], "a b");
  EXPECT_EQ(t->query["name"], "x y");
  EXPECT_EQ(t->query["status"], "queued,running");
  EXPECT_FALSE(parse_target("/x?a=%zz"));
  EXPECT_FALSE(parse_target("/x?a=%4"));
  EXPECT_FALSE(parse_target("x"));
  EXPECT_EQ(percent_encode("a b&c=d/é"), "a%20b%26c%3Dd%2F%C3%A9");
  EXPECT_EQ(*percent_decode(percent_encode("x y+z"), true), "x y+z");
}
