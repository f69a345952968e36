#include "api/run_annotations.hpp"

#include "api/free_text.hpp"
#include "api/json_fields.hpp"

namespace slipfront::api {

AnnotationsParse parse_annotations(const nlohmann::json& body) {
  AnnotationsParse out;
  if (!body.is_object()) {
    out.errors.push_back({"", "must be a JSON object with \"tags\" and/or \"note\""});
    return out;
  }
  ObjectReader in(&body, "", out.errors);
  if (body.contains("tags")) {
    std::vector<std::string> tags;
    const std::size_t before = out.errors.size();
    in.string_list("tags", tags, max_tags, max_tag_length);
    if (out.errors.size() == before) out.annotations.tags = std::move(tags);
  }
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
  if (out.errors.empty() && !out.annotations.tags && !out.annotations.note)
    out.errors.push_back({"", "give \"tags\" (an array of strings) and/or \"note\" (a string)"});
  return out;
}

} // namespace slipfront::api
