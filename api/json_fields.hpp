// Reading one object of the job JSON field by field.
//
// Each call reads one member: if it is absent the target keeps its default, if it is
// present and valid the target takes its value, otherwise a FieldError naming the member's
// JSON pointer, what was expected and what was got is recorded. Every value read (or
// defaulted) is copied into the canonical object, and members nobody asked for are
// reported as unknown when the reader finishes.
#pragma once

#include "api/job_spec.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace slipfront::api {

// An allowed range of a number: each bound is absent (infinite), closed or open.
struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double value) const;
  std::string describe() const; // e.g. "> 0", "in (0, 0.5)", "" for every finite number
};

Interval any_finite();
Interval positive();                            // > 0
Interval negative();                            // < 0
Interval non_negative();                        // >= 0
Interval open_interval(double lo, double hi);   // (lo, hi)
Interval closed_interval(double lo, double hi); // [lo, hi]
Interval left_open(double lo, double hi);       // (lo, hi]

// The JSON Schema of a number in `allowed` (an absent bound is left out).
nlohmann::json number_schema(const Interval& allowed);

// A short description of a JSON value for error messages: 0.5, "abc", true, null, an object.
std::string describe_value(const nlohmann::json& value);
// The first bytes of `text`, at most `max_bytes`, cut at a character boundary (UTF-8): a
// value echoed in an error stays short and its JSON dump cannot fail.
std::string_view text_prefix(std::string_view text, std::size_t max_bytes);
// The same with "..." when cut, at most `max_bytes` in all.
std::string cut_text(std::string_view text, std::size_t max_bytes);

// The JSON pointer of `key` inside the object at `parent` (escapes '~' and '/').
std::string child_pointer(const std::string& parent, const std::string& key);

// What a reader asks for, as JSON Schema fragments by JSON pointer, in reading order: the
// job schema (api/job_schema.hpp) is recorded from the reader itself, so that the types,
// ranges and defaults are written once, in api/job_reader.cpp.
struct FieldSchemaRecord {
  std::string pointer;
  nlohmann::json schema; // type, bounds, enum; "default": the value the reader kept
};
using SchemaRecorder = std::vector<FieldSchemaRecord>;

class ObjectReader {
public:
  // `object` may be null: every field then keeps its default. With a recorder, every field
  // read also appends its schema to it.
  ObjectReader(const nlohmann::json* object, std::string pointer, std::vector<FieldError>& errors,
               SchemaRecorder* recorder = nullptr);

  void number(const std::string& key, double& target, const Interval& allowed);
  void integer(const std::string& key, int& target, int lo, int hi);
  void boolean(const std::string& key, bool& target);
  // Free text (api/free_text.hpp): at most `max_length` bytes, no control characters.
  void string(const std::string& key, std::string& target, std::size_t max_length);
  void string_list(const std::string& key, std::vector<std::string>& target, std::size_t max_items,
                   std::size_t max_length);
  // An array of at most `max_items` numbers, each in `allowed` (errors name /key/i).
  void number_list(const std::string& key, std::vector<double>& target, std::size_t max_items,
                   const Interval& allowed);

  template <class Enum>
  void choice(const std::string& key, Enum& target,
              const std::vector<std::pair<std::string, Enum>>& names);

  // A nested object, read by `read`; its canonical form becomes a member of this one.
  void object(const std::string& key, const std::function<void(ObjectReader&)>& read);
  // An array of at most `max_items` objects, each read by `read` with its index. Its
  // canonical form is the array of theirs, left out when the array is empty or absent (a
  // job without it keeps the hash it had before the field existed). A recorder sees the
  // array and, as "<array>/*/<field>", the fields of its items.
  void object_list(const std::string& key, std::size_t max_items,
                   const std::function<void(ObjectReader&, std::size_t)>& read);
  // An optional number without a default: set (and in the canonical form) only if given.
  void optional_number(const std::string& key, std::optional<double>& target,
                       const Interval& allowed);

  // For fields with a shape of their own: the raw member (null if absent), marked as known.
  const nlohmann::json* raw(const std::string& key);
  void set_canonical(const std::string& key, nlohmann::json value);
  // Leaves `key` out of the canonical form (a section at its defaults that must not change
  // the canonical text, and so the hashes, of the specs written before it existed).
  void omit_canonical(const std::string& key) { canonical_.erase(key); }
  void error(const std::string& key, std::string reason);
  // For a field read through raw(): its schema, when a recorder listens (with "default"
  // if the schema has none and the canonical form holds the key).
  void describe(const std::string& key, nlohmann::json schema);
  // A field this job has no use for (another law's parameter, the other form of a
  // material): an error saying `why` if it is given. The schema still lists it: `schema`
  // is recorded (with its default) when a recorder listens.
  void reject(const std::string& key, const std::string& why, nlohmann::json schema);
  // Leaves `key` out of the canonical form (a field at a default that must not enter it).
  void drop_canonical(const std::string& key) { canonical_.erase(key); }
  // An error about this object itself (its pointer).
  void error_here(std::string reason);
  bool present() const { return object_ != nullptr; }        // the object was given
  std::size_t error_count() const { return errors_.size(); } // of the whole document so far
  std::string pointer(const std::string& key) const { return child_pointer(pointer_, key); }

  // The members of this object that `read` would read, marked as known; their values and
  // errors are dropped. For fields that another field's choice rules out: the caller then
  // names each one given in an error of its own.
  std::vector<std::string> present_fields_of(const std::function<void(ObjectReader&)>& read);

  // Records every member that was never asked for as an unknown field.
  void finish();
  const nlohmann::json& canonical() const { return canonical_; }

private:
  std::string choice_error(const std::vector<std::string>& names, const nlohmann::json& got);
  // Records `schema` for `key` with the canonical value as its default.
  void record(const std::string& key, nlohmann::json schema);

  const nlohmann::json* object_;
  std::string pointer_;
  std::vector<FieldError>& errors_;
  SchemaRecorder* recorder_;
  std::set<std::string> known_;
  nlohmann::json canonical_ = nlohmann::json::object();
};

template <class Enum>
void ObjectReader::choice(const std::string& key, Enum& target,
                          const std::vector<std::pair<std::string, Enum>>& names) {
  std::vector<std::string> spellings;
  std::string current;
  for (const auto& [name, value] : names) {
    spellings.push_back(name);
    if (value == target) current = name;
  }
  const nlohmann::json* member = raw(key);
  if (member != nullptr) {
    bool matched = false;
    if (member->is_string()) {
      for (const auto& [name, value] : names) {
        if (*member == name) {
          target = value;
          current = name;
          matched = true;
        }
      }
    }
    if (!matched) error(key, choice_error(spellings, *member));
  }
  set_canonical(key, current);
  record(key, {{"type", "string"}, {"enum", spellings}});
}

} // namespace slipfront::api
