// Bearer tokens of a shared server: a token file of "user:token" lines ('#' comments and
// blank lines allowed). Without a token file, every request is the user "anonymous".
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace slipfront::server {

class TokenTable {
public:
  // Throws with the file name and line number on unreadable files or malformed lines.
  static TokenTable load(const std::string& path);

  // The user of an "Authorization: Bearer <token>" header value; nullopt if unknown.
  std::optional<std::string> user_for_header(std::string_view authorization) const;
  std::size_t size() const { return users_by_token_.size(); }

private:
  std::map<std::string, std::string, std::less<>> users_by_token_; // duplicate check only
  std::vector<std::pair<std::string, std::string>> digests_;       // (SHA-256 hex of token, user)
};

} // namespace slipfront::server
