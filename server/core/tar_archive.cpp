#include "server/core/tar_archive.hpp"

#include "server/core/storage_error.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <optional>
#include <set>

namespace slipfront::server {

namespace {

constexpr std::size_t block = 512;

// The ustar header fields used here: offset and width in the 512-byte header.
struct Field {
  std::size_t offset, width;
};
constexpr Field name_field{0, 100}, mode_field{100, 8}, uid_field{108, 8}, gid_field{116, 8},
    size_field{124, 12}, mtime_field{136, 12}, checksum_field{148, 8}, type_field{156, 1},
    magic_field{257, 6}, version_field{263, 2}, prefix_field{345, 155};

// An octal number of width - 1 digits and a NUL (the ustar form).
void put_octal(std::array<char, block>& h, Field f, std::uint64_t value) {
  std::string digits(f.width - 1, '0');
  for (std::size_t i = digits.size(); i-- > 0 && value > 0; value >>= 3)
    digits[i] = static_cast<char>('0' + (value & 7));
  if (value != 0) throw TarError("tar: number too large for its field");
  std::memcpy(h.data() + f.offset, digits.data(), digits.size());
}

// The header checksum: the sum of its bytes, the checksum field counted as spaces.
std::uint64_t checksum_of(const char* h) {
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < block; ++i)
    sum += (i >= checksum_field.offset && i < checksum_field.offset + checksum_field.width)
               ? static_cast<unsigned char>(' ')
               : static_cast<unsigned char>(h[i]);
  return sum;
}

std::string field_text(const char* h, Field f) {
  const char* begin = h + f.offset;
  return std::string(begin, std::find(begin, begin + f.width, '\0'));
}

// An octal field (leading spaces or zeros, ended by NUL or space); nullopt if malformed.
std::optional<std::uint64_t> read_octal(const char* h, Field f) {
  std::uint64_t value = 0;
  std::size_t i = 0;
  while (i < f.width && h[f.offset + i] == ' ')
    ++i;
  bool digits = false;
  for (; i < f.width; ++i) {
    const char c = h[f.offset + i];
    if (c == '\0' || c == ' ') break;
    if (c < '0' || c > '7' || value > (std::uint64_t{1} << 60)) return std::nullopt;
    value = value * 8 + static_cast<std::uint64_t>(c - '0');
    digits = true;
  }
  if (!digits) return std::nullopt;
  return value;
}

} // namespace

bool is_safe_member_name(std::string_view name) {
  if (name.empty() || name.size() > 255) return false;
  std::size_t start = 0;
  while (start <= name.size()) {
    auto slash = name.find('/', start);
    if (slash == std::string_view::npos) slash = name.size();
    const auto part = name.substr(start, slash - start);
    if (part.empty() || part == "." || part == "..") return false;
    for (char c : part)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'))
        return false;
    start = slash + 1;
  }
  return true;
}

void TarWriter::write(const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd_, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw StorageError(std::string("tar: write failed: ") + std::strerror(errno), true);
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

std::uint64_t TarWriter::archive_size(const std::vector<std::uint64_t>& member_sizes) {
  std::uint64_t size = 2 * block; // the end blocks
  for (const std::uint64_t n : member_sizes)
    size += block + (n + block - 1) / block * block;
  return size;
}

void TarWriter::pad(std::uint64_t size) {
  static const std::array<char, block> zeros{};
  if (const auto rest = size % block) write(zeros.data(), block - rest);
}

void TarWriter::header(const std::string& name, std::uint64_t size) {
  if (!is_safe_member_name(name) || name.size() > name_field.width)
    throw TarError("tar: member name not writable: " + name);
  std::array<char, block> h{};
  std::memcpy(h.data() + name_field.offset, name.data(), name.size());
  put_octal(h, mode_field, 0644);
  put_octal(h, uid_field, 0);
  put_octal(h, gid_field, 0);
  put_octal(h, size_field, size);
  put_octal(h, mtime_field, 0);
  h[type_field.offset] = '0';
  std::memcpy(h.data() + magic_field.offset, "ustar", 6); // with its NUL
  std::memcpy(h.data() + version_field.offset, "00", 2);
  // Six octal digits, a NUL and a space.
  std::array<char, block> sum{};
  put_octal(sum, {0, 7}, checksum_of(h.data()));
  std::memcpy(h.data() + checksum_field.offset, sum.data(), 6);
  h[checksum_field.offset + 6] = '\0';
  h[checksum_field.offset + 7] = ' ';
  write(h.data(), h.size());
}

void TarWriter::add(const std::string& name, std::string_view content) {
  header(name, content.size());
  write(content.data(), content.size());
  pad(content.size());
}

void TarWriter::add_from(const std::string& name, int source, std::uint64_t size) {
  header(name, size);
  std::vector<char> buffer(1 << 20);
  std::uint64_t left = size;
  while (left > 0) {
    const ssize_t n = ::read(source, buffer.data(), std::min<std::uint64_t>(left, buffer.size()));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw TarError("tar: reading " + name + ": " +
                     (n == 0 ? std::string("file shorter than expected") : std::strerror(errno)));
    write(buffer.data(), static_cast<std::size_t>(n));
    left -= static_cast<std::uint64_t>(n);
  }
  pad(size);
}

void TarWriter::finish() {
  static const std::array<char, 2 * block> zeros{};
  write(zeros.data(), zeros.size());
}

std::vector<TarMember> read_tar(std::string_view archive, const TarLimits& limits) {
  std::vector<TarMember> members;
  std::set<std::string> names;
  std::size_t at = 0;
  const auto is_zero = [&](std::size_t from) {
    return std::all_of(archive.begin() + static_cast<std::ptrdiff_t>(from),
                       archive.begin() + static_cast<std::ptrdiff_t>(from + block),
                       [](char c) { return c == '\0'; });
  };
  while (true) {
    if (archive.size() - at < block)
      throw TarError("the archive ends without its end blocks (truncated?)");
    if (is_zero(at)) break;
    const char* h = archive.data() + at;
    const std::string where = "member " + std::to_string(members.size() + 1);
    const auto stored_sum = read_octal(h, checksum_field);
    if (!stored_sum || *stored_sum != checksum_of(h))
      throw TarError(where + ": header checksum does not match (not a tar file, or damaged)");
    std::string name = field_text(h, name_field);
    if (field_text(h, magic_field) == "ustar") {
      const std::string prefix = field_text(h, prefix_field);
      if (!prefix.empty()) name = prefix + "/" + name;
    }
    const std::string named = where + " (" + name.substr(0, 120) + ")";
    const char type = h[type_field.offset];
    const auto size = read_octal(h, size_field);
    if (!size) throw TarError(named + ": malformed size field");
    if (type == '5' && *size == 0 && name.size() > 1 && name.back() == '/' &&
        is_safe_member_name(name.substr(0, name.size() - 1))) {
      at += block; // a directory (tar adds them when an extracted export is packed again)
      continue;
    }
    if (type != '0' && type != '\0')
      throw TarError(named + ": not a regular file (type '" + std::string(1, type) +
                     "'); an export holds regular files only");
    if (!is_safe_member_name(name))
      throw TarError(named + ": unsafe name: give a relative path of plain components "
                             "([A-Za-z0-9._-], no '..', no leading '/')");
    if (!names.insert(name).second) throw TarError(named + ": given twice");
    if (members.size() + 1 > limits.max_members)
      throw TarError("the archive holds more than " + std::to_string(limits.max_members) +
                     " members");
    at += block;
    if (*size > archive.size() - at) throw TarError(named + ": its content runs past the end");
    members.push_back({name, archive.substr(at, *size)});
    at += (*size + block - 1) / block * block;
    if (at > archive.size()) throw TarError(named + ": its padding runs past the end");
  }
  for (std::size_t i = at; i < archive.size(); ++i)
    if (archive[i] != '\0') throw TarError("bytes after the archive's end blocks");
  return members;
}

} // namespace slipfront::server
