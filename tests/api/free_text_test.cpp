// Names and tags from clients may not hold control characters (a newline in
// a name once became a command in a SLURM batch script; docs/api-job-spec.md).
#include "api/free_text.hpp"
#include "api/job_spec.hpp"

#include <gtest/gtest.h>

using nlohmann::json;
using slipfront::api::free_text_error;
using slipfront::api::parse_job;

TEST(FreeText, ControlCharactersAreNamedByCodePointAndByte) {
  EXPECT_EQ(free_text_error("x)\nid > FILE\n# ("), "must not contain control characters "
                                                   "(U+000A at byte 2)");
  EXPECT_EQ(free_text_error(std::string("a\0b", 3)), "must not contain control characters "
                                                     "(U+0000 at byte 1)");
  EXPECT_NE(free_text_error("tab\there")->find("U+0009"), std::string::npos);
  EXPECT_NE(free_text_error("del\x7f")->find("U+007F"), std::string::npos);
  EXPECT_NE(free_text_error("esc\x1b[2J")->find("U+001B"), std::string::npos);
  EXPECT_NE(free_text_error("c1 \xc2\x85 next line")->find("U+0085 at byte 3"), std::string::npos);
  EXPECT_NE(free_text_error("c1 \xc2\x9f")->find("U+009F"), std::string::npos);
  EXPECT_NE(free_text_error("line\xe2\x80\xa8sep")->find("U+2028"), std::string::npos);
  EXPECT_NE(free_text_error("para\xe2\x80\xa9sep")->find("U+2029"), std::string::npos);
}

TEST(FreeText, PrintableTextOfAnyScriptIsAccepted) {
  for (const char* text :
       {"L = 1e-5 m on the paper's mesh", "$(touch x) `id`; #SBATCH", "n\xc3\xa9 \xc2\xa0 \xc2\xa9",
        "\xe2\x80\xa7 \xe2\x80\xaa \xe6\xbc\xa2", "\xf0\x9f\x94\xa5", ""})
    EXPECT_FALSE(free_text_error(text)) << text;
}

TEST(FreeText, JobNamesAndTagsWithControlCharactersAreRefusedByPointer) {
  auto refused_at = [](const json& job, const std::string& pointer) {
    const auto r = parse_job(job);
    ASSERT_EQ(r.errors.size(), 1u) << job.dump() << (r.ok() ? " was accepted" : "");
    EXPECT_EQ(r.errors[0].pointer, pointer);
    EXPECT_NE(r.errors[0].reason.find("must not contain control characters"), std::string::npos)
        << r.errors[0].reason;
  };
  refused_at({{"name", "x)\nid > FILE\n# ("}}, "/name");
  refused_at({{"name", "x\r#SBATCH --wrap=id"}}, "/name");
  refused_at({{"name", "x\xe2\x80\xa8y"}}, "/name");
  refused_at({{"tags", {"ok", "bad\ttag"}}}, "/tags/1");
  refused_at({{"method", "spectral_bi"}, {"tags", {"\x1b[31m"}}}, "/tags/0");
  EXPECT_TRUE(parse_job({{"name", "$(id) `id` ; # (\xc3\xa9)"}, {"tags", {"a b"}}}).ok());
}
