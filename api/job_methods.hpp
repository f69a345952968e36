// The methods in the job JSON, beside the solver's registry (solver/methods.hpp): what the
// api must know of a method that is JSON — the job's section of its options (the section's
// reader, the words of its fields, the fields its time step depends on, the value the spec
// hash leaves out) — one entry per method that has options, in one table; and the method a job
// document names.
#pragma once

#include "api/json_fields.hpp"
#include "solver/methods.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slipfront::api {

// A field of a method's section and its words, as api/job_schema.cpp has them for the others
// (docs/api-job-spec.md shows them beside the type, default and range the reader records).
struct OptionWords {
  const char* name;    // the field in the section: "mesh_damping"
  const char* unit;    // SI unit, "" for dimensionless
  const char* meaning; // one or two sentences
};

// A field a run's time step or step count depends on, and how to give it a job's value: the
// run bounds (api/run_bounds.cpp) name the one that alone moves a bounded quantity furthest.
struct StepInput {
  const char* pointer;
  void (*take)(SimulationParams& params, const SimulationParams& job);
};

struct MethodOptions {
  Method method;
  const char* section; // the job's member that holds its options: "fe", "spectral_bi"
  void (*read)(ObjectReader& section, SimulationParams& params);
  std::vector<OptionWords> words;     // of every field `read` reads
  std::vector<StepInput> step_inputs; // its fields that the time step depends on
  // The section's canonical value that the spec hash leaves out (null: none): the defaults of
  // a section that older records did not have, so that their hashes stay (api/job_spec.hpp).
  nlohmann::json unhashed;
};

// Every method's options, in the order the reader takes their sections (which is the order
// of their errors): the built-in ones, then those registered.
const std::vector<const MethodOptions*>& method_options();

// The options of `method`, or nullptr for a method without any (no section in the job).
const MethodOptions* find_options(Method method);

// Adds the options of a method registered with register_method (solver/methods.hpp), under
// the same conditions: before any job is read, from one thread. Throws std::invalid_argument
// for a method not registered, or one whose options or section are registered already.
void register_method_options(const MethodOptions& options);

// A field's pointer and words.
struct FieldWords {
  std::string pointer, unit, meaning;
};
// The words of "/method" (every method by its name and description) and of each field of
// every method's section.
std::vector<FieldWords> method_field_words();

// The methods whose runs cost less than the default's (cost_rank), the cheapest first (then in
// the registry's order): those an accuracy study on "auto" tries before the default
// (docs/studies-api.md "Accuracy target").
std::vector<const MethodEntry*> cheaper_methods();

// Every method's name, in the registry's order: "fe", "spectral_bi".
std::vector<std::string> method_names();

// "a, b or c": names as a reader says them (the words of an error listing the methods).
std::string or_list(const std::vector<std::string>& names);

// The methods' labels, for the views (the job schema's "x-labels" of "method"): for each
// method by name {label, heading, title, run_cost, cost_rank} (solver/method_entry.hpp).
nlohmann::json method_labels_json();

// The job document by method `to`: "method" set to it, and the fields that the document's own
// method reads and `to` does not dropped (a section of options whole). Unknown members stay
// (the reader reports them); a document that names no known method counts as the default's.
nlohmann::json method_document(const nlohmann::json& job, const MethodEntry& to);

// The name of the method a job document names: its "method" when that is a string, else the
// default method's (an invalid name is the reader's error to report).
std::string method_name_of(const nlohmann::json& job);

} // namespace slipfront::api
