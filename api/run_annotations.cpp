#include "api/run_annotations.hpp"

#include "api/free_text.hpp"
#include "api/json_fields.hpp"

#include <algorithm>

namespace slipfront::api {

namespace {

bool holds(const std::vector<std::string>& list, const std::string& tag) {
  return std::find(list.begin(), list.end(), tag) != list.end();
}

// Reads the list `key` of tags, if given; false when it is given and invalid.
bool read_tags(ObjectReader& in, std::vector<FieldError>& errors, const std::string& key,
               std::optional<std::vector<std::string>>& target) {
  if (!in.raw(key)) return true;
  std::vector<std::string> tags;
  const std::size_t before = errors.size();
  in.string_list(key, tags, max_tags, max_tag_length);
  if (errors.size() != before) return false;
  target = std::move(tags);
  return true;
}

} // namespace

TagsAfter apply_tag_change(const std::vector<std::string>& tags, const TagChange& change) {
  TagsAfter out;
  if (change.replace) {
    out.tags = *change.replace;
    return out;
  }
  for (const auto& tag : tags)
    if (!holds(change.remove, tag) && !holds(out.tags, tag)) out.tags.push_back(tag);
  for (const auto& tag : change.add)
    if (!holds(out.tags, tag)) out.tags.push_back(tag);
  if (out.tags.size() > max_tags)
    out.error = FieldError{"/tags_add", "would leave " + std::to_string(out.tags.size()) +
                                            " tags, at most " + std::to_string(max_tags) +
                                            " are kept: remove some (tags_remove)"};
  return out;
}

AnnotationsParse parse_annotations(const nlohmann::json& body) {
  AnnotationsParse out;
  if (!body.is_object()) {
    out.errors.push_back(
        {"", "must be a JSON object with \"tags\" (or \"tags_add\", \"tags_remove\") and/or "
             "\"note\""});
    return out;
  }
  ObjectReader in(&body, "", out.errors);
  TagChange& change = out.annotations.tags;
  std::optional<std::vector<std::string>> add, remove;
  read_tags(in, out.errors, "tags", change.replace);
  const bool add_ok = read_tags(in, out.errors, "tags_add", add);
  const bool remove_ok = read_tags(in, out.errors, "tags_remove", remove);
  if (body.contains("tags") && (body.contains("tags_add") || body.contains("tags_remove")))
    in.error(body.contains("tags_add") ? "tags_add" : "tags_remove",
             "cannot go with \"tags\", which replaces every tag: give \"tags\" alone, or "
             "\"tags_add\" and \"tags_remove\"");
  if (add_ok && remove_ok && add && remove)
    for (std::size_t i = 0; i < remove->size(); ++i)
      if (holds(*add, (*remove)[i]))
        out.errors.push_back({"/tags_remove/" + std::to_string(i),
                              "\"" + (*remove)[i] + "\" is also in tags_add: add it or remove it"});
  change.add = add.value_or(std::vector<std::string>());
  change.remove = remove.value_or(std::vector<std::string>());
  if (const nlohmann::json* note = in.raw("note")) {
    if (!note->is_string() || note->get_ref<const std::string&>().size() > max_note_length) {
      in.error("note", "must be a string of at most " + std::to_string(max_note_length) +
                           " bytes, got " + describe_value(*note));
    } else {
      // A note may span lines: newlines and tabs are allowed, other control characters not.
      std::string text = note->get<std::string>();
      std::string checked = text;
      for (char& c : checked)
        if (c == '\n' || c == '\t') c = ' ';
      if (auto reason = free_text_error(checked))
        in.error("note", *reason);
      else
        out.annotations.note = std::move(text);
    }
  }
  in.finish();
  if (out.errors.empty() && !body.contains("tags") && !body.contains("tags_add") &&
      !body.contains("tags_remove") && !out.annotations.note)
    out.errors.push_back({"", "give \"tags\" (replaces every tag), \"tags_add\" and/or "
                              "\"tags_remove\" (arrays of strings), and/or \"note\" (a string)"});
  return out;
}

} // namespace slipfront::api
