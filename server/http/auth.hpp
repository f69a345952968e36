// Bearer tokens of a shared server: a token file of "user:token" lines ('#' comments and
// blank lines allowed). Without a token file, every request is the user "anonymous".
// authenticate(): what a handler asks before a request that acts for a user.
#pragma once

#include "server/http/http_types.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace slipfront::server {

class TokenTable {
public:
  TokenTable() = default;
  TokenTable(TokenTable&& other) noexcept : digests_(std::move(other.digests_)) {}
  TokenTable& operator=(TokenTable&& other) noexcept {
    std::lock_guard lock(mutex_);
    digests_ = std::move(other.digests_);
    return *this;
  }

  // Throws with the file name and line number on unreadable files or malformed lines.
  static TokenTable load(const std::string& path);
  // Reads the file again (SIGHUP) and swaps the tokens in at once; on an error it throws and
  // the tokens in use stay. Safe while other threads call user_for_header().
  void reload(const std::string& path);

  // The user of an "Authorization: Bearer <token>" header value; nullopt if unknown.
  std::optional<std::string> user_for_header(std::string_view authorization) const;
  std::size_t size() const;

private:
  using Digests = std::vector<std::pair<std::string, std::string>>; // (SHA-256 hex, user)
  std::shared_ptr<const Digests> snapshot() const;

  mutable std::mutex mutex_;
  std::shared_ptr<const Digests> digests_;
};

// Sets rc.user; a 401 response when a token file is configured (`tokens` set) and the request
// carries no valid bearer token.
std::optional<Response> authenticate(const std::optional<TokenTable>& tokens, RequestContext& rc);

} // namespace slipfront::server
