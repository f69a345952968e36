// Bearer tokens (compared in constant time over their digests) and job ids (from getrandom).
#include "server/core/job_id.hpp"
#include "server/http/auth.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

using namespace slipfront::server;
using slipfront::server::testing::TempDir;

TEST(TokenTable, MatchesWholeTokensOnly) {
  TempDir dir("slipfront-auth-");
  {
    std::ofstream out(dir.file("tokens"));
    out << "# users\nalice:abcdefgh12345678\nbob : abcdefgh1234567X\n";
  }
  auto table = TokenTable::load(dir.file("tokens"));
  EXPECT_EQ(table.size(), 2u);
  EXPECT_EQ(table.user_for_header("Bearer abcdefgh12345678"), "alice");
  EXPECT_EQ(table.user_for_header("bearer   abcdefgh1234567X"), "bob");
  for (const char* wrong :
       {"Bearer abcdefgh1234567", "Bearer abcdefgh123456789", "Bearer abcdefgh12345679", "Bearer ",
        "Basic abcdefgh12345678", "abcdefgh12345678", ""})
    EXPECT_FALSE(table.user_for_header(wrong).has_value()) << wrong;
}

TEST(JobId, RandomHexOfTheRightShape) {
  std::set<std::string> seen;
  for (int i = 0; i < 1000; ++i) {
    auto id = new_job_id();
    EXPECT_TRUE(is_valid_job_id(id)) << id;
    seen.insert(id);
  }
  EXPECT_EQ(seen.size(), 1000u);
}
