// The job schema, defined once: every field of the job JSON with its type, allowed range,
// default, unit, meaning and the methods that use it.
//
// Types, ranges and defaults are not written here: they are recorded from the reader
// itself (api/job_reader.cpp) reading an empty job, once per method. Only the unit and the
// meaning of each field are written here (job_schema.cpp). From the two come the JSON
// Schema served at /api/v1/schema/job.json and used as the OpenAPI component `JobSpec`, and
// the field tables of docs/api-job-spec.md (`slipfront schema --markdown`); tests fail if a
// field lacks its words, or if the docs' tables differ from the generated ones.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace slipfront::api {

struct JobField {
  std::string pointer;              // JSON pointer, e.g. "/friction/L"
  nlohmann::json schema;            // JSON Schema of the value, with "default"
  std::vector<std::string> methods; // the methods that read it, in the registry's order
  std::string unit;                 // SI unit, "" for dimensionless or non-numbers
  std::string meaning;              // one or two sentences
  bool read_by(std::string_view method) const;
};

// Every field, in the reader's order (the default method's fields first).
std::vector<JobField> job_fields();

// The pointers that have words (unit, meaning) in job_schema.cpp: for the test that the
// words and the fields are the same set.
std::vector<std::string> documented_job_pointers();

// The SI unit of a field ("s", "m/s"), "" for a dimensionless or unknown one.
std::string field_unit(const std::string& pointer);

// JSON Schema (draft 2020-12) of the job object; unknown members are not allowed.
nlohmann::json job_json_schema();

// The field tables of docs/api-job-spec.md, one per section, each between the lines
//   <!-- generated: job fields SECTION -->   and   <!-- end generated -->
// (SECTION = "top level", "material", ...).
std::string job_fields_markdown();

} // namespace slipfront::api
