// The door for friction laws (docs/architecture.md "Adding a friction law"): a toy law in a
// test-only file (exponential_weakening.cpp), and nothing else edited, is known to the job
// schema (its choice, its fields with x-when, its label), to the reader's validation (its
// fields' ranges, its check mu_d <= mu_s in friction and in profiles, the fields it does not
// use), to the docs' table of fields, and runs by both methods.
#include "api/job_schema.hpp"
#include "api/job_spec.hpp"
#include "solver/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace slipfront::api {
namespace {

using nlohmann::json;

json toy_job(json friction) {
  friction["law"] = "exponential_weakening";
  return {{"geometry", {{"nodes_per_meter", 5}}},
          {"time", {{"duration", 2.0}}},
          {"friction", friction}};
}

bool has(const json& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// The laws of an x-when condition on /friction/law ({} if none).
json law_condition(const json& field) {
  const json& when = field.value("x-when", json());
  for (const json& c : when.is_array() ? when : json::array({when}))
    if (c.value("pointer", "") == "/friction/law") return c["values"];
  return json::array();
}

TEST(ToyLaw, TheSchemaKnowsIt) {
  const json schema = job_json_schema();
  const json& friction = schema["properties"]["friction"]["properties"];
  EXPECT_TRUE(has(friction["law"]["enum"], "exponential_weakening"));
  for (const char* field : {"mu_s", "mu_d", "D_c"})
    EXPECT_TRUE(has(law_condition(friction[field]), "exponential_weakening")) << field;
  EXPECT_FALSE(has(law_condition(friction["mu"]), "exponential_weakening"));
  // It lets the job choose a regularisation, so the form shows that choice with it.
  EXPECT_TRUE(has(law_condition(friction["regularization"]), "exponential_weakening"));
  EXPECT_EQ(friction["law"]["x-labels"]["exponential_weakening"]["label"],
            "exponential weakening D_c = {D_c} m");
  const std::string docs = job_fields_markdown();
  EXPECT_NE(docs.find("`exponential_weakening` (mu from mu_s towards mu_d"), std::string::npos);
  EXPECT_NE(docs.find("weakening distance (exponential_weakening)"), std::string::npos);
}

TEST(ToyLaw, TheReaderValidatesIt) {
  const ParseResult ok = parse_job(toy_job({{"mu_s", 0.7}, {"mu_d", 0.5}, {"D_c", 0.01}}));
  ASSERT_TRUE(ok.ok()) << ok.errors.front().pointer << ": " << ok.errors.front().reason;
  EXPECT_EQ(ok.spec->params.friction.law, "exponential_weakening");
  EXPECT_EQ(ok.spec->canonical["friction"]["law"], "exponential_weakening");
  auto first_error = [](const json& job) {
    const ParseResult r = parse_job(job);
    return r.errors.empty() ? FieldError{} : r.errors.front();
  };
  FieldError e = first_error(toy_job({{"mu", 0.5}}));
  EXPECT_EQ(e.pointer, "/friction/mu");
  EXPECT_NE(e.reason.find("is not used by friction law \"exponential_weakening\""),
            std::string::npos);
  e = first_error(toy_job({{"mu_s", 0.5}, {"mu_d", 0.6}}));
  EXPECT_EQ(e.pointer, "/friction/mu_d");
  EXPECT_EQ(e.reason, "mu_d = 0.6 exceeds mu_s = 0.5 (it weakens)");
  EXPECT_EQ(first_error(toy_job({{"D_c", 0.0}})).pointer, "/friction/D_c");
  json profiled = toy_job({{"mu_s", 0.7}, {"mu_d", 0.5}});
  profiled["profiles"] = {{{"x1_min", 2.0}, {"mu_d", 0.8}}};
  e = first_error(profiled);
  EXPECT_EQ(e.pointer, "/profiles/0/mu_d");
  EXPECT_NE(e.reason.find("exceeds mu_s = 0.7 (it weakens)"), std::string::npos);
}

TEST(ToyLaw, ItRunsByBothMethods) {
  for (const char* method : {"fe", "spectral_bi"}) {
    json job = toy_job({{"mu_s", 0.75}, {"mu_d", 0.5}, {"D_c", 0.05}});
    job["method"] = method;
    const ParseResult parsed = parse_job(job);
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front().reason;
    const RunResult r = run_simulation(parsed.spec->params);
    EXPECT_GT(r.metrics.steps, 0) << method;
    EXPECT_GT(r.metrics.max_slip_velocity, 0.0) << method; // the ellipse starts a rupture
    EXPECT_NE(r.metrics.outcome, Outcome::diverged) << method;
  }
}

} // namespace
} // namespace slipfront::api
