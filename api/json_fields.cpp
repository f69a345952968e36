#include "api/json_fields.hpp"

#include "api/free_text.hpp"

#include <cmath>
#include <sstream>

namespace slipfront::api {

namespace {

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

} // namespace

bool Interval::contains(double value) const {
  if (!std::isfinite(value)) return false;
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

std::string Interval::describe() const {
  const bool has_lo = std::isfinite(lo);
  const bool has_hi = std::isfinite(hi);
  if (has_lo && has_hi) {
    return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
           format_number(hi) + (hi_open ? ")" : "]");
  }
  if (has_lo) return (lo_open ? "> " : ">= ") + format_number(lo);
  if (has_hi) return (hi_open ? "< " : "<= ") + format_number(hi);
  return "";
}

Interval any_finite() {
  return {};
}
Interval positive() {
  return {.lo = 0.0, .lo_open = true};
}
Interval negative() {
  return {.hi = 0.0, .hi_open = true};
}
Interval non_negative() {
  return {.lo = 0.0};
}
Interval open_interval(double lo, double hi) {
  return {.lo = lo, .hi = hi, .lo_open = true, .hi_open = true};
}
Interval closed_interval(double lo, double hi) {
  return {.lo = lo, .hi = hi};
}
Interval left_open(double lo, double hi) {
  return {.lo = lo, .hi = hi, .lo_open = true};
}

std::string describe_value(const nlohmann::json& value) {
  if (value.is_object()) return "an object";
  if (value.is_array()) return "an array";
  if (value.is_number_float() && !std::isfinite(value.get<double>())) return "a non-finite number";
  // An error message must not fail: a string is cut at a character boundary (cutting a
  // UTF-8 sequence made dump() throw, and the request a 500), and anything that still is not
  // UTF-8 is shown with replacement characters.
  constexpr auto replace = nlohmann::json::error_handler_t::replace;
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    constexpr std::size_t shown = 40;
    if (text.size() > shown)
      return nlohmann::json(std::string(text_prefix(text, shown))).dump(-1, ' ', false, replace) +
             "...";
  }
  return value.dump(-1, ' ', false, replace);
}

std::string_view text_prefix(std::string_view text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return text;
  std::size_t shown = max_bytes;
  while (shown > 0 && (static_cast<unsigned char>(text[shown]) & 0xC0) == 0x80)
    --shown; // text[shown] continues a character: cut before that character
  return text.substr(0, shown);
}

std::string cut_text(std::string_view text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return std::string(text);
  return std::string(text_prefix(text, max_bytes > 3 ? max_bytes - 3 : 0)) + "...";
}

std::string child_pointer(const std::string& parent, const std::string& key) {
  std::string escaped;
  for (char c : key) {
    if (c == '~') {
      escaped += "~0";
    } else if (c == '/') {
      escaped += "~1";
    } else {
      escaped += c;
    }
  }
  return parent + "/" + escaped;
}

ObjectReader::ObjectReader(const nlohmann::json* object, std::string pointer,
                           std::vector<FieldError>& errors, SchemaRecorder* recorder)
    : object_(object), pointer_(std::move(pointer)), errors_(errors), recorder_(recorder) {}

void ObjectReader::record(const std::string& key, nlohmann::json schema) {
  if (recorder_ == nullptr) return;
  if (canonical_.contains(key) && !schema.contains("default")) schema["default"] = canonical_[key];
  recorder_->push_back({pointer(key), std::move(schema)});
}

void ObjectReader::describe(const std::string& key, nlohmann::json schema) {
  record(key, std::move(schema));
}

void ObjectReader::reject(const std::string& key, const std::string& why, nlohmann::json schema) {
  if (raw(key) != nullptr) error(key, why);
  record(key, std::move(schema));
}

void ObjectReader::error_here(std::string reason) {
  errors_.push_back({pointer_, std::move(reason)});
}

nlohmann::json number_schema(const Interval& allowed) {
  nlohmann::json schema = {{"type", "number"}};
  if (std::isfinite(allowed.lo))
    schema[allowed.lo_open ? "exclusiveMinimum" : "minimum"] = allowed.lo;
  if (std::isfinite(allowed.hi))
    schema[allowed.hi_open ? "exclusiveMaximum" : "maximum"] = allowed.hi;
  return schema;
}

const nlohmann::json* ObjectReader::raw(const std::string& key) {
  known_.insert(key);
  if (object_ == nullptr) return nullptr;
  const auto found = object_->find(key);
  return found == object_->end() ? nullptr : &*found;
}

void ObjectReader::set_canonical(const std::string& key, nlohmann::json value) {
  canonical_[key] = std::move(value);
}

void ObjectReader::error(const std::string& key, std::string reason) {
  errors_.push_back({pointer(key), std::move(reason)});
}

void ObjectReader::number(const std::string& key, double& target, const Interval& allowed) {
  if (const nlohmann::json* member = raw(key)) {
    if (member->is_number() && allowed.contains(member->get<double>())) {
      target = member->get<double>();
    } else {
      const std::string range = allowed.describe();
      error(key, "must be a finite number" + (range.empty() ? "" : " " + range) + ", got " +
                     describe_value(*member));
    }
  }
  set_canonical(key, target);
  record(key, number_schema(allowed));
}

void ObjectReader::integer(const std::string& key, int& target, int lo, int hi) {
  if (const nlohmann::json* member = raw(key)) {
    // 3.0 is accepted as 3: clients that write every number as a float stay welcome.
    const bool integral = member->is_number_integer() ||
                          (member->is_number_float() && std::isfinite(member->get<double>()) &&
                           std::floor(member->get<double>()) == member->get<double>());
    if (integral && member->get<double>() >= lo && member->get<double>() <= hi) {
      target = static_cast<int>(member->get<double>());
    } else {
      error(key, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "], got " + describe_value(*member));
    }
  }
  set_canonical(key, target);
  record(key, {{"type", "integer"}, {"minimum", lo}, {"maximum", hi}});
}

void ObjectReader::boolean(const std::string& key, bool& target) {
  if (const nlohmann::json* member = raw(key)) {
    if (member->is_boolean()) {
      target = member->get<bool>();
    } else {
      error(key, "must be true or false, got " + describe_value(*member));
    }
  }
  set_canonical(key, target);
  record(key, {{"type", "boolean"}});
}

void ObjectReader::string(const std::string& key, std::string& target, std::size_t max_length) {
  if (const nlohmann::json* member = raw(key)) {
    if (member->is_string() && member->get_ref<const std::string&>().size() <= max_length) {
      if (auto reason = free_text_error(member->get_ref<const std::string&>()))
        error(key, std::move(*reason));
      else
        target = member->get<std::string>();
    } else {
      error(key, "must be a string of at most " + std::to_string(max_length) + " characters, got " +
                     describe_value(*member));
    }
  }
  set_canonical(key, target);
  record(key, {{"type", "string"}, {"maxLength", max_length}, {"pattern", free_text_pattern}});
}

void ObjectReader::string_list(const std::string& key, std::vector<std::string>& target,
                               std::size_t max_items, std::size_t max_length) {
  const std::string expected = "must be an array of at most " + std::to_string(max_items) +
                               " non-empty strings of at most " + std::to_string(max_length) +
                               " characters";
  if (const nlohmann::json* member = raw(key)) {
    if (!member->is_array() || member->size() > max_items) {
      error(key, expected + ", got " + describe_value(*member));
    } else {
      std::vector<std::string> items;
      bool valid = true;
      for (std::size_t i = 0; i < member->size(); ++i) {
        const nlohmann::json& item = (*member)[i];
        const std::string at = pointer(key) + "/" + std::to_string(i);
        if (item.is_string() && !item.get_ref<const std::string&>().empty() &&
            item.get_ref<const std::string&>().size() <= max_length) {
          if (auto reason = free_text_error(item.get_ref<const std::string&>())) {
            valid = false;
            errors_.push_back({at, std::move(*reason)});
          } else {
            items.push_back(item.get<std::string>());
          }
        } else {
          valid = false;
          errors_.push_back({at, "must be a non-empty string of at most " +
                                     std::to_string(max_length) + " characters, got " +
                                     describe_value(item)});
        }
      }
      if (valid) target = std::move(items);
    }
  }
  set_canonical(key, target);
  record(key, {{"type", "array"},
               {"maxItems", max_items},
               {"items",
                {{"type", "string"},
                 {"minLength", 1},
                 {"maxLength", max_length},
                 {"pattern", free_text_pattern}}}});
}

void ObjectReader::number_list(const std::string& key, std::vector<double>& target,
                               std::size_t max_items, const Interval& allowed) {
  const std::string range = allowed.describe();
  const std::string each = "finite number" + (range.empty() ? "" : " " + range);
  if (const nlohmann::json* member = raw(key)) {
    if (!member->is_array() || member->size() > max_items) {
      const std::string got =
          member->is_array() ? std::to_string(member->size()) + " items" : describe_value(*member);
      error(key,
            "must be an array of at most " + std::to_string(max_items) + " numbers, got " + got);
    } else {
      std::vector<double> items;
      for (std::size_t i = 0; i < member->size(); ++i) {
        const nlohmann::json& item = (*member)[i];
        if (item.is_number() && allowed.contains(item.get<double>()))
          items.push_back(item.get<double>());
        else
          errors_.push_back({pointer(key) + "/" + std::to_string(i),
                             "must be a " + each + ", got " + describe_value(item)});
      }
      if (items.size() == member->size()) target = std::move(items);
    }
  }
  set_canonical(key, target);
  record(key, {{"type", "array"}, {"maxItems", max_items}, {"items", number_schema(allowed)}});
}

void ObjectReader::object(const std::string& key, const std::function<void(ObjectReader&)>& read) {
  const nlohmann::json* member = raw(key);
  if (member != nullptr && !member->is_object()) {
    error(key, "must be an object, got " + describe_value(*member));
    member = nullptr;
  }
  ObjectReader child(member, pointer(key), errors_, recorder_);
  read(child);
  child.finish();
  set_canonical(key, child.canonical());
}

void ObjectReader::object_list(const std::string& key, std::size_t max_items,
                               const std::function<void(ObjectReader&, std::size_t)>& read) {
  const nlohmann::json* member = raw(key);
  if (recorder_ != nullptr) {
    record(key, {{"type", "array"},
                 {"maxItems", max_items},
                 {"items", {{"type", "object"}}},
                 {"default", nlohmann::json::array()}});
    ObjectReader item(nullptr, pointer(key) + "/*", errors_, recorder_); // the items' fields
    read(item, 0);
  }
  if (member == nullptr) return;
  if (!member->is_array() || member->size() > max_items) {
    error(key, "must be an array of at most " + std::to_string(max_items) + " objects, got " +
                   describe_value(*member));
    return;
  }
  nlohmann::json items = nlohmann::json::array();
  for (std::size_t i = 0; i < member->size(); ++i) {
    const nlohmann::json& element = (*member)[i];
    const std::string at = pointer(key) + "/" + std::to_string(i);
    if (!element.is_object()) {
      errors_.push_back({at, "must be an object, got " + describe_value(element)});
      continue;
    }
    ObjectReader item(&element, at, errors_, nullptr);
    read(item, i);
    item.finish();
    items.push_back(item.canonical());
  }
  if (!items.empty()) set_canonical(key, std::move(items));
}

void ObjectReader::optional_number(const std::string& key, std::optional<double>& target,
                                   const Interval& allowed) {
  if (const nlohmann::json* member = raw(key)) {
    double value = 0;
    number(key, value, allowed);
    if (member->is_number() && allowed.contains(member->get<double>()))
      target = value;
    else
      canonical_.erase(key);
    return;
  }
  record(key, number_schema(allowed));
}

std::vector<std::string>
ObjectReader::present_fields_of(const std::function<void(ObjectReader&)>& read) {
  std::vector<FieldError> dropped;
  ObjectReader probe(object_, pointer_, dropped);
  read(probe);
  std::vector<std::string> present;
  for (const std::string& key : probe.known_)
    if (raw(key) != nullptr) present.push_back(key);
  return present;
}

void ObjectReader::finish() {
  if (object_ == nullptr) return;
  std::string known_list;
  for (const auto& name : known_)
    known_list += (known_list.empty() ? "" : ", ") + name;
  for (const auto& [key, value] : object_->items()) {
    if (!known_.contains(key)) error(key, "unknown field (known here: " + known_list + ")");
  }
}

std::string ObjectReader::choice_error(const std::vector<std::string>& names,
                                       const nlohmann::json& got) {
  std::string list;
  for (const auto& name : names)
    list += (list.empty() ? "\"" : ", \"") + name + "\"";
  return "must be one of " + list + ", got " + describe_value(got);
}

} // namespace slipfront::api
