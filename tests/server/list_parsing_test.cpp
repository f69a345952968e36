// Comma-separated lists (split_list) and If-None-Match matching (etag_list_matches): one
// parser for the sort= query value and for both ETag checks (JSON answers, result files).
#include "server/http/query_string.hpp"
#include "server/http/responses.hpp"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

using namespace slipfront::server;
using Items = std::vector<std::string_view>;

TEST(SplitList, TrimsEachItemAndKeepsEmptyOnes) {
  EXPECT_EQ(split_list("a, -b ,\t+c"), (Items{"a", "-b", "+c"}));
  EXPECT_EQ(split_list("a,,b"), (Items{"a", "", "b"}));
  EXPECT_EQ(split_list("a,"), (Items{"a", ""}));
  EXPECT_EQ(split_list(""), (Items{""}));
  EXPECT_EQ(split_list("  "), (Items{""}));
}

TEST(EtagListMatches, WeakComparisonOverTheList) {
  const std::string_view strong = "\"abc\"", weak = "W/\"abc\"";
  for (std::string_view etag : {strong, weak}) {
    EXPECT_TRUE(etag_list_matches("\"abc\"", etag)) << etag;
    EXPECT_TRUE(etag_list_matches("W/\"abc\"", etag)) << etag;
    EXPECT_TRUE(etag_list_matches("\"x\", W/\"abc\"", etag)) << etag;
    EXPECT_TRUE(etag_list_matches("*", etag)) << etag;
    EXPECT_FALSE(etag_list_matches("\"abd\"", etag)) << etag;
    EXPECT_FALSE(etag_list_matches("abc", etag)) << etag; // unquoted: another tag
    EXPECT_FALSE(etag_list_matches("", etag)) << etag;
    EXPECT_FALSE(etag_list_matches(" , ", etag)) << etag;
  }
}
