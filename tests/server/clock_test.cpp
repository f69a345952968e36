// Timestamps as the server writes and accepts them (server/core/clock.hpp).
#include "server/core/clock.hpp"

#include <gtest/gtest.h>

using slipfront::server::is_utc_iso8601;
using slipfront::server::now_iso8601;

TEST(Clock, TimesAreAcceptedInTheFormTheServerWritesThem) {
  EXPECT_TRUE(is_utc_iso8601(now_iso8601()));
  EXPECT_TRUE(is_utc_iso8601("2024-05-01T12:00:00Z"));
  EXPECT_TRUE(is_utc_iso8601("2024-02-29T23:59:59.123456789Z")); // a leap day
  for (const char* bad :
       {"not a time; DROP TABLE jobs", "", "2024-05-01", "2024-05-01T12:00:00",
        "2024-05-01T12:00:00+02:00", "2024-05-01 12:00:00Z", "2023-02-29T00:00:00Z",
        "2024-04-31T00:00:00Z", "2024-13-01T00:00:00Z", "2024-05-01T24:00:00Z",
        "2024-05-01T12:60:00Z", "2024-05-01T12:00:00.Z", "2024-05-01T12:00:00.1234567890Z",
        "2024-05-01T12:00:00.12aZ", "-024-05-01T12:00:00Z"})
    EXPECT_FALSE(is_utc_iso8601(bad)) << bad;
}
