// The tar files of run exports and imports (docs/server.md "Export and import"): the POSIX
// ustar format (POSIX.1-1988, IEEE Std 1003.1 "pax" description of ustar), regular files
// only. A 512-byte header per member (name, octal size, header checksum), the content padded
// to 512 bytes, two zero blocks at the end. Any tar program reads what TarWriter writes; the
// reader takes only what an export holds and refuses anything else, naming the member.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront::server {

class TarError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Writes members to an open file descriptor (the writer does not own it). A failed write
// throws a StorageError (worth a retry later: the disk may be full).
class TarWriter {
public:
  explicit TarWriter(int fd) : fd_(fd) {}
  // The size of the archive of members of these sizes, end blocks included: what the writer
  // will write, known before a byte is.
  static std::uint64_t archive_size(const std::vector<std::uint64_t>& member_sizes);
  void add(const std::string& name, std::string_view content);
  // `size` bytes read from `source` at its current position.
  void add_from(const std::string& name, int source, std::uint64_t size);
  void finish(); // the two zero blocks

private:
  void header(const std::string& name, std::uint64_t size);
  void write(const char* data, std::size_t size);
  void pad(std::uint64_t size);
  int fd_;
};

struct TarMember {
  std::string name;
  std::string_view content; // into the archive's bytes
};

struct TarLimits {
  std::size_t max_members = 3001;
};

// The members of an archive held in memory, in order. Throws TarError naming the member and
// the reason for: a header whose checksum does not match, a member that is not a regular
// file (links, devices, directories), a name that is absolute, holds "..", "." or an empty
// component, a backslash or a character outside [A-Za-z0-9._/-], a name given twice, a size
// past the end, more than `max_members` members, or bytes after the end blocks that are not
// zero.
std::vector<TarMember> read_tar(std::string_view archive, const TarLimits& limits = {});

// Whether `name` is a relative path of plain components ([A-Za-z0-9._-], not "." or "..").
bool is_safe_member_name(std::string_view name);

} // namespace slipfront::server
