// libFuzzer target: the reader of run archives (server/core/tar_archive.hpp), the first thing
// POST /imports does with a body. It either refuses with a TarError or returns members whose
// names are safe relative paths, given once, and whose contents lie inside the input.
#include "server/core/tar_archive.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace slipfront::server;
  const std::string_view archive(reinterpret_cast<const char*>(data), size);
  std::vector<TarMember> members;
  try {
    members = read_tar(archive, {16});
  } catch (const TarError&) {
    return 0;
  }
  std::set<std::string> names;
  for (const auto& m : members) {
    const bool inside = m.content.empty() ||
                        (m.content.data() >= archive.data() &&
                         m.content.data() + m.content.size() <= archive.data() + archive.size());
    if (!is_safe_member_name(m.name) || !names.insert(m.name).second || !inside) {
      std::fprintf(stderr, "member %s accepted\n", m.name.c_str());
      std::abort();
    }
  }
  if (members.size() > 16) std::abort();
  return 0;
}
