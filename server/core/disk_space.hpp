// The free space of the file system holding a directory (the data dir): what /healthz reports
// and what exports and imports leave above --min-free-bytes (docs/reliability.md "What bounds
// the disk").
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace slipfront::server {

// Bytes an unprivileged writer may still use there (statvfs f_bavail); nullopt if unknown.
std::optional<std::uint64_t> free_disk_bytes(const std::string& dir);

// Whether writing `bytes` more there leaves at least `min_free` bytes free (true when the free
// space cannot be read: the write itself will say).
bool leaves_free(const std::string& dir, std::uint64_t bytes, double min_free);

} // namespace slipfront::server
