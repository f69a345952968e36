#include "api/json_parse.hpp"

#include <string>
#include <vector>

namespace slipfront::api {

namespace {

using nlohmann::json;

std::string pointer_token(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

// Builds the document like nlohmann's own DOM parser, keeping the JSON pointer of the value
// being read so that an error can name it, and refusing to open a container deeper than
// the limit (parsing stops there: nothing deeper is ever built).
class BoundedBuilder : public nlohmann::json_sax<json> {
public:
  explicit BoundedBuilder(int max_depth) : max_depth_(max_depth) {}

  bool null() override { return add(json(nullptr)); }
  bool boolean(bool v) override { return add(json(v)); }
  bool number_integer(number_integer_t v) override { return add(json(v)); }
  bool number_unsigned(number_unsigned_t v) override { return add(json(v)); }
  bool number_float(number_float_t v, const string_t&) override { return add(json(v)); }
  bool string(string_t& v) override { return add(json(std::move(v))); }
  bool binary(binary_t& v) override { return add(json::binary(std::move(v))); }

  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool key(string_t& k) override {
    key_ = std::move(k);
    return true;
  }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& ex) override {
    if (ex.id == 406) { // number overflow: the lexer read a number beyond a double
      result_.status = JsonParse::Status::number_out_of_range;
      result_.error = {current_pointer(),
                       "is a number that overflows a double (beyond about ±1.8e308)"};
    } else {
      result_.status = JsonParse::Status::syntax;
      result_.error = {"", "not valid JSON: syntax error at byte " + std::to_string(position)};
    }
    return false;
  }

  JsonParse take() {
    if (result_.ok()) result_.value = std::move(root_);
    return std::move(result_);
  }

private:
  // The pointer of the value about to be added (or of the container being opened).
  std::string current_pointer() const {
    std::string out;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const json* container = stack_[i];
      if (container->is_array()) {
        // An array's current element is its next one, except for enclosing arrays whose
        // last element is the open container.
        std::size_t index = container->size() - (i + 1 < stack_.size() ? 1 : 0);
        out += '/';
        out += std::to_string(index);
      } else {
        out += '/';
        out += pointer_token(i + 1 < stack_.size() ? keys_[i + 1] : key_);
      }
    }
    return out;
  }

  json* place(json&& value) {
    if (stack_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(value));
      return &top.back();
    }
    json& slot = top[key_];
    slot = std::move(value);
    return &slot;
  }

  bool add(json&& value) {
    place(std::move(value));
    return true;
  }

  bool open(json&& container) {
    if (static_cast<int>(stack_.size()) >= max_depth_) {
      result_.status = JsonParse::Status::too_deep;
      result_.error = {current_pointer(), "nests deeper than " + std::to_string(max_depth_) +
                                              " levels of objects and arrays"};
      return false;
    }
    keys_.push_back(key_); // the key this container sits under in its parent
    json* slot = place(std::move(container));
    stack_.push_back(slot);
    return true;
  }

  bool close() {
    stack_.pop_back();
    key_ = keys_.back();
    keys_.pop_back();
    return true;
  }

  int max_depth_;
  json root_;
  std::vector<json*> stack_;
  std::vector<std::string> keys_; // keys_[i]: the key of stack_[i] in its parent
  std::string key_;               // the key of the member being read in the top object
  JsonParse result_;
};

} // namespace

JsonParse parse_bounded_json(std::string_view text, int max_depth) {
  BoundedBuilder builder(max_depth);
  json::sax_parse(text.begin(), text.end(), &builder);
  return builder.take();
}

} // namespace slipfront::api
