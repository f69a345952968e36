// The tar files of run archives (server/core/tar_archive.hpp): what TarWriter writes reads
// back member for member, and the reader refuses what an export never holds, naming it.
#include "server/core/tar_archive.hpp"

#include <gtest/gtest.h>

#include <stdio.h>
#include <unistd.h>

#include <array>
#include <cstring>
#include <string>

namespace slipfront::server {
namespace {

// The bytes TarWriter writes for `members` (name, content).
std::string written(const std::vector<std::pair<std::string, std::string>>& members) {
  FILE* file = ::tmpfile();
  EXPECT_NE(file, nullptr);
  const int fd = ::fileno(file);
  TarWriter tar(fd);
  for (const auto& [name, content] : members)
    tar.add(name, content);
  tar.finish();
  std::string bytes;
  ::lseek(fd, 0, SEEK_SET);
  std::array<char, 4096> buffer{};
  ssize_t n = 0;
  while ((n = ::read(fd, buffer.data(), buffer.size())) > 0)
    bytes.append(buffer.data(), static_cast<std::size_t>(n));
  ::fclose(file);
  return bytes;
}

// The first header's checksum made right again after a change.
std::string with_checksum(std::string archive) {
  std::memset(archive.data() + 148, ' ', 8);
  unsigned sum = 0;
  for (std::size_t i = 0; i < 512; ++i)
    sum += static_cast<unsigned char>(archive[i]);
  std::snprintf(archive.data() + 148, 8, "%06o", sum);
  return archive;
}

// An archive whose first member is named `name`.
std::string renamed(std::string archive, const std::string& name) {
  std::memset(archive.data(), 0, 100);
  std::memcpy(archive.data(), name.data(), std::min<std::size_t>(name.size(), 100));
  return with_checksum(archive);
}

std::string refusal(const std::string& archive) {
  try {
    read_tar(archive);
  } catch (const TarError& e) {
    return e.what();
  }
  return "";
}

TEST(TarArchive, ReadsBackWhatItWrites) {
  const std::string big(1500, 'x'); // three blocks, padded
  auto archive = written({{"manifest.json", "{}"}, {"runs/a/result.h5", big}, {"empty", ""}});
  EXPECT_EQ(archive.size() % 512, 0u);
  auto members = read_tar(archive);
  ASSERT_EQ(members.size(), 3u);
  EXPECT_EQ(members[0].name, "manifest.json");
  EXPECT_EQ(members[0].content, "{}");
  EXPECT_EQ(members[1].name, "runs/a/result.h5");
  EXPECT_EQ(members[1].content, big);
  EXPECT_EQ(members[2].content, "");
}

TEST(TarArchive, RefusesUnsafeNames) {
  const auto archive = written({{"manifest.json", "{}"}});
  for (const std::string name :
       {"../evil", "runs/../../evil", "/etc/passwd", "a//b", "./a", "a\\b", "a b", "runs/.."}) {
    EXPECT_NE(refusal(renamed(archive, name)).find("unsafe name"), std::string::npos) << name;
  }
  EXPECT_THROW(TarWriter(-1).add("../evil", "x"), TarError);
}

TEST(TarArchive, RefusesLinksDamageAndTruncation) {
  auto archive = written({{"manifest.json", "{}"}, {"runs/x", "abc"}});
  std::string link = archive;
  link[156] = '2'; // a symbolic link
  EXPECT_NE(refusal(link).find("checksum"), std::string::npos);
  EXPECT_NE(refusal(with_checksum(link)).find("not a regular file"), std::string::npos);
  std::string flipped = archive;
  flipped[10] ^= 1;
  EXPECT_NE(refusal(flipped).find("member 1"), std::string::npos);
  EXPECT_NE(refusal(archive.substr(0, 700)).find("past the end"), std::string::npos);
  EXPECT_NE(refusal(archive.substr(0, 1024)).find("end blocks"), std::string::npos);
  auto twice = written({{"a", "1"}, {"a", "2"}});
  EXPECT_NE(refusal(twice).find("given twice"), std::string::npos);
  auto many = written({{"a", ""}, {"b", ""}, {"c", ""}});
  EXPECT_THROW(read_tar(many, {2}), TarError);
  EXPECT_NE(refusal(archive + "junk").find("after the archive"), std::string::npos);
}

} // namespace
} // namespace slipfront::server
