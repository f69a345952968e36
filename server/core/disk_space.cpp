#include "server/core/disk_space.hpp"

#include <sys/statvfs.h>

namespace slipfront::server {

std::optional<std::uint64_t> free_disk_bytes(const std::string& dir) {
  struct statvfs fs {};
  if (::statvfs(dir.empty() ? "." : dir.c_str(), &fs) != 0) return std::nullopt;
  return static_cast<std::uint64_t>(fs.f_bavail) * static_cast<std::uint64_t>(fs.f_frsize);
}

bool leaves_free(const std::string& dir, std::uint64_t bytes, double min_free) {
  const auto free = free_disk_bytes(dir);
  if (!free) return true;
  return static_cast<double>(*free) - static_cast<double>(bytes) >= min_free;
}

} // namespace slipfront::server
