#include "server/services/result_files.hpp"

#include "api/job_spec.hpp" // sha256_descriptor

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace slipfront::server {

std::string ResultFiles::absolute_path(const api::ResultFile& stored) const {
  return (data_dir_.empty() ? std::string(".") : data_dir_) + "/" + stored.path;
}

ResultFiles::Identity ResultFiles::identity_of(const struct stat& st) {
  constexpr std::int64_t ns = 1000000000;
  return {st.st_dev, st.st_ino, st.st_size, st.st_mtim.tv_sec * ns + st.st_mtim.tv_nsec,
          st.st_ctim.tv_sec * ns + st.st_ctim.tv_nsec};
}

OpenedResult ResultFiles::open(const api::ResultFile& stored) {
  using State = OpenedResult::State;
  OpenedResult out;
  if (stored.path.empty()) return out;
  // O_NONBLOCK: opening a FIFO for reading returns at once instead of waiting for a writer;
  // anything but a regular file is refused below before a byte is read.
  const int fd = ::open(absolute_path(stored).c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    out.state = err == ENOENT ? State::missing : State::unreadable;
    out.reason = std::strerror(err);
    return out;
  }
  out.fd = FileDescriptor(fd);
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    out.state = State::unreadable;
    out.reason = std::strerror(errno);
    return out;
  }
  if (!S_ISREG(st.st_mode)) {
    out.state = State::not_regular;
    out.reason = "not a regular file";
    out.fd = FileDescriptor();
    return out;
  }
  // Reads block from here on (a regular file never would with O_NONBLOCK anyway).
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  out.size = static_cast<std::uint64_t>(st.st_size);
  if (out.size != stored.size) {
    out.state = State::damaged;
    out.reason =
        "damaged: " + std::to_string(out.size) + " bytes instead of " + std::to_string(stored.size);
    return out;
  }
  const Identity identity = identity_of(st);
  bool intact = false;
  bool known = false;
  {
    std::lock_guard lock(mutex_);
    auto it = verdicts_.find(stored.path);
    if (it != verdicts_.end() && it->second.identity == identity &&
        it->second.sha256 == stored.sha256) {
      known = true;
      intact = it->second.intact;
    }
  }
  if (!known) {
    try {
      intact = api::sha256_descriptor(fd) == stored.sha256;
    } catch (const std::exception& e) {
      out.state = State::unreadable;
      out.reason = e.what();
      return out;
    }
    std::lock_guard lock(mutex_);
    verdicts_[stored.path] = {identity, stored.sha256, intact};
  }
  if (!intact) {
    out.state = State::damaged;
    out.reason = "damaged: its SHA-256 is not the one stored when it was written";
    return out;
  }
  if (::lseek(fd, 0, SEEK_SET) != 0) {
    out.state = State::unreadable;
    out.reason = std::strerror(errno);
    return out;
  }
  out.state = State::intact;
  return out;
}

} // namespace slipfront::server

namespace slipfront::server {

std::vector<StrayResult> find_stray_results(const std::string& data_dir,
                                            const ResultReferences& refs) {
  namespace fs = std::filesystem;
  std::vector<StrayResult> stray;
  std::error_code ec;
  const fs::path dir = fs::path(data_dir.empty() ? "." : data_dir) / "results";
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string path = "results/" + name;
    if (refs.paths.contains(path)) continue;
    const std::string id = name.substr(0, name.find('.'));
    if (refs.unfinished_ids.contains(id)) continue;
    stray.push_back({path, name.find(".tmp") != std::string::npos});
  }
  return stray;
}

} // namespace slipfront::server
