// A method is one entry: a toy method registered from this file alone — the finite elements
// under another name, with an options section of its own and no lower elastic solid — is
// known to the job schema (its name, labels, section and the fields it reads), the reader and
// the validation (its section, the fields it refuses), the run (its factory) and the
// documents derived from a job (the counterpart, the presets), with no other edit. Its own
// executable, so that the other tests see the two built-in methods only.
#include "api/job_methods.hpp"
#include "api/job_schema.hpp"
#include "api/job_spec.hpp"
#include "api/presets.hpp"
#include "api/run_job.hpp"
#include "solver/fe/finite_element_method.hpp"
#include "solver/methods.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace slipfront::api {
namespace {

using nlohmann::json;

const Method toy{"toy"};

// The solver's entry: the FE method's factory and estimates under the name "toy".
const MethodEntry& toy_entry() {
  static const MethodEntry entry = [] {
    MethodEntry e = fe::method_entry();
    e.method = toy;
    e.label = "TOY";
    e.heading = "toy FE";
    e.title = "toy finite elements";
    e.description = "the finite elements under another name (a test's)";
    e.run_cost = "as FE";
    e.cost_rank = 2;
    e.counterpart = Method::finite_element;
    e.supports.two_solids = false;
    return e;
  }();
  return entry;
}

// The job's side: its section "toy" holds the FE options.
const MethodOptions& toy_options() {
  static const MethodOptions options{
      toy,
      "toy",
      [](ObjectReader& in, SimulationParams& params) {
        in.number("mesh_damping", params.fe.mesh_damping, closed_interval(0.0, 1.0));
      },
      {{"mesh_damping", "", "the toy's mesh damping"}},
      {{"/toy/mesh_damping",
        [](SimulationParams& p, const SimulationParams& job) {
          p.fe.mesh_damping = job.fe.mesh_damping;
        }}},
      nullptr,
  };
  return options;
}

// Registered before main, as a method outside the solver would be at start-up.
const bool registered = [] {
  register_method(toy_entry());
  register_method_options(toy_options());
  return true;
}();

bool has_error(const ParseResult& parsed, const std::string& pointer, const std::string& part) {
  return std::any_of(parsed.errors.begin(), parsed.errors.end(), [&](const FieldError& e) {
    return e.pointer == pointer && e.reason.find(part) != std::string::npos;
  });
}

TEST(ToyMethod, TheRegistryKnowsIt) {
  ASSERT_TRUE(registered);
  EXPECT_EQ(methods().size(), 3u);
  EXPECT_EQ(&method_entry(toy), &toy_entry());
  EXPECT_EQ(default_method().method, Method::finite_element);
  EXPECT_THROW(register_method(toy_entry()), std::invalid_argument);
}

TEST(ToyMethod, TheSchemaListsItsNameLabelsAndFields) {
  const json schema = job_json_schema();
  const json& method = schema["properties"]["method"];
  EXPECT_EQ(method["enum"], json({"fe", "spectral_bi", "toy"}));
  EXPECT_EQ(method["default"], "fe");
  EXPECT_EQ(method["x-labels"]["toy"]["label"], "TOY");
  EXPECT_EQ(method["x-labels"]["toy"]["heading"], "toy FE");
  EXPECT_EQ(method["x-labels"]["toy"]["title"], "toy finite elements");
  EXPECT_EQ(method["x-labels"]["spectral_bi"]["label"], "BI");
  EXPECT_NE(method["description"].get<std::string>().find("`\"toy\"`: the finite elements"),
            std::string::npos);
  // Its section, read with it only.
  const json& section = schema["properties"]["toy"]["properties"]["mesh_damping"];
  EXPECT_EQ(section["x-methods"], json({"toy"}));
  EXPECT_EQ(section["maximum"], 1.0);
  EXPECT_EQ(section["description"], "the toy's mesh damping");
  // A block: it reads the heights and the safety factor; no elastic lower solid.
  const json& props = schema["properties"];
  EXPECT_EQ(props["geometry"]["properties"]["height"]["x-methods"], json({"fe", "toy"}));
  EXPECT_EQ(props["time"]["properties"]["safety_factor"]["x-methods"], json({"fe", "toy"}));
  EXPECT_EQ(props["material"]["properties"]["density"]["x-methods"],
            json({"fe", "spectral_bi", "toy"}));
  EXPECT_EQ(props["lower"]["properties"]["young_modulus"]["x-methods"],
            json({"fe", "spectral_bi"}));
  EXPECT_EQ(props["preset"]["x-methods"], json({"fe", "spectral_bi", "toy"}));
  // The docs' tables.
  const std::string markdown = job_fields_markdown();
  EXPECT_NE(markdown.find("<!-- generated: job fields toy -->"), std::string::npos);
  EXPECT_NE(markdown.find("| `height` | number or `\"auto\"` | 20 | > 0, or `\"auto\"` | m | h; "),
            std::string::npos);
  EXPECT_NE(markdown.find("(methods `fe`, `toy` only)"), std::string::npos);
}

TEST(ToyMethod, TheReaderAndTheValidationKnowIt) {
  const ParseResult parsed = parse_job({{"method", "toy"}, {"toy", {{"mesh_damping", 0.5}}}});
  ASSERT_TRUE(parsed.ok()) << parsed.errors[0].pointer << " " << parsed.errors[0].reason;
  EXPECT_EQ(parsed.spec->params.method, toy);
  EXPECT_EQ(parsed.spec->params.fe.mesh_damping, 0.5);
  EXPECT_EQ(parsed.spec->canonical["toy"], json({{"mesh_damping", 0.5}}));
  EXPECT_FALSE(parsed.spec->canonical.contains("fe"));
  EXPECT_GT(parsed.spec->memory_estimate_bytes, 0.0);
  // Its section's range; the sections of the other methods; what it does not support.
  EXPECT_TRUE(has_error(parse_job({{"method", "toy"}, {"toy", {{"mesh_damping", 2}}}}),
                        "/toy/mesh_damping", "in [0, 1]"));
  EXPECT_TRUE(has_error(parse_job({{"method", "toy"}, {"fe", json::object()}}), "/fe",
                        "is used only with \"method\": \"fe\" (the method is \"toy\")"));
  EXPECT_TRUE(has_error(parse_job({{"toy", json::object()}}), "/toy",
                        "is used only with \"method\": \"toy\" (the method is \"fe\")"));
  EXPECT_TRUE(has_error(parse_job({{"method", "toy"}, {"lower", {{"solid", "elastic"}}}}),
                        "/lower/solid", "method \"toy\""));
  EXPECT_TRUE(has_error(parse_job({{"method", "toys"}}), "/method",
                        "must be one of \"fe\", \"spectral_bi\", \"toy\""));
}

TEST(ToyMethod, ItRunsAndItsResultSaysSo) {
  const ParseResult parsed = parse_job({{"method", "toy"},
                                        {"geometry", {{"nodes_per_meter", 5}}},
                                        {"time", {{"duration", 1.0}}},
                                        {"threads", 1}});
  ASSERT_TRUE(parsed.ok());
  const JobOutput out = run_job(*parsed.spec, "");
  EXPECT_EQ(out.record.metrics["method"], "toy");
  EXPECT_EQ(out.result.mesh.method, Method::finite_element); // the FE method ran it
  EXPECT_EQ(out.record.metrics["method_description"].get<std::string>().rfind(
                "Q4 2x2 Gauss, lumped mass, central differences; top boundary: traction", 0),
            0u);
}

TEST(ToyMethod, DocumentsDerivedFromAJobKnowIt) {
  // Its counterpart is FE: the toy's section goes, the block's fields stay.
  const json job = {
      {"method", "toy"}, {"toy", {{"mesh_damping", 0.5}}}, {"geometry", {{"height", 4}}}};
  const json fe = counterpart_document(job);
  EXPECT_EQ(fe, json({{"method", "fe"}, {"geometry", {{"height", 4}}}}));
  EXPECT_TRUE(parse_job(fe).ok());
  // A preset's job by every method.
  const json preset = preset_json(presets().front());
  EXPECT_TRUE(preset["specs"].contains("toy"));
  EXPECT_EQ(preset["specs"]["toy"]["method"], "toy");
}

} // namespace
} // namespace slipfront::api
