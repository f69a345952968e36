#include "server/http/auth.hpp"

#include "api/job_spec.hpp"
#include "server/core/file_descriptor.hpp"
#include "server/http/responses.hpp"

#include <sstream>
#include <stdexcept>

namespace slipfront::server {

namespace {
constexpr std::size_t max_token_file_bytes = 1 << 20;

std::string trim(const std::string& s) {
  auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}
} // namespace

TokenTable TokenTable::load(const std::string& path) {
  // A regular file only, opened without blocking: a FIFO in its place is refused at once.
  std::string text;
  try {
    text = read_regular_file(path, max_token_file_bytes);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("cannot read token file ") + e.what());
  }
  std::istringstream in(text);
  std::map<std::string, std::string> users_by_token;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    auto colon = line.find(':');
    std::string where = path + ":" + std::to_string(number);
    if (colon == std::string::npos || colon == 0 || colon + 1 == line.size())
      throw std::runtime_error(where + ": expected \"user:token\"");
    std::string user = trim(line.substr(0, colon)), token = trim(line.substr(colon + 1));
    if (token.size() < 8) throw std::runtime_error(where + ": token shorter than 8 characters");
    if (!users_by_token.emplace(token, user).second)
      throw std::runtime_error(where + ": token already given to another user");
  }
  if (users_by_token.empty()) throw std::runtime_error("token file " + path + " has no tokens");
  auto digests = std::make_shared<Digests>();
  for (const auto& [token, user] : users_by_token)
    digests->emplace_back(api::sha256_hex(token), user);
  TokenTable table;
  table.digests_ = std::move(digests);
  return table;
}

void TokenTable::reload(const std::string& path) {
  TokenTable fresh = load(path);
  std::lock_guard lock(mutex_);
  digests_ = std::move(fresh.digests_);
}

std::shared_ptr<const TokenTable::Digests> TokenTable::snapshot() const {
  std::lock_guard lock(mutex_);
  return digests_;
}

std::size_t TokenTable::size() const {
  auto digests = snapshot();
  return digests ? digests->size() : 0;
}

std::optional<std::string> TokenTable::user_for_header(std::string_view authorization) const {
  constexpr std::string_view scheme = "Bearer ";
  if (authorization.size() <= scheme.size()) return std::nullopt;
  for (std::size_t i = 0; i < scheme.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(authorization[i])) !=
        std::tolower(static_cast<unsigned char>(scheme[i])))
      return std::nullopt;
  auto token = authorization.substr(scheme.size());
  while (!token.empty() && token.front() == ' ')
    token.remove_prefix(1);
  // Compared in constant time: the digests of every token, each byte, whatever matches, so
  // that the answer's timing tells nothing of how much of a guess was right.
  const std::string digest = api::sha256_hex(std::string(token));
  const std::string* found = nullptr;
  const auto digests = snapshot();
  if (!digests) return std::nullopt;
  for (const auto& [stored, user] : *digests) {
    unsigned char diff = 0;
    for (std::size_t i = 0; i < digest.size(); ++i)
      diff |= static_cast<unsigned char>(stored[i] ^ digest[i]);
    if (diff == 0) found = &user;
  }
  if (!found) return std::nullopt;
  return *found;
}

std::optional<Response> authenticate(const std::optional<TokenTable>& tokens, RequestContext& rc) {
  if (!tokens) {
    rc.user = "anonymous";
    return std::nullopt;
  }
  auto header = rc.request[http::field::authorization];
  auto user = tokens->user_for_header(header);
  if (!user) {
    auto res = problem_response(rc.request, http::status::unauthorized,
                                header.empty() ? "this server needs a bearer token "
                                                 "(Authorization: Bearer <token>)"
                                               : "unknown bearer token");
    res.set(http::field::www_authenticate, "Bearer realm=\"slipfront\"");
    return Response(std::move(res));
  }
  rc.user = *user;
  return std::nullopt;
}

} // namespace slipfront::server
