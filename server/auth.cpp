#include "server/auth.hpp"

#include <fstream>
#include <stdexcept>

namespace slipfront::server {

namespace {
std::string trim(const std::string& s) {
  auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}
} // namespace

TokenTable TokenTable::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read token file " + path);
  TokenTable table;
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
    if (!table.users_by_token_.emplace(token, user).second)
      throw std::runtime_error(where + ": token already given to another user");
  }
  if (table.users_by_token_.empty())
    throw std::runtime_error("token file " + path + " has no tokens");
  return table;
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
  auto it = users_by_token_.find(token);
  if (it == users_by_token_.end()) return std::nullopt;
  return it->second;
}

} // namespace slipfront::server
